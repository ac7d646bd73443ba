#include "scene/light_source.h"

#include <cmath>

#include "geometry/sphere.h"
#include "math/constants.h"
#include "math/frame.h"
#include "math/sampling.h"
#include "scene/light.h"

namespace lenslab {

namespace {

// Isotropic: intensity spectrum / (4 pi) in every direction.
class PointLightSource final : public Light {
public:
    explicit PointLightSource(const PointLight& l) : Light(l.spectrum), m_position(l.position) {}

    double power() const override { return spectrum_watts(); }

    PhotonStart sample_le(Rng& rng) const override {
        const double u1 = rng.uniform(), u2 = rng.uniform();
        return {{m_position, sample_uniform_sphere(u1, u2)}, &spectrum(), 1.0};
    }

    PhotonStart sample_le_towards(const PhotonTargets& targets, const AimSample& u) const override {
        const double u0 = u[0], u1 = u[1], u2 = u[2];
        Vec3 dir;
        double pdf;
        if (!targets.sample_direction(m_position, u0, u1, u2, 4.0 * kPi, dir, pdf)) {
            return {{m_position, sample_uniform_sphere(u1, u2)}, &spectrum(), 1.0};
        }
        // Intensity 1 / (4 pi) per unit spectrum, over the direction's density.
        return {{m_position, dir}, &spectrum(), 1.0 / (4.0 * kPi * pdf)};
    }

    bool sample_li(const Vec3& p, Rng&, LightSample& out) const override {
        const Vec3 to_light = m_position - p;
        const double dist2 = length_squared(to_light);
        if (!(dist2 > 0.0)) return false;
        out.distance = std::sqrt(dist2);
        out.wi = to_light / out.distance;
        out.factor = 1.0 / (4.0 * kPi * dist2);  // E = I cos / r^2, I = Phi / (4 pi)
        return true;
    }

    bool is_delta() const override { return true; }

    bool worth_aiming(const PhotonTargets& targets) const override {
        return targets.solid_angle(m_position) < 4.0 * kPi;
    }

private:
    Vec3 m_position;
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

LightPtr make_point_light(const PointLight& l) { return std::make_shared<PointLightSource>(l); }
LightPtr make_beam_light(const BeamLight& b) { return std::make_shared<BeamLightSource>(b); }
LightPtr make_sphere_light(std::shared_ptr<const Sphere> sphere, SpectrumPtr radiance) {
    return std::make_shared<SphereLightSource>(std::move(sphere), std::move(radiance));
}

}  // namespace lenslab
