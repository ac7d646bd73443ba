// The integrator registry: it names what the scene reader accepts, every entry makes its
// integrator both ways, and its `progressive` flag says how the integrator renders.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "render/integrator_registry.h"
#include "render/progressive_render.h"
#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

Scene small_caustic_room() {
    Scene s = load_scene_file(LENSLAB_SOURCE_DIR "/scenes/caustic_room.json");
    s.render.width = s.render.height = 12;
    s.render.spp = 1;
    s.render.photons = 2000;
    s.render.passes = 2;
    s.render.pass_photons = 1000;
    return s;
}

bool same_pixels_registry(const Film& a, const Film& b) {
    if (a.width() != b.width() || a.height() != b.height()) return false;
    for (size_t i = 0; i < a.pixels().size(); ++i) {
        const PixelRgb &p = a.pixels()[i], &q = b.pixels()[i];
        if (p.r != q.r || p.g != q.g || p.b != q.b) return false;
    }
    return true;
}

TEST(IntegratorRegistry, NamesWhatTheSceneReaderAccepts) {
    EXPECT_EQ(integrator_names(), kIntegratorNames);
}

TEST(IntegratorRegistry, EveryEntryIsDescribedAndMakesItsIntegrator) {
    const Scene scene = small_caustic_room();
    for (const IntegratorInfo& info : integrator_registry()) {
        SCOPED_TRACE(std::string(info.name));
        EXPECT_FALSE(info.description.empty());
        EXPECT_EQ(info.description.find('\n'), std::string_view::npos);
        EXPECT_NE(info.make(scene), nullptr);
        EXPECT_NE(info.make_progressive(scene), nullptr);
        EXPECT_EQ(&integrator_info(info.name), &info);
    }
}

TEST(IntegratorRegistry, RefusesAnUnknownName) {
    try {
        integrator_info("raymarch");
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "unknown integrator 'raymarch'");
    }
    Scene scene = small_caustic_room();
    scene.render.integrator = "raymarch";
    EXPECT_THROW(make_integrator(scene), std::invalid_argument);
    EXPECT_THROW(ProgressiveRender{scene}, std::invalid_argument);
}

// A progressive integrator reports the passes it ran; the others took samples per pixel.
TEST(IntegratorRegistry, ProgressiveFlagSaysHowTheIntegratorRenders) {
    for (const IntegratorInfo& info : integrator_registry()) {
        SCOPED_TRACE(std::string(info.name));
        Scene scene = small_caustic_room();
        scene.render.integrator = info.name;
        RenderControl control;
        const RenderResult result = render_scene(scene, control, 1);
        EXPECT_EQ(result.stats.passes, info.progressive ? scene.render.passes : 0);
    }
}

// Pass by pass, an integrator that takes samples per pixel gives after one pass the image of
// one sample per pixel (the same seed), and reuses its photon maps for the later passes.
TEST(IntegratorRegistry, AveragedPassesStartWithTheOneSampleImage) {
    for (const IntegratorInfo& info : integrator_registry()) {
        if (info.progressive) continue;
        SCOPED_TRACE(std::string(info.name));
        Scene scene = small_caustic_room();
        scene.render.integrator = info.name;
        RenderControl control;
        const RenderResult once = render_scene(scene, control, 1);
        ProgressiveRender progressive(scene, 2);
        ASSERT_TRUE(progressive.add_pass(control));
        EXPECT_TRUE(same_pixels_registry(progressive.image(), once.film));
        EXPECT_EQ(progressive.stats(1.0).photons, once.stats.photons);
        ASSERT_TRUE(progressive.add_pass(control));
        EXPECT_EQ(progressive.passes(), 2);
        EXPECT_EQ(progressive.stats(1.0).passes, 2);
        EXPECT_EQ(progressive.stats(1.0).photons, once.stats.photons);  // the same maps
    }
}

}  // namespace
}  // namespace lenslab
