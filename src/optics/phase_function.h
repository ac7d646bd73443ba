#pragma once
// The Henyey–Greenstein phase function (Henyey and Greenstein 1941, "Diffuse radiation in the
// galaxy", ApJ 93, 70): the angular distribution of light scattered in a medium,
//   p(cos theta) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos theta)^(3/2)),
// theta the angle between the light's direction before and after scattering. It integrates
// to 1 over the sphere and its mean cosine is g: g > 0 scatters forward (fog, milky water),
// g < 0 back, g = 0 is isotropic.

#include <algorithm>
#include <cmath>

#include "math/constants.h"
#include "math/frame.h"
#include "math/vec3.h"

namespace lenslab {

class HenyeyGreenstein {
public:
    // g is clamped inside (-1, 1): at +-1 the function is a delta, which no sampler reaches.
    explicit HenyeyGreenstein(double g) : m_g(std::clamp(g, -0.999, 0.999)) {}

    double g() const { return m_g; }

    // Density per steradian of scattering by angle theta.
    double eval(double cos_theta) const {
        const double denom = 1.0 + m_g * m_g - 2.0 * m_g * cos_theta;
        return (1.0 - m_g * m_g) / (4.0 * kPi * denom * std::sqrt(denom));
    }

    // The new direction of light travelling along `forward` (unit), drawn with density
    // eval(cos theta), by inverting the cumulative distribution in cos theta.
    Vec3 sample(const Vec3& forward, double u1, double u2) const {
        double cos_theta;
        if (std::abs(m_g) < 1e-4) {
            cos_theta = 1.0 - 2.0 * u1;
        } else {
            const double s = (1.0 - m_g * m_g) / (1.0 - m_g + 2.0 * m_g * u1);
            cos_theta = (1.0 + m_g * m_g - s * s) / (2.0 * m_g);
        }
        cos_theta = std::clamp(cos_theta, -1.0, 1.0);
        const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
        const double phi = 2.0 * kPi * u2;
        return Frame::from_axis(forward).to_world(
            {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta});
    }

private:
    double m_g;
};

}  // namespace lenslab
