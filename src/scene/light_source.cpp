#include "scene/light_source.h"

#include <algorithm>
#include <cmath>

#include "geometry/sphere.h"
#include "math/constants.h"
#include "math/frame.h"
#include "math/sampling.h"
#include "scene/light.h"

namespace lenslab {

namespace {

// Isotropic: intensity spectrum / (4 pi) in every direction.
class PointLightSource final : public PointSourceLight {
public:
    explicit PointLightSource(const PointLight& l) : PointSourceLight(l.spectrum, l.position) {}

private:
    double intensity(const Vec3&) const override { return 1.0 / (4.0 * kPi); }
    Vec3 sample_direction(double u1, double u2, double& pdf) const override {
        pdf = 1.0 / (4.0 * kPi);
        return sample_uniform_sphere(u1, u2);
    }
    double emission_solid_angle() const override { return 4.0 * kPi; }
};

// Parallel rays along `direction` from a disc: irradiance spectrum / (pi r^2) across it.
class BeamLightSource final : public Light {
public:
    explicit BeamLightSource(const BeamLight& b)
        : Light(b.spectrum), m_origin(b.origin), m_direction(b.direction), m_radius(b.radius) {}

    double power() const override { return spectrum_watts(); }

    PhotonStart sample_le(Rng& rng) const override {
        const double u1 = rng.uniform(), u2 = rng.uniform();
        return {{point_on_disc(u1, u2), m_direction}, &spectrum(), 1.0};
    }

    PhotonStart sample_le_towards(const PhotonTargets& targets, const AimSample& u) const override {
        const double u0 = u[0], u1 = u[1], u2 = u[2];
        const double area = kPi * m_radius * m_radius;
        Vec3 p;
        double pdf;
        if (!targets.sample_plane_point(m_origin, m_direction, u0, u1, u2, area, p, pdf)) {
            return {{point_on_disc(u1, u2), m_direction}, &spectrum(), 1.0};
        }
        // Outside the beam's disc the beam sends nothing there.
        const bool inside = length_squared(p - m_origin) <= m_radius * m_radius;
        return {{p, m_direction}, &spectrum(), inside ? 1.0 / (area * pdf) : 0.0};
    }

    bool sample_li(const Vec3& p, Rng&, LightSample& out) const override {
        const Vec3 v = p - m_origin;
        const double along = dot(v, m_direction);
        if (along <= 0.0 || length_squared(v - m_direction * along) > m_radius * m_radius)
            return false;
        out.wi = -m_direction;
        out.distance = along;
        out.factor = 1.0 / (kPi * m_radius * m_radius);
        return true;
    }

    bool is_delta() const override { return true; }

    // Uniform along the chord of the ray inside the beam's cylinder, ahead of its disc.
    bool sample_in_scattering(const Ray& ray, double t_max, double u, double& t,
                              double& pdf) const override {
        double t0 = 0.0, t1 = t_max;
        // Ahead of the disc: dot(o + t d - origin, direction) > 0.
        const double along0 = dot(ray.origin - m_origin, m_direction);
        const double along_rate = dot(ray.direction, m_direction);
        if (!clip_halfline(along0, along_rate, t0, t1)) return false;
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
        return targets.plane_area(m_origin, m_direction) < kPi * m_radius * m_radius;
    }

private:
    Vec3 point_on_disc(double u1, double u2) const {
        double x, y;
        sample_disc_concentric(u1, u2, x, y);
        const Frame f = Frame::from_axis(m_direction);
        return m_origin + (f.u * x + f.v * y) * m_radius;
    }

    // Narrows [t0, t1] to where along0 + t * rate > 0; false when nothing is left.
    static bool clip_halfline(double along0, double rate, double& t0, double& t1) {
        if (rate > 0.0) {
            t0 = std::max(t0, -along0 / rate);
        } else if (rate < 0.0) {
            t1 = std::min(t1, -along0 / rate);
        } else if (along0 <= 0.0) {
            return false;
        }
        return t1 > t0;
    }

    Vec3 m_origin, m_direction;
    double m_radius;
};

// A Lambertian emitter: radiance spectrum from every point of its surface, so it sends
// pi L 4 pi R^2 in all.
class SphereLightSource final : public Light {
public:
    SphereLightSource(std::shared_ptr<const Sphere> sphere, SpectrumPtr radiance)
        : Light(std::move(radiance)), m_sphere(std::move(sphere)) {}

    double power() const override { return kPi * area() * spectrum_watts(); }

    PhotonStart sample_le(Rng& rng) const override {
        const Vec3 normal = sample_uniform_sphere(rng.uniform(), rng.uniform());
        const double u1 = rng.uniform(), u2 = rng.uniform();
        const Vec3 dir = Frame::from_axis(normal).to_world(sample_cosine_hemisphere(u1, u2));
        return {{surface_point(normal), dir}, &spectrum(), kPi * area()};
    }

    PhotonStart sample_le_towards(const PhotonTargets& targets, const AimSample& u) const override {
        const Vec3 normal = sample_uniform_sphere(u[3], u[4]);
        const Vec3 from = surface_point(normal);
        const double u0 = u[0], u1 = u[1], u2 = u[2];
        Vec3 dir;
        double pdf;
        // Cosine sampling has density cos / pi <= 1 / pi: aiming pays where the cones
        // subtend less than pi steradians.
        if (!targets.sample_direction(from, u0, u1, u2, kPi, dir, pdf)) {
            const Vec3 d = Frame::from_axis(normal).to_world(sample_cosine_hemisphere(u1, u2));
            return {{from, d}, &spectrum(), kPi * area()};
        }
        const double cos_theta = dot(dir, normal);
        return {{from, dir}, &spectrum(), cos_theta > 0.0 ? cos_theta * area() / pdf : 0.0};
    }

    bool sample_li(const Vec3& p, Rng& rng, LightSample& out) const override {
        const Vec3 to_centre = m_sphere->centre() - p;
        const double d2 = length_squared(to_centre);
        const double r2 = m_sphere->radius() * m_sphere->radius();
        if (d2 <= r2) return false;  // inside the light
        const double cos_max = std::sqrt(1.0 - r2 / d2);
        // 1 - cos_max written without cancellation for small, distant lights.
        const double one_minus_cos = (r2 / d2) / (1.0 + cos_max);
        out.wi = Frame::from_axis(to_centre / std::sqrt(d2))
                     .to_world(sample_uniform_cone(rng.uniform(), rng.uniform(), cos_max));
        SurfaceHit h;
        // A direction grazing the silhouette can miss by rounding: it brings nothing.
        if (!m_sphere->intersect({p, out.wi}, surface_epsilon(p), INFINITY, h)) return false;
        out.distance = h.t;
        out.factor = 2.0 * kPi * one_minus_cos;  // radiance over the cone's uniform density
        return true;
    }

    bool is_delta() const override { return false; }

    // Judged from the centre: each point of the surface sees the targets a little
    // differently, and falls back to cosine sampling where aiming does not pay.
    bool worth_aiming(const PhotonTargets& targets) const override {
        return targets.solid_angle(m_sphere->centre()) < kPi;
    }

private:
    double area() const { return 4.0 * kPi * m_sphere->radius() * m_sphere->radius(); }
    Vec3 surface_point(const Vec3& normal) const {
        return m_sphere->centre() + normal * m_sphere->radius();
    }

    std::shared_ptr<const Sphere> m_sphere;
};

}  // namespace

PhotonStart PointSourceLight::sample_le(Rng& rng) const {
    const double u1 = rng.uniform(), u2 = rng.uniform();
    double pdf;
    const Vec3 dir = sample_direction(u1, u2, pdf);
    return photon_towards(dir, pdf);
}

PhotonStart PointSourceLight::sample_le_towards(const PhotonTargets& targets,
                                                const AimSample& u) const {
    Vec3 dir;
    double pdf;
    if (!targets.sample_direction(m_position, u[0], u[1], u[2], emission_solid_angle(), dir, pdf)) {
        dir = sample_direction(u[1], u[2], pdf);
    }
    // The intensity over the direction's density: 0 where the light sends nothing.
    return photon_towards(dir, pdf);
}

bool PointSourceLight::worth_aiming(const PhotonTargets& targets) const {
    return targets.solid_angle(m_position) < emission_solid_angle();
}

bool PointSourceLight::sample_li(const Vec3& p, Rng&, LightSample& out) const {
    const Vec3 to_light = m_position - p;
    const double dist2 = length_squared(to_light);
    if (!(dist2 > 0.0)) return false;
    out.distance = std::sqrt(dist2);
    out.wi = to_light / out.distance;
    const double i = intensity(-out.wi);
    if (i <= 0.0) return false;
    out.factor = i / dist2;  // E = I cos / r^2
    return true;
}

bool PointSourceLight::sample_in_scattering(const Ray& ray, double t_max, double u, double& t,
                                            double& pdf) const {
    return sample_equiangular(ray, t_max, m_position, u, t, pdf);
}

bool sample_equiangular(const Ray& ray, double t_max, const Vec3& light, double u, double& t,
                        double& pdf) {
    const double delta = dot(light - ray.origin, ray.direction);
    const double d = length(light - ray.at(delta));
    if (!(d > 1e-12)) return false;
    const double theta_a = std::atan2(-delta, d);
    const double theta_b = std::isfinite(t_max) ? std::atan2(t_max - delta, d) : 0.5 * kPi;
    if (!(theta_b > theta_a)) return false;
    const double offset = d * std::tan(theta_a + u * (theta_b - theta_a));
    t = std::clamp(delta + offset, 0.0, t_max);
    pdf = d / ((theta_b - theta_a) * (d * d + offset * offset));
    return t < t_max;
}

LightPtr make_point_light(const PointLight& l) { return std::make_shared<PointLightSource>(l); }
LightPtr make_beam_light(const BeamLight& b) { return std::make_shared<BeamLightSource>(b); }
LightPtr make_sphere_light(std::shared_ptr<const Sphere> sphere, SpectrumPtr radiance) {
    return std::make_shared<SphereLightSource>(std::move(sphere), std::move(radiance));
}

}  // namespace lenslab
