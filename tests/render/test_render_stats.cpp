// What integrators report as generic statistics: the summary lines the command line prints
// (and tools parse), the counts the editor shows, and named values.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "render/integrator_names.h"
#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

RenderResult render_with(std::string_view integrator) {
    Scene s = load_scene_file(LENSLAB_SOURCE_DIR "/scenes/caustic_room.json");
    s.render.width = s.render.height = 12;
    s.render.spp = 1;
    s.render.photons = 2000;
    s.render.passes = 3;
    s.render.pass_photons = 1000;
    s.render.integrator = integrator;
    RenderControl control;
    return render_scene(s, control, 1);
}

bool starts_with(const std::string& s, const std::string& prefix) {
    return s.rfind(prefix, 0) == 0;
}

TEST(RenderStats, ValueByName) {
    RenderStats stats;
    stats.values = {{"a", 1.5}, {"b", 2}};
    EXPECT_EQ(stats.value("b"), 2);
    EXPECT_THROW(stats.value("c"), std::out_of_range);
}

TEST(RenderStats, PhotonMapSummarisesItsPhotons) {
    const RenderStats s = render_with(integrators::kPhotonMap).stats;
    EXPECT_TRUE(starts_with(
        s.summary,
        "photons: " + std::to_string(int64_t(s.value("photons_emitted"))) + " emitted ("))
        << s.summary;
    EXPECT_NE(s.summary.find(" caustic stored ("), std::string::npos) << s.summary;
    EXPECT_EQ(s.summary.find('\n'), std::string::npos);
    EXPECT_EQ(s.photons, int64_t(s.value("direct_photons") + s.value("caustic_photons")));
    EXPECT_GT(s.photons, 0);
    EXPECT_EQ(s.passes, 0);
}

TEST(RenderStats, SppmSummarisesItsPasses) {
    const RenderStats s = render_with(integrators::kSppm).stats;
    EXPECT_TRUE(
        starts_with(s.summary, "sppm: 3 passes, " + std::to_string(s.photons) + " photons ("))
        << s.summary;
    EXPECT_EQ(s.passes, 3);
    EXPECT_EQ(s.value("passes"), 3);
    EXPECT_EQ(s.photons, int64_t(s.value("photons_emitted")));
    EXPECT_GT(s.value("mean_radius"), 0);
}

TEST(RenderStats, RayTracersHaveNothingToSay) {
    for (std::string_view name : {integrators::kWhitted, integrators::kPath}) {
        const RenderStats s = render_with(name).stats;
        EXPECT_TRUE(s.summary.empty()) << name;
        EXPECT_EQ(s.passes, 0);
        EXPECT_EQ(s.photons, 0);
    }
}

}  // namespace
}  // namespace lenslab
