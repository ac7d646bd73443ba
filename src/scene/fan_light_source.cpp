// A line laser's fan (light.h): a sheet of light 2 r thick (r the beam's radius) leaving the
// exit aperture and spreading over the full angle theta along `fan_axis`, uniformly in angle.
//
// In the sheet's frame (d the beam's direction, a the fan axis, n = d x a across the sheet)
// photons leave the aperture's line {origin + s n, |s| <= r} in directions
// cos(phi) d + sin(phi) a, phi uniform in [-theta / 2, theta / 2]. The flux per unit angle and
// per unit of thickness is P / (theta 2 r), spread over the arc rho dphi at in-plane distance
// rho: the irradiance at p on a surface facing the aperture is P / (theta rho 2 r).
//
// Aiming: the fan's own photons all lie in its sheet, which is what aiming at targets would
// buy; a sheet has no solid angle to aim into, so the fan keeps its own sampling
// (worth_aiming false, sample_le_towards the same photons). Unbiased either way.

#include <cmath>

#include "math/constants.h"
#include "scene/beam_clip.h"
#include "scene/light.h"
#include "scene/light_source.h"

namespace lenslab {

namespace {

class FanLightSource final : public Light {
public:
    explicit FanLightSource(const BeamLight& b)
        : Light(b.spectrum),
          m_origin(b.origin),
          m_d(b.direction),
          m_a(normalize(b.fan_axis - b.direction * dot(b.fan_axis, b.direction))),
          m_n(cross(m_d, m_a)),
          m_radius(b.radius),
          m_theta(b.fan_angle * kPi / 180.0) {}

    double power() const override { return spectrum_watts(); }

    PhotonStart sample_le(Rng& rng) const override {
        const double u1 = rng.uniform(), u2 = rng.uniform();
        return photon(u1, u2);
    }

    PhotonStart sample_le_towards(const PhotonTargets&, const AimSample& u) const override {
        return photon(u[1], u[2]);
    }

    bool worth_aiming(const PhotonTargets&) const override { return false; }

    bool sample_li(const Vec3& p, Rng&, LightSample& out) const override {
        const Vec3 v = p - m_origin;
        if (std::abs(dot(v, m_n)) > m_radius) return false;  // outside the sheet
        const double x = dot(v, m_d), y = dot(v, m_a);
        const double rho = std::hypot(x, y);
        if (!(rho > 0.0) || std::abs(std::atan2(y, x)) > 0.5 * m_theta) return false;
        out.wi = -(m_d * x + m_a * y) / rho;
        out.distance = rho;
        out.factor = 1.0 / (m_theta * rho * 2.0 * m_radius);
        return true;
    }

    bool is_delta() const override { return true; }
    Aabb bounds() const override { return {m_origin, m_origin}; }

    // Uniform along the chord of the ray inside the sheet's slab and its wedge (ahead of the
    // aperture, within theta / 2 of the beam's direction). The wedge of a fan under 180
    // degrees is the meeting of two half-spaces bounded by its edges.
    bool sample_in_scattering(const Ray& ray, double t_max, double u, double& t,
                              double& pdf) const override {
        double t0 = 0.0, t1 = t_max;
        const Vec3 v = ray.origin - m_origin;
        if (!clip_to_slab(dot(v, m_n), dot(ray.direction, m_n), m_radius, t0, t1)) return false;
        const double s = std::sin(0.5 * m_theta), c = std::cos(0.5 * m_theta);
        for (const double side : {1.0, -1.0}) {
            // Inward normal of the edge at phi = side * theta / 2.
            const Vec3 inward = m_d * s - m_a * (side * c);
            if (!clip_to_halfspace(dot(v, inward), dot(ray.direction, inward), t0, t1))
                return false;
        }
        if (!(t1 > t0) || !std::isfinite(t1)) return false;
        t = t0 + u * (t1 - t0);
        pdf = 1.0 / (t1 - t0);
        return true;
    }

private:
    PhotonStart photon(double u1, double u2) const {
        const double phi = (u2 - 0.5) * m_theta;
        const Vec3 from = m_origin + m_n * ((2.0 * u1 - 1.0) * m_radius);
        return {{from, m_d * std::cos(phi) + m_a * std::sin(phi)}, &spectrum(), 1.0};
    }

    Vec3 m_origin, m_d, m_a, m_n;
    double m_radius, m_theta;  // theta: the full angle, radians
};

}  // namespace

LightPtr make_fan_light(const BeamLight& b) { return std::make_shared<FanLightSource>(b); }

}  // namespace lenslab
