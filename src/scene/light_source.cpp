#include "scene/light_source.h"

#include <algorithm>
#include <cmath>

#include "geometry/shape.h"
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

// A Lambertian emitter: radiance spectrum from every point of its surface, so it sends
// pi L 4 pi R^2 in all.
class SphereLightSource final : public Light {
public:
    SphereLightSource(std::shared_ptr<const Shape> shape, BoundingSphere sphere,
                      SpectrumPtr radiance)
        : Light(std::move(radiance)), m_shape(std::move(shape)), m_sphere(sphere) {}

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
        const Vec3 to_centre = m_sphere.centre - p;
        const double d2 = length_squared(to_centre);
        const double r2 = m_sphere.radius * m_sphere.radius;
        if (d2 <= r2) return false;  // inside the light
        const double cos_max = std::sqrt(1.0 - r2 / d2);
        // 1 - cos_max written without cancellation for small, distant lights.
        const double one_minus_cos = (r2 / d2) / (1.0 + cos_max);
        out.wi = Frame::from_axis(to_centre / std::sqrt(d2))
                     .to_world(sample_uniform_cone(rng.uniform(), rng.uniform(), cos_max));
        SurfaceHit h;
        // A direction grazing the silhouette can miss by rounding: it brings nothing.
        if (!m_shape->intersect({p, out.wi}, surface_epsilon(p), INFINITY, h)) return false;
        out.distance = h.t;
        out.factor = 2.0 * kPi * one_minus_cos;  // radiance over the cone's uniform density
        return true;
    }

    bool is_delta() const override { return false; }
    Aabb bounds() const override { return m_shape->bounds(); }

    // Towards the centre: a small light seen from afar is all but a point, and a large one
    // still sends the most where the ray passes closest.
    bool samples_in_scattering() const override { return true; }
    bool sample_in_scattering(const Ray& ray, double t_max, double u, double& t,
                              double& pdf) const override {
        return sample_equiangular(ray, t_max, m_sphere.centre, u, t, pdf);
    }

    // Judged from the centre: each point of the surface sees the targets a little
    // differently, and falls back to cosine sampling where aiming does not pay.
    bool worth_aiming(const PhotonTargets& targets) const override {
        return targets.solid_angle(m_sphere.centre) < kPi;
    }

private:
    double area() const { return 4.0 * kPi * m_sphere.radius * m_sphere.radius; }
    Vec3 surface_point(const Vec3& normal) const {
        return m_sphere.centre + normal * m_sphere.radius;
    }

    std::shared_ptr<const Shape> m_shape;
    BoundingSphere m_sphere;
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
LightPtr make_sphere_light(std::shared_ptr<const Shape> shape, BoundingSphere sphere,
                           SpectrumPtr radiance) {
    return std::make_shared<SphereLightSource>(std::move(shape), sphere, std::move(radiance));
}

}  // namespace lenslab
