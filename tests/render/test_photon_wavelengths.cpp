// Issue 39: aimed photons take their wavelength from the last coordinate of their Halton
// point (render/photon_emission.h), so photons that land close together (from nearby points)
// have wavelengths spread evenly over the light's spectrum, and a gather disc in a dispersive
// caustic sees a smooth mix instead of a random handful of colours.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "render/photon_emission.h"
#include "render/photon_map.h"
#include "render/photon_tracer.h"
#include "scene/interaction.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// A point light over a ball of dense flint (N-SF11) on a floor: the ball's caustic.
Scene ball_caustic() {
    return parse_scene(R"({
      "camera": {"position": [0, 2, -3], "look_at": [0, 0, 0], "fov": 40},
      "objects": [
        {"type": "triangle", "vertices": [[-50, 0, -50], [-50, 0, 50], [50, 0, 50]], "material": {"color": 0.5}},
        {"type": "triangle", "vertices": [[-50, 0, -50], [50, 0, 50], [50, 0, -50]], "material": {"color": 0.5}},
        {"type": "sphere", "center": [0, 0.6, 0], "radius": 0.5, "material": {"color": 1, "transparency": 1, "glass": "N-SF11"}}],
      "lights": [{"type": "point", "position": [0, 3, 0], "power": 100}]})");
}

using Cells = std::map<std::pair<int, int>, std::vector<double>>;

// The wavelengths of the aimed photons that reach the floor through the ball, by landing
// cell (3 cm square: about a gather disc).
Cells floor_wavelengths(const Scene& scene, uint64_t seed) {
    PhotonTracingSettings settings{0, 8, seed, 20000, true};
    const PhotonPlan plan = photon_plan(scene, settings);
    EXPECT_EQ(plan.total(), plan.aimed_total()) << "the aimed stream only";
    Cells cells;
    for (int64_t i = 0; i < plan.total(); ++i) {
        trace_photon_path(scene, settings, plan, i, [&](const PhotonArrival& a) {
            const Vec3& p = a.interaction->point();
            if (a.lambda_nm <= 0 || a.depth < 2 || std::abs(p.y) > 1e-6) return;
            cells[{static_cast<int>(std::floor(p.x / 0.03)),
                   static_cast<int>(std::floor(p.z / 0.03))}]
                .push_back(a.lambda_nm);
        });
    }
    return cells;
}

// A cell's mean wavelength varies from seed to seed far less than independent draws of its
// wavelengths would make it (their variance over the count).
TEST(PhotonWavelengths, PhotonsLandingTogetherSpreadOverTheSpectrum) {
    const Scene scene = ball_caustic();
    std::vector<Cells> runs;
    for (uint64_t seed = 1; seed <= 4; ++seed) runs.push_back(floor_wavelengths(scene, seed));
    double between = 0, independent = 0;
    int counted = 0;
    for (const auto& [cell, first] : runs[0]) {
        std::vector<double> means;
        double within = 0;
        for (const Cells& run : runs) {
            const auto it = run.find(cell);
            if (it == run.end() || it->second.size() < 30) break;
            const std::vector<double>& nm = it->second;
            double mean = 0, square = 0;
            for (double x : nm) mean += x / nm.size();
            for (double x : nm) square += (x - mean) * (x - mean) / (nm.size() - 1);
            means.push_back(mean);
            within += square / nm.size() / runs.size();
        }
        if (means.size() < runs.size()) continue;
        double grand = 0, spread = 0;
        for (double m : means) grand += m / means.size();
        for (double m : means) spread += (m - grand) * (m - grand) / (means.size() - 1);
        between += spread;
        independent += within;
        ++counted;
    }
    ASSERT_GT(counted, 10);
    std::printf(
        "%d cells: variance of a cell's mean wavelength over seeds %.3f nm^2, "
        "independent draws %.3f nm^2\n",
        counted, between / counted, independent / counted);
    EXPECT_LT(between, 0.5 * independent);
}

}  // namespace
}  // namespace lenslab
