// The spot light (light.h): a point source whose intensity fills a cone.
//
// Intensity I(theta) = I0 * s(cos theta), s = 1 inside cos_full, smoothstep down to 0 at
// cos_edge (pbrt-v4's spot light, section 12.1.1). Its flux is
// Phi = 2 pi I0 [(1 - cos_full) + (cos_full - cos_edge) / 2] (the smoothstep's integral over
// the cosine is half the interval), so I0 = Phi / (2 pi * weight).

#include <algorithm>
#include <cmath>

#include "math/constants.h"
#include "math/frame.h"
#include "math/sampling.h"
#include "scene/light.h"
#include "scene/light_source.h"

namespace lenslab {

namespace {

double spot_smoothstep(double cos_theta, double cos_edge, double cos_full) {
    if (cos_theta >= cos_full) return 1.0;
    if (cos_theta <= cos_edge) return 0.0;
    const double t = (cos_theta - cos_edge) / (cos_full - cos_edge);
    return t * t * (3.0 - 2.0 * t);
}

class SpotLightSource final : public PointSourceLight {
public:
    explicit SpotLightSource(const SpotLight& s)
        : PointSourceLight(s.spectrum, s.position),
          m_frame(Frame::from_axis(s.direction)),
          m_cos_edge(std::cos(s.cone_angle * kPi / 180.0)),
          m_cos_full(std::cos((s.cone_angle - s.falloff) * kPi / 180.0)),
          m_weight((1.0 - m_cos_full) + 0.5 * (m_cos_full - m_cos_edge)) {}

private:
    double intensity(const Vec3& dir) const override {
        return spot_smoothstep(dot(dir, m_frame.w), m_cos_edge, m_cos_full) /
               (2.0 * kPi * m_weight);
    }
    // Uniform in the cone.
    Vec3 sample_direction(double u1, double u2, double& pdf) const override {
        pdf = 1.0 / emission_solid_angle();
        return m_frame.to_world(sample_uniform_cone(u1, u2, m_cos_edge));
    }
    double emission_solid_angle() const override { return 2.0 * kPi * (1.0 - m_cos_edge); }

    Frame m_frame;
    double m_cos_edge, m_cos_full, m_weight;
};

}  // namespace

LightPtr make_spot_light(const SpotLight& s) { return std::make_shared<SpotLightSource>(s); }

}  // namespace lenslab
