#include "render/density_tracking.h"

#include <algorithm>

namespace lenslab {

namespace {

double max_of(const BandWeights& w) { return std::max({w[0], w[1], w[2]}); }

}  // namespace

RaySpan span_inside(const Aabb& box, const Ray& ray, double t_end) {
    RaySpan s{0, t_end};
    for (int a = 0; a < 3; ++a) {
        const double o = ray.origin[a], d = ray.direction[a];
        if (d == 0) {
            if (o < box.lo[a] || o > box.hi[a]) return {1, 0};
            continue;
        }
        double t0 = (box.lo[a] - o) / d, t1 = (box.hi[a] - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        s.t0 = std::max(s.t0, t0);
        s.t1 = std::min(s.t1, t1);
    }
    return s;
}

double delta_track(const MediumDensity& density, double mu, const Ray& ray, double t_end,
                   Rng& rng) {
    const double mu_bar = mu * density.bound();
    double hit = INFINITY;
    for_each_tentative(density, mu_bar, ray, t_end, rng, [&](double t, double f) {
        if (rng.uniform() * density.bound() >= f) return true;  // a null collision
        hit = t;
        return false;
    });
    return hit;
}

double ratio_track(const MediumDensity& density, double mu, const Ray& ray, double t_end,
                   Rng& rng) {
    double tr = 1;
    for_each_tentative(density, mu * density.bound(), ray, t_end, rng, [&](double, double f) {
        tr *= 1 - f / density.bound();
        return tr > 0;
    });
    return tr;
}

BandWeights ratio_track(const Medium& medium, const Ray& ray, double t_end, Rng& rng) {
    const BandWeights mu = medium.extinction();
    const double mu_bar = max_of(mu) * medium.density->bound();
    BandWeights tr{1, 1, 1};
    for_each_tentative(*medium.density, mu_bar, ray, t_end, rng, [&](double, double f) {
        for (int b = 0; b < 3; ++b) tr[b] *= 1 - mu[b] * f / mu_bar;
        return max_of(tr) > 0;
    });
    return tr;
}

TransmittanceWalk::TransmittanceWalk(const Medium& medium, int band, const Ray& ray, double t_end,
                                     Rng& rng) {
    const double mu = medium.extinction()[size_t(band)];
    const MediumDensity& density = *medium.density;
    double tr = 1;
    for_each_tentative(density, mu * density.bound(), ray, t_end, rng, [&](double t, double f) {
        tr *= 1 - f / density.bound();
        m_t.push_back(t);
        m_product.push_back(tr);
        return tr > 0;
    });
}

double TransmittanceWalk::at(double t) const {
    // The tentative collisions before t: the first at or after it is not yet counted.
    const size_t n = size_t(std::lower_bound(m_t.begin(), m_t.end(), t) - m_t.begin());
    if (n == 0) return 1;
    // A walk that reached 0 stopped there: every later point is 0 too.
    return m_product[n - 1];
}

}  // namespace lenslab
