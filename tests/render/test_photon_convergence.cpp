// The photon map converges: the caustic estimate's error against a 20-million-photon
// reference falls as the photon count grows. In its own file because it is the one test the
// sanitized stage of scripts/test-all.sh leaves out (minutes under ASan): the release stage
// builds this file alone (LENSLAB_UNSANITIZED_TESTS_ONLY, tests/CMakeLists.txt).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "render/integrators/photon_map.h"
#include "render/photon_tracer.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// A diffuse floor, 10 across, at y = 0.
const std::string kConvergenceFloor =
    R"({"name": "floor", "type": "triangle", "vertices": [[-5, 0, -5], [-5, 0, 5], [5, 0, 5]], "material": {"color": 0.5}},
       {"name": "floor", "type": "triangle", "vertices": [[-5, 0, -5], [5, 0, 5], [5, 0, -5]], "material": {"color": 0.5}})";

PhotonMap trace_caustics(const Scene& scene, int64_t photons) {
    RenderControl control;
    PhotonTracingSettings settings;
    settings.photons_per_light = photons;
    return trace_photons(scene, settings, control, nullptr);
}

TEST(PhotonMap, CausticErrorShrinksAsPhotonsGrow) {
    // A beam through a glass ball onto a floor: the caustic estimate on a grid, against a
    // 20M-photon reference. The gather radius is fixed, so the bias is the same for every
    // count and what remains is noise, which must fall as photons grow.
    const Scene scene = parse_scene(R"({"camera": {"position": [0, 5, 5], "look_at": [0, 0, 0]},
        "objects": [{"type": "sphere", "center": [0, 1.2, 0], "radius": 0.5, "material": {"transparency": 1, "ior": 1.5}}, )" +
                                    kConvergenceFloor + R"(],
        "lights": [{"type": "beam", "origin": [0, 3, 0], "direction": [0, -1, 0], "radius": 0.5, "power": 1}]})");
    GatherSettings g;
    g.radius = 0.03;
    g.max_photons = 1000000;
    std::vector<PhotonNeighbour> scratch;
    auto grid = [&](const PhotonMap& map) {
        std::vector<double> e;
        for (int i = -6; i <= 6; ++i) {
            for (int j = -6; j <= 6; ++j) {
                e.push_back(PhotonMap::irradiance(map.caustic(), {i * 0.05, 0, j * 0.05}, {0, 1, 0},
                                                  g, scratch)
                                .g);
            }
        }
        return e;
    };
    const std::vector<double> reference = grid(trace_caustics(scene, 20000000));
    double previous = INFINITY;
    for (int64_t photons : {50000, 200000, 800000, 3200000}) {
        const std::vector<double> e = grid(trace_caustics(scene, photons));
        double err = 0, norm = 0;
        for (size_t i = 0; i < e.size(); ++i) {
            err += (e[i] - reference[i]) * (e[i] - reference[i]);
            norm += reference[i] * reference[i];
        }
        const double relative = std::sqrt(err / norm);
        RecordProperty("photons_" + std::to_string(photons), std::to_string(relative));
        std::printf("caustic error with %lld photons: %.4f\n", static_cast<long long>(photons),
                    relative);
        EXPECT_LT(relative, previous);
        previous = relative;
    }
    EXPECT_LT(previous, 0.05);
}

}  // namespace
}  // namespace lenslab
