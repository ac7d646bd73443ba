// The collimated beam (light.h), with or without a slit: parallel rays leaving the beam's
// disc, or the part of it inside a strip `slit_width` wide. Irradiance spectrum / A across
// the cross-section, A = pi r^2, or with a slit of half-width h the disc's area within the
// strip, 2 [h sqrt(r^2 - h^2) + r^2 asin(h / r)] (two circular segments taken from the disc).

#include <algorithm>
#include <cmath>

#include "math/constants.h"
#include "math/frame.h"
#include "math/sampling.h"
#include "scene/beam_clip.h"
#include "scene/light.h"
#include "scene/light_source.h"

namespace lenslab {

namespace {

double beam_cross_section(double r, double h) {
    if (h >= r) return kPi * r * r;
    return 2.0 * (h * std::sqrt(r * r - h * h) + r * r * std::asin(h / r));
}

class BeamLightSource final : public Light {
public:
    explicit BeamLightSource(const BeamLight& b)
        : Light(b.spectrum),
          m_origin(b.origin),
          m_direction(b.direction),
          m_radius(b.radius),
          m_slit(b.slit_width > 0.0 && b.slit_width < 2.0 * b.radius),
          m_half_width(m_slit ? 0.5 * b.slit_width : b.radius),
          m_along(m_slit ? b.slit_axis : Vec3{}),
          m_across(m_slit ? normalize(cross(b.direction, b.slit_axis)) : Vec3{}),
          m_area(beam_cross_section(m_radius, m_half_width)) {}

    double power() const override { return spectrum_watts(); }

    PhotonStart sample_le(Rng& rng) const override {
        if (!m_slit) {
            const double u1 = rng.uniform(), u2 = rng.uniform();
            return {{point_on_disc(u1, u2), m_direction}, &spectrum(), 1.0};
        }
        // Uniform over disc and strip: points of the strip's rectangle, until one is in the
        // disc (at least 2 / pi of them are).
        for (;;) {
            const double u1 = rng.uniform(), u2 = rng.uniform();
            const Vec3 p = point_in_strip(u1, u2);
            if (length_squared(p - m_origin) <= m_radius * m_radius)
                return {{p, m_direction}, &spectrum(), 1.0};
        }
    }

    PhotonStart sample_le_towards(const PhotonTargets& targets, const AimSample& u) const override {
        const double u0 = u[0], u1 = u[1], u2 = u[2];
        Vec3 p;
        double pdf;
        if (!targets.sample_plane_point(m_origin, m_direction, u0, u1, u2, m_area, p, pdf)) {
            if (!m_slit) return {{point_on_disc(u1, u2), m_direction}, &spectrum(), 1.0};
            // The strip's rectangle, weighted by its area over A inside the disc and 0 outside:
            // unbiased with two numbers and no rejection.
            p = point_in_strip(u1, u2);
            const double rect = 4.0 * m_half_width * m_radius;
            return {{p, m_direction}, &spectrum(), inside(p) ? rect / m_area : 0.0};
        }
        // Outside the beam's cross-section the beam sends nothing there.
        return {{p, m_direction}, &spectrum(), inside(p) ? 1.0 / (m_area * pdf) : 0.0};
    }

    bool sample_li(const Vec3& p, Rng&, LightSample& out) const override {
        const double along = dot(p - m_origin, m_direction);
        if (along <= 0.0 || !inside(p - m_direction * along)) return false;
        out.wi = -m_direction;
        out.distance = along;
        out.factor = 1.0 / m_area;
        return true;
    }

    bool is_delta() const override { return true; }
    Aabb bounds() const override { return {m_origin, m_origin}; }

    // Uniform along the chord of the ray inside the beam's cylinder (and the slit's slab),
    // ahead of its disc.
    bool sample_in_scattering(const Ray& ray, double t_max, double u, double& t,
                              double& pdf) const override {
        double t0 = 0.0, t1 = t_max;
        // Ahead of the disc: dot(o + t d - origin, direction) > 0.
        const double along0 = dot(ray.origin - m_origin, m_direction);
        const double along_rate = dot(ray.direction, m_direction);
        if (!clip_to_halfspace(along0, along_rate, t0, t1)) return false;
        if (m_slit && !clip_to_slab(dot(ray.origin - m_origin, m_across),
                                    dot(ray.direction, m_across), m_half_width, t0, t1))
            return false;
        // Inside the cylinder: |v + t w|^2 <= r^2, v and w the parts across the axis.
        const Vec3 v = (ray.origin - m_origin) - m_direction * along0;
        const Vec3 w = ray.direction - m_direction * along_rate;
        const double a = length_squared(w), b = dot(v, w),
                     c = length_squared(v) - m_radius * m_radius;
        if (a < 1e-300) {
            if (c > 0.0) return false;  // parallel to the axis, outside the beam
        } else {
            const double disc = b * b - a * c;
            if (disc <= 0.0) return false;
            const double root = std::sqrt(disc);
            t0 = std::max(t0, (-b - root) / a);
            t1 = std::min(t1, (-b + root) / a);
        }
        if (!(t1 > t0) || !std::isfinite(t1)) return false;
        t = t0 + u * (t1 - t0);
        pdf = 1.0 / (t1 - t0);
        return true;
    }

    bool worth_aiming(const PhotonTargets& targets) const override {
        return targets.plane_area(m_origin, m_direction) < m_area;
    }

private:
    Vec3 point_on_disc(double u1, double u2) const {
        double x, y;
        sample_disc_concentric(u1, u2, x, y);
        const Frame f = Frame::from_axis(m_direction);
        return m_origin + (f.u * x + f.v * y) * m_radius;
    }
    // Uniform on the rectangle 2 h across by 2 r along the slit.
    Vec3 point_in_strip(double u1, double u2) const {
        return m_origin + m_across * ((2.0 * u1 - 1.0) * m_half_width) +
               m_along * ((2.0 * u2 - 1.0) * m_radius);
    }
    // Whether `p`, on the disc's plane, is in the cross-section.
    bool inside(const Vec3& p) const {
        const Vec3 v = p - m_origin;
        if (length_squared(v) > m_radius * m_radius) return false;
        return !m_slit || std::abs(dot(v, m_across)) <= m_half_width;
    }

    Vec3 m_origin, m_direction;
    double m_radius;
    bool m_slit;             // a strip narrower than the disc
    double m_half_width;     // h: half the slit's width (the radius without one)
    Vec3 m_along, m_across;  // the slit's long direction, and across it
    double m_area;           // A, of disc and strip
};

}  // namespace

LightPtr make_beam_light(const BeamLight& b) {
    if (b.fan_angle > 0.0) return make_fan_light(b);
    return std::make_shared<BeamLightSource>(b);
}

}  // namespace lenslab
