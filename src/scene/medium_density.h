#pragma once
// A medium whose coefficients vary in space: a density field f(x, y, z) >= 0, a typed
// formula or samples on a grid (scene/density_grid.h), multiplies
// both of the medium's coefficients at each point (sigma_a(x) = absorption f(x),
// sigma_s(x) = scattering f(x)), so the medium's colour and phase function are the same
// everywhere and only how much of it there is changes: smoke, a plume, a fog bank.
//
// The tracers sample such a medium by delta and ratio tracking (render/density_tracking.h),
// which need a majorant: a bound that f never exceeds. The user may give it; otherwise a
// formula's is estimated by sampling f on a grid over the medium's region, with a safety
// margin, and a grid's is its largest value (exact: interpolation never exceeds it). The
// region is where the medium is: a shape's bounding box, the scene's bounds for the
// atmosphere (outside them the atmosphere's density is taken as 0, so a ray leaving the
// scene meets a finite amount of it).

#include <atomic>
#include <memory>
#include <string>

#include "math/aabb.h"
#include "math/formula.h"
#include "scene/density_grid.h"

namespace lenslab {

class MediumDensity {
public:
    // `formula` over x, y, z in scene units; `owner` is its JSON path, for messages.
    // Throws FormulaError for text muparser refuses.
    MediumDensity(const std::string& formula, std::string owner);
    MediumDensity(DensityGrid grid, std::string owner);

    const std::string& owner() const { return m_owner; }

    // The majorant and the region it holds over; set once, before rendering.
    void bound_over(const Aabb& region, double bound);
    double bound() const { return m_bound; }
    const Aabb& region() const { return m_region; }

    // The sampled maximum of a formula over `region` (a grid of kCheckGrid^3 points), or why
    // f is not a density there: negative or undefined at a point, named. A grid's maximum,
    // exact.
    struct Survey {
        double max = 0;
        bool exact = false;   // `max` is f's largest value, not a sample of it
        std::string problem;  // empty when f is finite and >= 0 at every point
    };
    Survey survey(const Aabb& region) const;

    // One thread's view for one task (a free flight, a shadow ray): the formula's evaluator
    // looked up once. f is 0 outside the region, and clamped to [0, bound] inside, so
    // tracking stays valid where the grid missed a peak; such points are counted.
    class Local {
    public:
        explicit Local(const MediumDensity& d)
            : m_d(d), m_eval(d.m_formula ? &d.m_formula->local() : nullptr) {}
        double operator()(const Vec3& p);

    private:
        const MediumDensity& m_d;
        Formula::Evaluator* m_eval;  // none for a grid
    };
    Local local() const { return Local(*this); }

    // How many points tracking met where f left [0, bound] between the grid's points (and
    // was clamped into it).
    uint64_t points_clamped() const { return m_clamped.load(std::memory_order_relaxed); }

    static constexpr int kCheckGrid = 33;
    // The estimated bound is the sampled maximum times this: room for peaks between points.
    static constexpr double kSafety = 1.25;

private:
    std::unique_ptr<Formula> m_formula;  // or
    std::unique_ptr<DensityGrid> m_grid;
    std::string m_owner;
    Aabb m_region;
    double m_bound = 0;
    mutable std::atomic<uint64_t> m_clamped{0};
};

}  // namespace lenslab
