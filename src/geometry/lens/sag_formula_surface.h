#pragma once

#include <memory>
#include <optional>

#include "geometry/lens/lens_surface.h"
#include "math/formula.h"

namespace lenslab {

// A surface whose sag the user types as a formula (muparser syntax): z(r) for a surface of
// revolution, when the formula uses only r, or z(x, y) for any other, when it uses x or y
// (r = sqrt(x^2 + y^2) may appear in it too). z is measured from the vertex along the lens
// axis, so the formula must give 0 at r = 0. The ray crossing is found numerically
// (sag_intersection.h) and the normal from the gradient by central differences.
class SagFormulaSurface final : public LensSurface {
public:
    // Throws FormulaError (syntax, unknown variable, non-zero sag on the axis).
    // `length_scale` (the lens's semi-diameter) sets the finite-difference step. `owner`
    // (the surface's JSON path) names it when `intersect` meets a point inside the lens
    // where the sag is not a number: that throws UndefinedFormulaError.
    explicit SagFormulaSurface(const std::string& text, double length_scale = 1.0,
                               std::string owner = "");

    // What an editor shows while the formula is typed: the reason it would be refused, or
    // nothing. Checks the syntax and the variables (not values, which need a diameter).
    static std::optional<std::string> check(const std::string& text);

    double sag(double r) const override;
    double sag_xy(double x, double y) const override;
    bool is_rotationally_symmetric() const override { return m_symmetric; }
    double max_semi_diameter() const override;
    bool intersect(const Ray& ray, const SurfaceSpan& span, double t_min, double t_max,
                   double& t) const override;
    Vec3 normal(const Vec3& p) const override;
    std::string describe() const override;
    std::string why_undefined(double x, double y) const override;

    const std::string& text() const { return m_formula->text(); }

private:
    std::shared_ptr<const Formula> m_formula;
    bool m_symmetric;
    double m_step;  // central-difference step
    std::string m_owner;
};

}  // namespace lenslab
