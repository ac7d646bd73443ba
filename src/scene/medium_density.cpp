#include "scene/medium_density.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lenslab {

namespace {

const std::vector<std::string> kDensityVariables{"x", "y", "z"};

std::string point_text(const Vec3& p) {
    std::ostringstream s;
    s.precision(10);
    s << "(x, y, z) = (" << p.x << ", " << p.y << ", " << p.z << ")";
    return s.str();
}

}  // namespace

MediumDensity::MediumDensity(const std::string& formula, std::string owner)
    : m_formula(std::make_unique<Formula>(formula, kDensityVariables, "(use x, y and z)")),
      m_owner(std::move(owner)) {}

MediumDensity::MediumDensity(DensityGrid grid, std::string owner)
    : m_grid(std::make_unique<DensityGrid>(std::move(grid))), m_owner(std::move(owner)) {}

void MediumDensity::bound_over(const Aabb& region, double bound) {
    m_region = region;
    m_bound = bound;
}

MediumDensity::Survey MediumDensity::survey(const Aabb& region) const {
    Survey out;
    if (m_grid) {  // its values were checked as they were read
        out.max = m_grid->max();
        out.exact = true;
        return out;
    }
    Formula::Evaluator& f = m_formula->local();
    for_each_grid_point(region, kCheckGrid, [&](const Vec3& p) {
        const double v = f({p.x, p.y, p.z, 0.0});
        if (std::isnan(v) || std::isinf(v)) {
            const std::string why = m_formula->why_not_finite({p.x, p.y, p.z, 0.0});
            out.problem = std::string(std::isnan(v) ? "undefined" : "infinite") + " at " +
                          point_text(p) + (why.empty() ? "" : " (" + why + ")");
            return false;
        }
        if (v < 0) {
            std::ostringstream s;
            s.precision(6);
            s << "is " << v << " at " << point_text(p) << ": a density must be >= 0";
            out.problem = s.str();
            return false;
        }
        out.max = std::max(out.max, v);
        return true;
    });
    return out;
}

double MediumDensity::Local::operator()(const Vec3& p) {
    if (!m_d.m_region.contains(p)) return 0.0;
    if (!m_eval) return std::min(m_d.m_grid->at(p), m_d.m_bound);
    const double v = (*m_eval)({p.x, p.y, p.z, 0.0});
    if (std::isnan(v))
        throw UndefinedFormulaError(m_d.m_owner, *m_d.m_formula, point_text(p),
                                    {p.x, p.y, p.z, 0.0});
    if (v >= 0 && v <= m_d.m_bound) return v;
    // Between the grid's points f went negative or above the majorant: tracking needs
    // 0 <= f <= bound, so it is clamped, and counted (points_clamped).
    m_d.m_clamped.fetch_add(1, std::memory_order_relaxed);
    return v < 0 ? 0.0 : m_d.m_bound;
}

}  // namespace lenslab
