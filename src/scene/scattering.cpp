#include "scene/scattering.h"

#include <cmath>

#include "optics/fresnel.h"
#include "optics/refraction.h"

namespace lenslab {

const char* event_name(Event e) {
    switch (e) {
        case Event::Refract:
            return "refract";
        case Event::Reflect:
            return "reflect";
        case Event::Tir:
            return "tir";
        case Event::Absorb:
            return "absorb";
        case Event::Escape:
            return "escape";
    }
    return "unknown";
}

Scattering scatter(const Material& m, bool closed, const Vec3& d, const Vec3& outward_normal,
                   double lambda_nm, const Material* beyond) {
    return scatter_with_index(m, m.ior(lambda_nm), closed, d, outward_normal, lambda_nm, beyond,
                              beyond ? beyond->ior(lambda_nm) : kOutsideIor);
}

Scattering scatter_with_index(const Material& m, double n_inside, bool closed, const Vec3& d,
                              const Vec3& outward_normal, double lambda_nm, const Material* beyond,
                              double n_beyond) {
    Scattering s;
    s.diffuse = m.diffuse_weight();
    const bool entering = dot(d, outward_normal) < 0.0;
    const Vec3 facing = entering ? outward_normal : -outward_normal;  // towards the arriving ray
    const Vec3 mirrored = reflect(d, facing);
    const double cos_i = -dot(d, facing);

    double reflected = m.specular;
    Event reflect_event = Event::Reflect;
    if (m.transparency > 0.0) {
        if (closed) {
            const double n = n_inside;
            const double eta_i = entering ? n_beyond : n;
            const double eta_t = entering ? n : n_beyond;
            const FresnelTerms f = eta_i == eta_t ? FresnelTerms{0.0, 0.0, false}
                                                  : fresnel_dielectric(cos_i, eta_i, eta_t);
            if (f.total_internal_reflection) {
                reflected += m.transparency;
                reflect_event = Event::Tir;
            } else {
                const double r = f.reflectance();
                reflected += m.transparency * r;
                // Matched indices (a Luneburg lens's rim): the ray goes straight on, unreflected.
                if (auto t = eta_i == eta_t ? std::optional<Vec3>(d)
                                            : refract(d, facing, eta_i / eta_t)) {
                    s.branches[s.count++] = {Event::Refract, *t, m.transparency * (1.0 - r)};
                    s.dispersive = m.index->dispersive() || (beyond && beyond->index->dispersive());
                }
            }
        } else {
            // Incoherent sum of the reflections between the two faces, 2R / (1 + R), taken
            // per polarisation: the sum does not commute with averaging Rs and Rp.
            const FresnelTerms f = fresnel_dielectric(cos_i, kOutsideIor, m.ior(lambda_nm));
            const double r_pane = 0.5 * (2.0 * f.rs / (1.0 + f.rs) + 2.0 * f.rp / (1.0 + f.rp));
            reflected += m.transparency * r_pane;
            s.branches[s.count++] = {Event::Refract, d, m.transparency * (1.0 - r_pane)};
        }
    }
    if (reflected > 0.0) {
        // Keep the reflected branch first: tests and traces list it before the refracted one.
        if (s.count == 1) s.branches[1] = s.branches[0];
        s.branches[0] = {reflect_event, mirrored, reflected};
        ++s.count;
    }
    return s;
}

}  // namespace lenslab
