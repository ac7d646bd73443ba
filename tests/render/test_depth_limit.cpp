// The deepest render the limits allow (render.max_depth 1000, docs/reliability.md) runs to
// the end: between two parallel perfect mirrors every camera ray bounces max_depth times,
// each bounce one more level of the Whitted integrator's recursion, on a worker thread's
// stack (and, in the asan build, with the sanitizer's larger frames).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render/render_session.h"
#include "scene/limits.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

// Two parallel perfect mirrors (z = -1 and z = 1, x from -1 to 18) and a camera between
// them looking along (0.01, 0, 1): a camera ray crosses the 2 units between the mirrors 900
// times, moving 0.02 along x each time, before it leaves past x = 18 into the white
// background. So a pixel is white exactly when the render followed 900 bounces.
Scene mirror_corridor(int max_depth) {
    const std::string mirror =
        R"({"type": "triangle", "vertices": [[-1, -5, Z], [18, -5, Z], [18, 5, Z]], "material": {"specular": 1}},
        {"type": "triangle", "vertices": [[-1, -5, Z], [18, 5, Z], [-1, 5, Z]], "material": {"specular": 1}})";
    auto at = [&](const char* z) {
        std::string m = mirror;
        for (size_t p; (p = m.find('Z')) != std::string::npos;) m.replace(p, 1, z);
        return m;
    };
    return parse_scene(R"({
      "camera": {"position": [0, 0, 0], "direction": [0.01, 0, 1], "fov": 0.001},
      "render": {"width": 2, "height": 2, "spp": 256, "max_depth": )" +
                       std::to_string(max_depth) + R"(,
                 "min_weight": 1e-6, "background": 1, "photons": 1000},
      "objects": [)" + at("1") +
                       ", " + at("-1") + R"(],
      "lights": [{"type": "point", "position": [0, 0, 0.5], "power": 10}]
    })");
}

TEST(DepthLimit, MirrorCorridorAtTheDeepestAllowedDepth) {
    for (const std::string& name : integrator_names()) {
        SCOPED_TRACE(name);
        for (int depth : {kMaxDepth, 800}) {
            Scene scene = mirror_corridor(depth);
            scene.render.integrator = name;
            RenderControl control;
            const RenderResult r = render_scene(scene, control, 2);
            EXPECT_FALSE(r.cancelled);
            EXPECT_EQ(control.non_finite_samples(), 0);
            // Past 900 bounces the background shows (white to the colour noise of 256
            // samples of 4 wavelengths); cut at 800 the pixel stays black.
            const double expected = depth > 900 ? 1.0 : 0.0;
            for (const PixelRgb& p : r.film.pixels())
                EXPECT_NEAR(p.g, expected, 0.02) << "max_depth " << depth;
        }
    }
}

}  // namespace
}  // namespace lenslab
