#include "optics/grin_profile.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace lenslab {

const char* grin_kind_name(GrinKind kind) {
    switch (kind) {
        case GrinKind::Luneburg:
            return "luneburg";
        case GrinKind::Fisheye:
            return "fisheye";
        case GrinKind::Radial:
            return "radial";
        case GrinKind::Axial:
            return "axial";
        case GrinKind::Formula:
            return "formula";
    }
    return "unknown";
}

namespace {

Vec3 grin_off_axis(const GrinProfile& g, const Vec3& p) { return p - g.axis * dot(p, g.axis); }

double grin_formula_value(const GrinProfile& g, const Vec3& p) {
    const Formula::Values v{p.x, p.y, p.z, 0.0};
    const double n = g.formula->local()(v);
    if (!std::isfinite(n)) {
        char point[160];
        std::snprintf(point, sizeof point, "(x, y, z) = (%.9g, %.9g, %.9g)", p.x, p.y, p.z);
        throw UndefinedFormulaError(g.owner, *g.formula, point, v);
    }
    return n;
}

}  // namespace

double GrinProfile::index(const Vec3& p) const {
    switch (kind) {
        case GrinKind::Luneburg:
            // Clamped at 1 just outside the rim, where integration steps may land.
            return std::sqrt(std::max(1.0, 2.0 - dot(p, p) / (radius * radius)));
        case GrinKind::Fisheye:
            return n0 / (1.0 + dot(p, p) / (radius * radius));
        case GrinKind::Radial: {
            const Vec3 q = grin_off_axis(*this, p);
            return n0 * (1.0 - 0.5 * A * dot(q, q));
        }
        case GrinKind::Axial:
            return n0 + A * dot(p, axis);
        case GrinKind::Formula:
            return grin_formula_value(*this, p);
    }
    return 1.0;
}

std::optional<std::string> GrinProfile::problem_in(const Vec3& origin, const Vec3& lo,
                                                   const Vec3& hi) const {
    constexpr int kGrid = 9;
    const Vec3 e = hi - lo;
    for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
            for (int k = 0; k < kGrid; ++k) {
                const Vec3 p = lo + Vec3{e.x * i, e.y * j, e.z * k} / (kGrid - 1);
                const Vec3 q = p - origin;
                // A formula read directly: index() would throw the render-time error.
                const double n =
                    kind == GrinKind::Formula ? (*formula)({q.x, q.y, q.z, 0.0}) : index(q);
                if (n > 0.0) continue;
                std::ostringstream msg;
                msg.precision(10);
                msg << "the index is " << n << " at (x, y, z) = (" << q.x << ", " << q.y << ", "
                    << q.z << ") from its centre, in the object: it must be a number > 0 there";
                if (kind == GrinKind::Formula) {
                    const std::string why = formula->why_not_finite({q.x, q.y, q.z, 0.0});
                    if (!why.empty()) msg << " (" << why << ")";
                }
                return msg.str();
            }
        }
    }
    return std::nullopt;
}

Vec3 GrinProfile::gradient(const Vec3& p) const {
    switch (kind) {
        case GrinKind::Luneburg: {
            const double r2 = dot(p, p) / (radius * radius);
            if (r2 >= 1.0) return {0, 0, 0};
            return p * (-1.0 / (radius * radius * std::sqrt(2.0 - r2)));
        }
        case GrinKind::Fisheye: {
            const double q = 1.0 + dot(p, p) / (radius * radius);
            return p * (-2.0 * n0 / (radius * radius * q * q));
        }
        case GrinKind::Radial:
            return grin_off_axis(*this, p) * (-n0 * A);
        case GrinKind::Axial:
            return axis * A;
        case GrinKind::Formula: {
            // Central differences, a step near the cube root of the rounding error times the
            // coordinates' size: error O(h^2) from truncation balances O(eps / h).
            const double h = 1e-5 * std::max(1.0, std::max(std::abs(p.x),
                                                           std::max(std::abs(p.y), std::abs(p.z))));
            const auto diff = [&](const Vec3& e) {
                return (grin_formula_value(*this, p + e * h) -
                        grin_formula_value(*this, p - e * h)) /
                       (2.0 * h);
            };
            return {diff({1, 0, 0}), diff({0, 1, 0}), diff({0, 0, 1})};
        }
    }
    return {0, 0, 0};
}

}  // namespace lenslab
