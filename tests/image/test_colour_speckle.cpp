// The colour-speckle index (image/colour_speckle.h) against values worked out by hand from its
// definition: each pixel's chroma (R - G, G - B) against its 5 x 5 neighbourhood's mean.

#include <gtest/gtest.h>

#include <random>

#include "image/colour_speckle.h"

namespace lenslab {
namespace {

Image8 filled(int w, int h, unsigned char r, unsigned char g, unsigned char b) {
    Image8 img{w, h, {}};
    for (int i = 0; i < w * h; ++i) img.rgb.insert(img.rgb.end(), {r, g, b});
    return img;
}

void set_pixel(Image8& img, int x, int y, unsigned char r, unsigned char g, unsigned char b) {
    unsigned char* p = &img.rgb[(static_cast<size_t>(y) * img.width + x) * 3];
    p[0] = r;
    p[1] = g;
    p[2] = b;
}

TEST(ColourSpeckle, AnEvenColourScoresNothing) {
    EXPECT_NEAR(colour_speckle(filled(30, 20, 200, 40, 90), {15, 10, 8}), 0.0, 1e-12);
}

TEST(ColourSpeckle, GreyNoiseIsNotColourNoise) {
    Image8 img = filled(40, 40, 0, 0, 0);
    std::mt19937 rng(3);
    for (int y = 0; y < 40; ++y) {
        for (int x = 0; x < 40; ++x) {
            const auto v = static_cast<unsigned char>(rng() % 256);
            set_pixel(img, x, y, v, v, v);
        }
    }
    EXPECT_EQ(colour_speckle(img, {20, 20, 15}), 0.0);
}

// Columns of pure red (chroma (1, 0)) and pure green ((-1, 1)) in turn: a red pixel's window
// holds 3 red and 2 green columns, mean (0.2, 0.4), so |1 - 0.2| + |0 - 0.4| = 1.2; a green
// one's 3 green and 2 red, mean (-0.2, 0.6), |-1 + 0.2| + |1 - 0.6| = 1.2.
TEST(ColourSpeckle, AlternatingRedAndGreenColumnsScoreOnePointTwo) {
    Image8 img = filled(40, 40, 0, 0, 0);
    for (int y = 0; y < 40; ++y) {
        for (int x = 0; x < 40; ++x) {
            if (x % 2 == 0) {
                set_pixel(img, x, y, 255, 0, 0);
            } else {
                set_pixel(img, x, y, 0, 255, 0);
            }
        }
    }
    EXPECT_NEAR(colour_speckle(img, {20, 20, 10}), 1.2, 1e-12);
}

// One red pixel on grey: alone it scores |1 - 1/25| = 0.96; its 8 neighbours each see it in
// their window, 1/25 = 0.04 each; the 3 x 3 disc (radius 1.5) averages (0.96 + 8 x 0.04) / 9.
// At the picture's corner its window repeats it: the corner pixel's 5 x 5 window holds it 9
// times (rows and columns -2, -1, 0 all clamp to 0), so 1 - 9/25 = 0.64.
TEST(ColourSpeckle, OneRedPixelOnGrey) {
    Image8 img = filled(21, 21, 128, 128, 128);
    set_pixel(img, 10, 10, 255, 0, 0);
    EXPECT_NEAR(colour_speckle(img, {10, 10, 0}), 0.96, 1e-12);
    EXPECT_NEAR(colour_speckle(img, {10, 10, 1.5}), (0.96 + 8 * 0.04) / 9, 1e-12);
    Image8 corner = filled(21, 21, 128, 128, 128);
    set_pixel(corner, 0, 0, 255, 0, 0);
    EXPECT_NEAR(colour_speckle(corner, {0, 0, 0}), 1 - 9.0 / 25, 1e-12);
}

TEST(ColourSpeckle, ADiscOutsideThePictureHoldsNoPixels) {
    EXPECT_EQ(colour_speckle(filled(10, 10, 255, 0, 0), {100, 100, 5}), 0.0);
}

}  // namespace
}  // namespace lenslab
