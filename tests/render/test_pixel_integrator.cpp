// A window of an image renders each of its pixels exactly as the whole image does, and
// nothing outside it: a caustic's reference can take far more samples than the whole.

#include <gtest/gtest.h>

#include "render/integrator.h"
#include "render/integrator_registry.h"
#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

TEST(PixelWindow, RendersItsPixelsAsTheWholeImageDoesAndLeavesTheRestBlack) {
    Scene scene = default_scene();
    scene.render.width = 40;
    scene.render.height = 30;
    scene.render.spp = 2;
    scene.render.integrator = "path";
    RenderControl control;
    const Film whole = render_scene(scene, control, 2).film;

    const PixelWindow window{13, 7, 31, 19};  // across tile borders (tiles are 16 pixels)
    Film part(scene.render.width, scene.render.height);
    const Camera camera(scene.camera, scene.render.width, scene.render.height);
    auto integrator = make_integrator(scene);
    auto* pixels = dynamic_cast<PixelIntegrator*>(integrator.get());
    ASSERT_NE(pixels, nullptr);
    EXPECT_TRUE(pixels->render_window(scene, camera, part, control, window));

    int lit_inside = 0;
    for (int y = 0; y < scene.render.height; ++y) {
        for (int x = 0; x < scene.render.width; ++x) {
            const PixelRgb& p = part.at(x, y);
            if (window.contains(x, y)) {
                const PixelRgb& w = whole.at(x, y);
                EXPECT_EQ(p.r, w.r) << x << "," << y;
                EXPECT_EQ(p.g, w.g) << x << "," << y;
                EXPECT_EQ(p.b, w.b) << x << "," << y;
                lit_inside += p.r + p.g + p.b > 0;
            } else {
                EXPECT_EQ(p.r + p.g + p.b, 0.0f) << "outside the window: " << x << "," << y;
            }
        }
    }
    EXPECT_GT(lit_inside, 0) << "the window saw nothing: the test would prove nothing";
}

}  // namespace
}  // namespace lenslab
