#pragma once
// Clipping a ray's interval [t0, t1] to the half-spaces and slabs beams and fans fill, for
// their in-scattering chords (Light::sample_in_scattering).

#include <algorithm>

namespace lenslab {

// Narrows [t0, t1] to where offset0 + t * rate > 0; false when nothing is left.
inline bool clip_to_halfspace(double offset0, double rate, double& t0, double& t1) {
    if (rate > 0.0) {
        t0 = std::max(t0, -offset0 / rate);
    } else if (rate < 0.0) {
        t1 = std::min(t1, -offset0 / rate);
    } else if (offset0 <= 0.0) {
        return false;
    }
    return t1 > t0;
}

// Narrows [t0, t1] to where |offset0 + t * rate| <= half_width.
inline bool clip_to_slab(double offset0, double rate, double half_width, double& t0, double& t1) {
    return clip_to_halfspace(half_width + offset0, rate, t0, t1) &&
           clip_to_halfspace(half_width - offset0, -rate, t0, t1);
}

}  // namespace lenslab
