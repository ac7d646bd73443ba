#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "image/image_io.h"
#include "image/tone_map.h"
#include "scene/render_settings_json.h"
#include "scene/render_tone_map.h"
#include "util/scene_error.h"

namespace lenslab {
namespace {

ToneMap log_map(double stops = 8) { return {0, true, stops}; }

TEST(ToneMap, ClipScalesByTheExposureAndStopsAtWhite) {
    const PixelRgb p = ToneMap{1.0}.apply({0.25f, 0.7f, -1.0f});
    EXPECT_FLOAT_EQ(p.r, 0.5f);  // 2^1 * 0.25
    EXPECT_FLOAT_EQ(p.g, 1.0f);
    EXPECT_FLOAT_EQ(p.b, 0.0f);
}

TEST(ToneMap, LogLeavesEverythingBelowTheKneeAsClipShowsIt) {
    const PixelRgb dim{0.3f, 0.5f, 0.2f};  // brightest channel at the knee
    const PixelRgb a = log_map().apply(dim), b = ToneMap{}.apply(dim);
    EXPECT_FLOAT_EQ(a.r, b.r);
    EXPECT_FLOAT_EQ(a.g, b.g);
    EXPECT_FLOAT_EQ(a.b, b.b);
}

TEST(ToneMap, LogReachesWhiteTheGivenStopsAboveTheKnee) {
    // Grey at knee * 2^stops is white; half as many stops above the knee, halfway to white.
    for (double stops : {4.0, 8.0, 12.0}) {
        const float white = float(kToneMapKnee * std::exp2(stops));
        EXPECT_NEAR(log_map(stops).apply({white, white, white}).g, 1.0, 1e-6);
        EXPECT_NEAR(log_map(stops).apply({4 * white, 4 * white, 4 * white}).g, 1.0, 1e-6);
        const float half = float(kToneMapKnee * std::exp2(stops / 2));
        EXPECT_NEAR(log_map(stops).apply({half, half, half}).g, 0.75, 1e-6);
    }
}

TEST(ToneMap, LogKeepsABrightPixelsColourAndOrder) {
    // A red highlight 60x the knee: its channels keep their ratios (no white-out).
    const PixelRgb bright{30.0f, 6.0f, 3.0f};
    const PixelRgb shown = log_map().apply(bright);
    EXPECT_LT(shown.r, 1.0f);
    EXPECT_NEAR(shown.r / shown.g, 5.0, 1e-5);
    EXPECT_NEAR(shown.g / shown.b, 2.0, 1e-5);
    // A rim 3.5 times brighter than the disc inside it (the lens caustic of
    // docs/performance.md) stays brighter once shown, where clip makes both white.
    const float inside = 25.0f, rim = 3.5f * inside;
    EXPECT_GT(log_map().apply({rim, rim, rim}).g - log_map().apply({inside, inside, inside}).g,
              0.1);
    EXPECT_EQ(ToneMap{}.apply({rim, rim, rim}).g, ToneMap{}.apply({inside, inside, inside}).g);
}

TEST(ToneMap, ComesFromTheRenderBlock) {
    const RenderSettings s =
        read_render_settings(nlohmann::json::parse(R"({"tone_map": "log", "highlight_stops": 6})"));
    const ToneMap t = tone_map_for(s, -1);
    EXPECT_TRUE(t.log_highlights);
    EXPECT_EQ(t.highlight_stops, 6);
    EXPECT_EQ(t.exposure_stops, -1);
    EXPECT_FALSE(tone_map_for(RenderSettings{}).log_highlights);
    EXPECT_THROW(read_render_settings(nlohmann::json::parse(R"({"tone_map": "filmic"})")),
                 SceneError);
    EXPECT_THROW(read_render_settings(nlohmann::json::parse(R"({"highlight_stops": 0.5})")),
                 SceneError);
}

TEST(ToneMap, PngPixelsGoThroughIt) {
    Film f(1, 1);
    f.set(0, 0, {100, 100, 100});
    EXPECT_EQ(to_srgb8(f).rgb[0], 255);
    const Image8 shown = to_srgb8(f, log_map());  // 100 = 0.5 * 2^7.64: 0.977 linear
    EXPECT_NEAR(shown.rgb[0], std::lround(255 * linear_to_srgb(0.5 + 0.5 * std::log2(200.0) / 8)),
                0);
}

}  // namespace
}  // namespace lenslab
