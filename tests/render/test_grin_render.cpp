// Every integrator through a gradient-index solid: a uniform formula n(x, y, z) = 1.5 must
// render like plain glass of index 1.5, since the ray equation then gives straight lines.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "render/integrator_names.h"
#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

Scene grin_render_scene(const std::string& material) {
    Scene scene =
        parse_scene(R"({"camera": {"position": [0, 1, 4], "look_at": [0, 0.5, 0], "fov": 40},
      "render": {"width": 24, "height": 16, "spp": 2, "photons": 4000, "passes": 2,
                 "pass_photons": 2000},
      "objects": [
        {"type": "sphere", "center": [0, 0.6, 0], "radius": 0.5, "material": )" +
                    material + R"(},
        {"type": "rectangle", "center": [0, 0, 0], "normal": [0, 1, 0], "size": [6, 6],
         "material": {"color": 0.7}}],
      "lights": [{"type": "point", "position": [1, 3, 1], "power": 100}]})");
    return scene;
}

TEST(GrinRender, UniformFormulaRendersLikePlainGlassWithEveryIntegrator) {
    Scene glass = grin_render_scene(R"({"transparency": 1, "ior": 1.5})");
    Scene grin = grin_render_scene(
        R"({"transparency": 1, "grin": {"profile": "formula", "formula": "1.5"}})");
    for (const std::string& name : integrator_names()) {
        SCOPED_TRACE(name);
        glass.render.integrator = name;
        grin.render.integrator = name;
        RenderControl c1, c2;
        const RenderResult a = render_scene(glass, c1, 1);
        const RenderResult b = render_scene(grin, c2, 1);
        ASSERT_EQ(a.film.pixels().size(), b.film.pixels().size());
        double worst = 0, brightest = 0;
        for (size_t i = 0; i < a.film.pixels().size(); ++i) {
            const PixelRgb& p = a.film.pixels()[i];
            const PixelRgb& q = b.film.pixels()[i];
            worst = std::max({worst, std::abs(double(p.r) - q.r), std::abs(double(p.g) - q.g),
                              std::abs(double(p.b) - q.b)});
            brightest = std::max({brightest, double(p.r), double(p.g), double(p.b)});
        }
        EXPECT_GT(brightest, 0.0);
        // Float pixels: the same up to their rounding.
        EXPECT_LE(worst, 1e-5 * brightest);
    }
}

}  // namespace
}  // namespace lenslab
