// The spot light (light.h): a point source whose intensity fills a cone.
//
// Intensity I(theta) = I0 * s(cos theta), s = 1 inside cos_full, smoothstep down to 0 at
// cos_edge (pbrt-v4's spot light, section 12.1.1). Its flux is
// Phi = 2 pi I0 [(1 - cos_full) + (cos_full - cos_edge) / 2] (the smoothstep's integral over
// the cosine is half the interval), so I0 = Phi / (2 pi * spot_cone_weight).

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

class SpotLightSource final : public Light {
public:
    explicit SpotLightSource(const SpotLight& s)
        : Light(s.spectrum),
          m_position(s.position),
          m_frame(Frame::from_axis(s.direction)),
          m_cos_edge(std::cos(s.cone_angle * kPi / 180.0)),
          m_cos_full(std::cos((s.cone_angle - s.falloff) * kPi / 180.0)),
          m_weight((1.0 - m_cos_full) + 0.5 * (m_cos_full - m_cos_edge)) {}

    double power() const override { return spectrum_watts(); }

    // Uniform in the cone: density 1 / (2 pi (1 - cos_edge)); the photon carries
    // I(w) / (density * Phi) of the flux.
    PhotonStart sample_le(Rng& rng) const override {
        const double u1 = rng.uniform(), u2 = rng.uniform();
        const Vec3 dir = m_frame.to_world(sample_uniform_cone(u1, u2, m_cos_edge));
        return {{m_position, dir}, &spectrum(), share(dir) * (1.0 - m_cos_edge)};
    }

    PhotonStart sample_le_towards(const PhotonTargets& targets, const AimSample& u) const override {
        Vec3 dir;
        double pdf;
        if (!targets.sample_direction(m_position, u[0], u[1], u[2], cone_solid_angle(), dir, pdf)) {
            const Vec3 d = m_frame.to_world(sample_uniform_cone(u[1], u[2], m_cos_edge));
            return {{m_position, d}, &spectrum(), share(d) * (1.0 - m_cos_edge)};
        }
        return {{m_position, dir}, &spectrum(), share(dir) / (2.0 * kPi * pdf)};
    }

    bool sample_li(const Vec3& p, Rng&, LightSample& out) const override {
        const Vec3 to_light = m_position - p;
        const double dist2 = length_squared(to_light);
        if (!(dist2 > 0.0)) return false;
        out.distance = std::sqrt(dist2);
        out.wi = to_light / out.distance;
        const double s = share(-out.wi);
        if (s <= 0.0) return false;
        out.factor = s / (2.0 * kPi * dist2);  // E = I cos / r^2
        return true;
    }

    bool is_delta() const override { return true; }

    bool sample_in_scattering(const Ray& ray, double t_max, double u, double& t,
                              double& pdf) const override {
        return sample_equiangular(ray, t_max, m_position, u, t, pdf);
    }

    bool worth_aiming(const PhotonTargets& targets) const override {
        return targets.solid_angle(m_position) < cone_solid_angle();
    }

private:
    // I(dir) * 2 pi / Phi: the intensity per unit flux, times 2 pi.
    double share(const Vec3& dir) const {
        return spot_smoothstep(dot(dir, m_frame.w), m_cos_edge, m_cos_full) / m_weight;
    }
    double cone_solid_angle() const { return 2.0 * kPi * (1.0 - m_cos_edge); }

    Vec3 m_position;
    Frame m_frame;
    double m_cos_edge, m_cos_full, m_weight;
};

}  // namespace

LightPtr make_spot_light(const SpotLight& s) { return std::make_shared<SpotLightSource>(s); }

}  // namespace lenslab
