#include "scene/area_light_source.h"

#include <cmath>

#include "math/constants.h"
#include "math/frame.h"
#include "math/sampling.h"

namespace lenslab {

Vec3 AreaLightSource::sample_point(double u1, double u2) const {
    const std::array<double, 2> uv = sample_uv(u1, u2);
    return m_frame.at(uv[0], uv[1]);
}

// Position uniform (density 1 / A) and direction cosine-weighted (cos / pi): the photon
// carries L cos / (pdf_A pdf_w) = Phi, the whole flux, as one photon of one sent.
PhotonStart AreaLightSource::sample_le(Rng& rng) const {
    const double u1 = rng.uniform(), u2 = rng.uniform();
    const Vec3 from = sample_point(u1, u2);
    const double u3 = rng.uniform(), u4 = rng.uniform();
    const Vec3 dir = Frame::from_axis(m_frame.n).to_world(sample_cosine_hemisphere(u3, u4));
    return {{from, dir}, &spectrum(), 1.0};
}

PhotonStart AreaLightSource::sample_le_towards(const PhotonTargets& targets,
                                               const AimSample& u) const {
    const Vec3 from = sample_point(u[3], u[4]);
    Vec3 dir;
    double pdf;
    // Cosine sampling has density cos / pi <= 1 / pi: aiming pays where the targets subtend
    // less than pi steradians.
    if (!targets.sample_direction(from, u[0], u[1], u[2], kPi, dir, pdf)) {
        const Vec3 d = Frame::from_axis(m_frame.n).to_world(sample_cosine_hemisphere(u[1], u[2]));
        return {{from, d}, &spectrum(), 1.0};
    }
    // L cos A / pdf_w with L = Phi / (pi A); nothing leaves the back.
    const double cos_theta = dot(dir, m_frame.n);
    return {{from, dir}, &spectrum(), cos_theta > 0.0 ? cos_theta / (kPi * pdf) : 0.0};
}

// Judged from the centre, as an emitting sphere's.
bool AreaLightSource::worth_aiming(const PhotonTargets& targets) const {
    return targets.solid_angle(m_frame.origin) < kPi;
}

bool AreaLightSource::sample_li(const Vec3& p, Rng& rng, LightSample& out) const {
    const double u1 = rng.uniform(), u2 = rng.uniform();
    const Vec3 to_light = sample_point(u1, u2) - p;
    const double d2 = length_squared(to_light);
    if (!(d2 > 0.0)) return false;
    out.distance = std::sqrt(d2);
    out.wi = to_light / out.distance;
    const double cos_light = -dot(out.wi, m_frame.n);
    if (cos_light <= 0.0) return false;  // behind the patch, or in its plane
    // L cos' A / d^2 per unit of spectrum (the flux): cos' / (pi d^2).
    out.factor = cos_light / (kPi * d2);
    return true;
}

Aabb AreaLightSource::bounds() const {
    Aabb box;
    for (const double su : {-1.0, 1.0}) {
        for (const double sv : {-1.0, 1.0})
            box.expand(m_frame.at(su * m_half_size[0], sv * m_half_size[1]));
    }
    return box;
}

bool AreaLightSource::sample_in_scattering(const Ray& ray, double t_max, double u, double& t,
                                           double& pdf) const {
    return sample_equiangular(ray, t_max, m_frame.origin, u, t, pdf);
}

}  // namespace lenslab
