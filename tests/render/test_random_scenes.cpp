// Property tests over random scenes (random_scene.h): whatever a user builds from spheres,
// lenses, triangles, prisms and implicit solids, with any materials and lights,
//   - no sample of any integrator is NaN or infinite, and no pixel is;
//   - no stored photon has a NaN or infinite position or power;
//   - no photon gains power: between its light and the surface that stores it, an emitted
//     photon's power changes only by the storage's Russian roulette (divided by the
//     probability p_diffuse of being stored there, Jensen 2001, section 5.2), so stored power
//     x p_diffuse equals, to float precision, what its light gave it; an aimed photon carries
//     at most that (it was sent where it is denser, and split at the glass).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "random_scene.h"
#include "render/integrators/photon_map.h"
#include "render/photon_tracer.h"
#include "render/render_session.h"

namespace lenslab {
namespace {

constexpr int kScenes = 24;

bool finite(const float v[3]) {
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

// The power one emitted photon of each light leaves with: an emitting sphere of radiance L
// and radius R sends pi L 4 pi R^2, a point light or a beam its power, divided among the
// photons that light sends (photons_by_power).
std::vector<Rgb> emitted_per_photon(const Scene& scene, int64_t photons_per_light) {
    std::vector<Rgb> out;
    const std::vector<int64_t> counts = photons_by_power(scene, photons_per_light);
    size_t light = 0;
    auto add = [&](const Rgb& total) {
        out.push_back(total * (1.0 / static_cast<double>(counts[light++])));
    };
    for (const SphereEmitter& e : scene.emitters()) {
        const double r = e.sphere.radius;
        add(spectrum_to_rgb(*e.radiance) * (std::numbers::pi * 4 * std::numbers::pi * r * r));
    }
    for (const PointLight& l : scene.point_lights) add(spectrum_to_rgb(*l.spectrum));
    for (const BeamLight& b : scene.beams) add(spectrum_to_rgb(*b.spectrum));
    return out;
}

// The probability that a photon arriving at `p` along -towards is stored there: the diffuse
// share of the material found just behind it. Negative when no surface is there.
double storage_probability(const Scene& scene, const Photon& ph) {
    const Vec3 towards = ph.incoming();
    const double eps = 1e-4 * std::max(1.0, length(ph.pos()));
    SceneHit hit;
    if (!scene.intersect({ph.pos() + towards * eps, -towards}, 0.0, 2 * eps, hit)) return -1;
    const Material& m = scene.materials[scene.objects[hit.object].material];
    return m.color.is_black() ? 0.0 : m.diffuse_weight();
}

bool matches(const Rgb& a, const Rgb& b) {
    const double scale = std::max({std::abs(b.r), std::abs(b.g), std::abs(b.b)});
    const double tol = 1e-5 * scale + 1e-30;
    return std::abs(a.r - b.r) <= tol && std::abs(a.g - b.g) <= tol && std::abs(a.b - b.b) <= tol;
}

TEST(RandomScenes, NoIntegratorMakesANonFiniteSampleOrPixel) {
    for (uint64_t seed = 1; seed <= kScenes; ++seed) {
        const Scene base = testing::random_scene(seed);
        for (const std::string& name : integrator_names()) {
            SCOPED_TRACE("scene seed " + std::to_string(seed) + ", integrator " + name + ":\n" +
                         testing::random_scene_json(seed).dump());
            Scene scene = base;
            scene.render.integrator = name;
            RenderControl control;
            const RenderResult r = render_scene(scene, control, 2);
            ASSERT_FALSE(r.cancelled);
            EXPECT_EQ(control.non_finite_samples(), 0);
            for (const PixelRgb& p : r.film.pixels()) {
                ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b));
                ASSERT_TRUE(p.r >= 0 && p.g >= 0 && p.b >= 0);
            }
        }
    }
}

TEST(RandomScenes, EveryStoredPhotonIsFinite) {
    size_t photons = 0;
    for (uint64_t seed = 1; seed <= kScenes; ++seed) {
        SCOPED_TRACE("scene seed " + std::to_string(seed) + ":\n" +
                     testing::random_scene_json(seed).dump());
        const Scene scene = testing::random_scene(seed);
        RenderControl control;
        const PhotonMap map = trace_photons(scene, photon_tracing_settings(scene), control);
        for (const PhotonKdTree* tree : {&map.direct(), &map.caustic()}) {
            for (size_t i = 0; i < tree->size(); ++i) {
                const Photon& ph = tree->begin()[i];
                ASSERT_TRUE(finite(ph.position) && finite(ph.power)) << "photon " << i;
            }
            photons += tree->size();
        }
    }
    EXPECT_GT(photons, 1000u);  // the scenes do store photons
}

TEST(RandomScenes, NoPhotonGainsPower) {
    // Constant-index glass: a photon keeps its light's spectrum, so its colour is exact.
    testing::RandomSceneOptions options;
    options.dispersive = false;
    size_t checked = 0, unplaced = 0, aimed = 0;
    for (uint64_t seed = 1; seed <= kScenes; ++seed) {
        for (const bool aim : {false, true}) {
            SCOPED_TRACE("scene seed " + std::to_string(seed) + (aim ? ", aimed" : ", uniform") +
                         ":\n" + testing::random_scene_json(seed, options).dump());
            const Scene scene = testing::random_scene(seed, options);
            PhotonTracingSettings settings = photon_tracing_settings(scene);
            settings.aim = aim;
            settings.photons_per_light = settings.caustic_photons_per_light = scene.render.photons;
            const std::vector<Rgb> emitted = emitted_per_photon(scene, settings.photons_per_light);
            double most = 0;
            for (const Rgb& e : emitted) most = std::max({most, e.r, e.g, e.b});
            RenderControl control;
            const PhotonMap map = trace_photons(scene, settings, control);
            for (const PhotonKdTree* tree : {&map.direct(), &map.caustic()}) {
                for (size_t i = 0; i < tree->size(); ++i) {
                    const Photon& ph = tree->begin()[i];
                    const double p_diffuse = storage_probability(scene, ph);
                    if (p_diffuse < 0) {
                        ++unplaced;  // two surfaces closer than the probe: cannot tell which
                        continue;
                    }
                    ASSERT_GT(p_diffuse, 0.0)
                        << "photon " << i << " stored on a surface that cannot store";
                    const Rgb carried = ph.flux() * p_diffuse;
                    bool from_a_light = false;
                    for (const Rgb& e : emitted) from_a_light = from_a_light || matches(carried, e);
                    if (aim && !from_a_light) {
                        ASSERT_LE(std::max({carried.r, carried.g, carried.b}), most * (1 + 1e-5))
                            << "aimed photon " << i << " carried more than any light's photons";
                        ++aimed;
                    } else {
                        ASSERT_TRUE(from_a_light)
                            << "photon " << i << " carried (" << carried.r << ", " << carried.g
                            << ", " << carried.b << "), which no light emitted";
                    }
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(aimed, 1000u);  // the scenes do aim photons at their glass
    EXPECT_GT(checked, 1000u);
    EXPECT_LT(unplaced, checked / 100 + 1);
}

}  // namespace
}  // namespace lenslab
