#include "render/photon_emission.h"

#include <numbers>

#include "math/frame.h"
#include "math/sampling.h"

namespace lenslab {

int photon_light_count(const Scene& scene) {
    return static_cast<int>(scene.emitters().size() + scene.point_lights.size() +
                            scene.beams.size());
}

const Spectrum& emitted_spectrum(const Scene& scene, int light) {
    const int spheres = static_cast<int>(scene.emitters().size());
    const int points = static_cast<int>(scene.point_lights.size());
    if (light < spheres) return *scene.emitters()[light].radiance;
    if (light < spheres + points) return *scene.point_lights[light - spheres].spectrum;
    return *scene.beams[light - spheres - points].spectrum;
}

PhotonStart emit_photon(const Scene& scene, int light, int64_t n, Rng& rng) {
    const Spectrum* spectrum = &emitted_spectrum(scene, light);
    const double inv_n = 1.0 / static_cast<double>(n);
    const int spheres = static_cast<int>(scene.emitters().size());
    const int points = static_cast<int>(scene.point_lights.size());
    if (light < spheres) {
        const Sphere& sphere = *scene.emitters()[light].sphere;
        const Vec3 normal = sample_uniform_sphere(rng.uniform(), rng.uniform());
        const Vec3 dir = Frame::from_axis(normal).to_world(
            sample_cosine_hemisphere(rng.uniform(), rng.uniform()));
        const double area = 4.0 * std::numbers::pi * sphere.radius() * sphere.radius();
        return {{sphere.centre() + normal * sphere.radius(), dir},
                spectrum,
                std::numbers::pi * area * inv_n};
    }
    if (light < spheres + points) {
        const PointLight& l = scene.point_lights[light - spheres];
        return {{l.position, sample_uniform_sphere(rng.uniform(), rng.uniform())}, spectrum, inv_n};
    }
    const BeamLight& b = scene.beams[light - spheres - points];
    double x, y;
    sample_disc_concentric(rng.uniform(), rng.uniform(), x, y);
    const Frame f = Frame::from_axis(b.direction);
    return {{b.origin + (f.u * x + f.v * y) * b.radius, b.direction}, spectrum, inv_n};
}

}  // namespace lenslab
