#include "geometry/lens/sag_formula_surface.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "geometry/lens/sag_intersection.h"
#include "util/format_number.h"

namespace lenslab {

namespace {

// Variables in the order values are passed to the formula.
const std::vector<std::string> kSagVariables{"x", "y", "r"};
constexpr const char* kSagHint = "(use r, or x and y)";

// The sag and its gradient for one intersection, on the calling thread's evaluator.
struct FormulaSag {
    Formula::Evaluator& f;
    bool symmetric;
    double h;
    // Where the lens is (r up to the seam tolerance past its semi-diameter), a sag that is
    // not a number is an error in the formula, not a miss; `formula` is null when the
    // caller only wants values (the normal).
    const Formula* formula = nullptr;
    const std::string* owner = nullptr;
    double max_r = 0;

    double at(double x, double y, double r) { return f({x, y, r, 0.0}); }
    double value(double x, double y) {
        const double r = std::hypot(x, y);
        const double z = at(x, y, r);
        if (std::isnan(z) && formula && r <= max_r) {
            const std::string point =
                symmetric ? "r = " + format_number(r)
                          : "(x, y) = (" + format_number(x) + ", " + format_number(y) + ")";
            throw UndefinedFormulaError(*owner, *formula, point, {x, y, r, 0.0});
        }
        return z;
    }
    double value_and_gradient(double x, double y, double& dx, double& dy) {
        const double r = std::hypot(x, y);
        if (symmetric) {
            // The sag is even in r, so s(|r - h|) stands in for s(r - h) near the axis.
            const double slope = (at(0, 0, r + h) - at(0, 0, std::abs(r - h))) / (2.0 * h);
            dx = r > 0.0 ? slope * x / r : 0.0;
            dy = r > 0.0 ? slope * y / r : 0.0;
        } else {
            // Probes a step beyond the rim may be undefined: the gradient is then not finite,
            // which the root finder survives.
            dx = (at(x + h, y, std::hypot(x + h, y)) - at(x - h, y, std::hypot(x - h, y))) /
                 (2.0 * h);
            dy = (at(x, y + h, std::hypot(x, y + h)) - at(x, y - h, std::hypot(x, y - h))) /
                 (2.0 * h);
        }
        return value(x, y);
    }
};

}  // namespace

SagFormulaSurface::SagFormulaSurface(const std::string& text, double length_scale,
                                     std::string owner)
    : m_formula(std::make_shared<Formula>(text, kSagVariables, kSagHint)),
      m_symmetric(!m_formula->uses("x") && !m_formula->uses("y")),
      // Central differences err by O(h^2) in truncation and O(eps / h) in rounding; h near
      // eps^(1/3) of the length scale balances them (Press et al., Numerical Recipes, 5.7).
      m_step(6e-6 * length_scale),
      m_owner(std::move(owner)) {
    const double vertex = sag_xy(0.0, 0.0);
    if (!(std::abs(vertex) <= 1e-9 * std::max(1.0, length_scale))) {
        std::ostringstream msg;
        msg << "must be 0 on the axis (z is measured from the vertex), got " << vertex
            << " at r = 0";
        throw FormulaError(0, msg.str());
    }
}

std::optional<std::string> SagFormulaSurface::check(const std::string& text) {
    try {
        Formula f(text, kSagVariables, kSagHint);
    } catch (const FormulaError& e) {
        return e.message();
    }
    return std::nullopt;
}

double SagFormulaSurface::sag(double r) const { return sag_xy(r, 0.0); }

double SagFormulaSurface::sag_xy(double x, double y) const {
    return (*m_formula)({x, y, std::hypot(x, y), 0.0});
}

double SagFormulaSurface::max_semi_diameter() const {
    // Where a formula is defined is found by evaluating it (the lens's load-time check).
    return std::numeric_limits<double>::infinity();
}

bool SagFormulaSurface::intersect(const Ray& ray, const SurfaceSpan& span, double t_min,
                                  double t_max, double& t) const {
    FormulaSag sag{m_formula->local(), m_symmetric, m_step,
                   m_formula.get(),    &m_owner,    span.semi_diameter * (1.0 + kSeamTolerance)};
    return intersect_sag(ray, span, t_min, t_max, t, sag);
}

Vec3 SagFormulaSurface::normal(const Vec3& p) const {
    FormulaSag sag{m_formula->local(), m_symmetric, m_step, nullptr, nullptr, 0.0};
    double dx, dy;
    (void)sag.value_and_gradient(p.x, p.y, dx, dy);
    const Vec3 n{-dx, -dy, 1.0};
    return is_finite(n) ? normalize(n) : Vec3{0, 0, 1};
}

std::string SagFormulaSurface::describe() const {
    return std::string(m_symmetric ? "sag z(r) = " : "sag z(x, y) = ") + m_formula->text();
}

std::string SagFormulaSurface::why_undefined(double x, double y) const {
    return m_formula->why_not_finite({x, y, std::hypot(x, y), 0.0});
}

}  // namespace lenslab
