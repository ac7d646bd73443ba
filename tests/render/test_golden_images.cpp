// Small scenes rendered and compared with committed reference images. The references were
// rendered by lenslab and checked by eye; regenerate them after an intended change with
//   LENSLAB_UPDATE_GOLDEN=1 build/release/tests/test_render
// and look at every changed image before committing it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "image/image_io.h"
#include "render/render_session.h"
#include "scene/scene_json.h"

namespace lenslab {
namespace {

const std::string kGoldenDir = std::string(LENSLAB_TEST_DATA) + "/golden/";

Film render_golden(const std::string& name, int threads = 0) {
    const Scene scene = load_scene_file(kGoldenDir + name + ".json");
    RenderControl control;
    return render_scene(scene, control, threads).film;
}

class GoldenImage : public ::testing::TestWithParam<const char*> {};

TEST_P(GoldenImage, MatchesTheReference) {
    const std::string name = GetParam();
    const Film film = render_golden(name);
    const std::string reference = kGoldenDir + name + ".png";
    if (std::getenv("LENSLAB_UPDATE_GOLDEN")) {
        write_image(film, reference);
        GTEST_SKIP() << "wrote " << reference;
    }
    const Image8 expected = read_png(reference);
    const Image8 actual = to_srgb8(film);
    ASSERT_EQ(actual.width, expected.width);
    ASSERT_EQ(actual.height, expected.height);
    // Tolerances allow for a different compiler's rounding, not for a different picture:
    // a mean error under 1 level in 255 and under 1% of values off by more than 16 levels.
    double total = 0;
    int large = 0;
    for (size_t i = 0; i < actual.rgb.size(); ++i) {
        const int diff = std::abs(int(actual.rgb[i]) - int(expected.rgb[i]));
        total += diff;
        large += diff > 16;
    }
    EXPECT_LT(total / actual.rgb.size(), 1.0);
    EXPECT_LT(large, static_cast<int>(actual.rgb.size() / 100));
}

INSTANTIATE_TEST_SUITE_P(Scenes, GoldenImage,
                         ::testing::Values("glass_sphere_inverts", "lens_forms",
                                           "mirror_beam_pane"));

// The references named *_rgb.png were rendered by the RGB transport of the first version
// (issue 2). With constant indices, spectral transport must give the same picture: no
// colour shift. Compared in linear light, per channel, over the whole image, with enough
// samples that wavelength noise averages out.
TEST_P(GoldenImage, SpectralAgreesWithTheRgbRender) {
    const std::string name = GetParam();
    Scene scene = load_scene_file(kGoldenDir + name + ".json");
    scene.render.spp = 64;
    RenderControl control;
    const Film film = render_scene(scene, control).film;
    const Image8 rgb = read_png(kGoldenDir + name + "_rgb.png");
    auto to_linear = [](unsigned char v) {
        const double c = v / 255.0;
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    double spectral[3] = {0, 0, 0}, reference[3] = {0, 0, 0};
    for (size_t i = 0; i < film.pixels().size(); ++i) {
        const PixelRgb& p = film.pixels()[i];
        // Clip as the 8-bit reference did, so bright highlights compare like with like.
        spectral[0] += std::min(p.r, 1.0f);
        spectral[1] += std::min(p.g, 1.0f);
        spectral[2] += std::min(p.b, 1.0f);
        for (int c = 0; c < 3; ++c) reference[c] += to_linear(rgb.rgb[3 * i + c]);
    }
    for (int c = 0; c < 3; ++c) {
        std::printf("%s channel %d: spectral %.4f, rgb %.4f\n", name.c_str(), c,
                    spectral[c] / film.pixels().size(), reference[c] / film.pixels().size());
        EXPECT_NEAR(spectral[c] / reference[c], 1.0, 0.01) << "channel " << c;
    }
}

// A ball lens forms an inverted real image of a distant scene: seen through the ball, the
// wall's blue lower half appears at the top and the red upper half at the bottom.
TEST(GoldenImage, GlassSphereShowsTheSceneBehindItUpsideDown) {
    const Film film = render_golden("glass_sphere_inverts");
    const int c = film.width() / 2;
    auto redness = [&](int x, int y) { return film.at(x, y).r - film.at(x, y).b; };
    // Outside the ball (corners): red above, blue below.
    EXPECT_GT(redness(2, 2), 0.3);
    EXPECT_LT(redness(2, film.height() - 3), -0.3);
    // Inside the ball, a quarter radius above and below its centre: the opposite.
    const int offset = film.height() / 12;
    EXPECT_LT(redness(c, c - offset), -0.2) << "top of the ball should show the blue half";
    EXPECT_GT(redness(c, c + offset), 0.2) << "bottom of the ball should show the red half";
}

}  // namespace
}  // namespace lenslab
