#pragma once
// Light crossing a heterogeneous medium (scene/medium_density.h), where the extinction
// sigma(x) = mu f(x) varies along the ray, so neither transmittance nor free-flight
// distances have closed forms. Both are estimated without bias against a majorant
// mu_bar = mu * bound >= sigma(x): tentative collisions are drawn as in a homogeneous
// medium of mu_bar (exponential steps), and at each the local density decides.
//
// - Delta (Woodcock) tracking: a tentative collision is real with probability
//   sigma(x) / mu_bar; the first real one is distributed exactly as a free flight through
//   sigma (Woodcock et al. 1965; Novák et al. 2018, "Monte Carlo methods for volumetric
//   light transport simulation", section 4).
// - Ratio tracking: the product of (1 - sigma(x_i) / mu_bar) over the tentative collisions
//   before `t_end` is an unbiased estimate of exp(-\int_0^t_end sigma) (Novák et al. 2014,
//   "Residual ratio tracking"). Truncated at any t < t_end the same product is that t's
//   estimate, which lets one walk serve every point of a segment (sppm's volume gather).
//
// The density is 0 outside its region, so steps skip straight to the part of the ray
// inside it, and a ray leaving the scene ends.

#include <cmath>
#include <vector>

#include "math/ray.h"
#include "math/rng.h"
#include "optics/spectrum.h"
#include "scene/medium.h"

namespace lenslab {

// The part [t0, t1] of [0, t_end] where `ray` is inside `box`; t0 > t1 when none.
struct RaySpan {
    double t0, t1;
};
RaySpan span_inside(const Aabb& box, const Ray& ray, double t_end);

// Calls `visit(t, f(t))` at each tentative collision of rate `mu_bar` along the part of
// `ray` inside the density's region before `t_end`, until it returns false: the walk every
// tracking estimator here shares.
template <class Visit>
void for_each_tentative(const MediumDensity& density, double mu_bar, const Ray& ray, double t_end,
                        Rng& rng, Visit&& visit) {
    if (!(mu_bar > 0)) return;
    const RaySpan span = span_inside(density.region(), ray, t_end);
    MediumDensity::Local f = density.local();
    for (double t = span.t0;;) {
        t -= std::log1p(-rng.uniform()) / mu_bar;
        if (!(t < span.t1)) return;
        if (!visit(t, f(ray.at(t)))) return;
    }
}

// The distance to the first real collision along `ray` in a medium of extinction
// mu f(x), or INFINITY when there is none before `t_end`.
double delta_track(const MediumDensity& density, double mu, const Ray& ray, double t_end, Rng& rng);

// An unbiased estimate of exp(-mu \int_0^t_end f) along `ray`.
double ratio_track(const MediumDensity& density, double mu, const Ray& ray, double t_end, Rng& rng);

// The same per band of a heterogeneous `medium`'s extinction, with one walk for all three
// (the majorant of the densest band).
BandWeights ratio_track(const Medium& medium, const Ray& ray, double t_end, Rng& rng);

// One ratio-tracking walk along a segment kept for every point on it: `at(t)` is the
// estimate of the transmittance from 0 to t in `band`, each unbiased (the walk's product
// truncated at t).
class TransmittanceWalk {
public:
    TransmittanceWalk(const Medium& medium, int band, const Ray& ray, double t_end, Rng& rng);
    double at(double t) const;

private:
    std::vector<double> m_t;        // the tentative collisions, in order
    std::vector<double> m_product;  // the transmittance just after each
};

}  // namespace lenslab
