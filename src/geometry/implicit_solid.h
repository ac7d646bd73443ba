#pragma once
// A refractive solid given by an equation the user types: the points of a bounding box where
// f(x, y, z) <= 0 (muparser syntax), with x, y, z and the box measured from `centre`. Where the set
// {f <= 0} reaches the box, the box's faces close it, so it is always a closed solid: a torus, a
// blob, or a cylinder cut to length by its box.
//
// Intersection: the ray is clipped to the box and f is sampled along it in steps of the
// box's diagonal / `steps`; the first change of sign is refined by bracketed Newton
// (math/bracketed_newton.h) to 1e-12 of the diagonal. A general formula has no Lipschitz
// bound, so nothing finer than a step can be guaranteed: a feature thinner than one step
// (a sliver, or a ray grazing a surface so that it enters and leaves within a step) can be
// missed, consistently from either side. Normals are the gradient of f by central
// differences, pointing out of the solid.

#include <memory>
#include <optional>
#include <string>

#include "geometry/shape.h"
#include "math/formula.h"

namespace lenslab {

class ImplicitSolid final : public Shape {
public:
    static constexpr int kDefaultSteps = 512;

    // Throws FormulaError for a formula that does not parse or uses variables other than
    // x, y and z. `box` (relative to `centre`) must not be empty in any axis; `steps` >= 1.
    // `owner` (the formula's JSON path) names it when `intersect` or `contains` meets a
    // point inside the box where f is not a number: that throws UndefinedFormulaError.
    ImplicitSolid(const std::string& formula, const Aabb& box, int steps = kDefaultSteps,
                  const Vec3& centre = {}, std::string owner = "");

    // What an editor shows while the formula is typed: the reason it would be refused, or
    // nothing (syntax and variables).
    static std::optional<std::string> check(const std::string& text);
    // What the scene reader refuses once the box is known: f undefined (NaN) somewhere
    // inside it, or f > 0 everywhere sampled (an empty solid). Nothing if the solid is fine.
    std::optional<std::string> check_values() const;

    bool intersect(const Ray& ray, double t_min, double t_max, SurfaceHit& hit) const override;
    Aabb bounds() const override { return {m_box.lo + m_centre, m_box.hi + m_centre}; }
    bool is_closed() const override { return true; }

    // True for points (in world coordinates) inside or on the solid.
    bool contains(const Vec3& p) const override;
    // f at a point given relative to the centre.
    double f(const Vec3& local) const { return (*m_formula)({local.x, local.y, local.z, 0.0}); }
    const std::string& formula() const { return m_formula->text(); }
    int steps() const { return m_steps; }

private:
    // f at a local point inside the box, where NaN is an error in the formula.
    double defined_f(Formula::Evaluator& f, const Vec3& local) const;

    std::shared_ptr<const Formula> m_formula;
    Aabb m_box;  // relative to m_centre
    int m_steps;
    Vec3 m_centre;
    double m_diagonal;
    std::string m_owner;
};

}  // namespace lenslab
