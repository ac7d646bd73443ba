// The built-in 5x7 font: every printable character has its own glyph, text is drawn where
// asked and clipped at the image's edges.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "image/bitmap_font.h"

namespace lenslab {
namespace {

std::string bits_of(char c) {
    std::string s;
    for (int y = 0; y < kGlyphHeight; ++y) {
        for (int x = 0; x < kGlyphWidth; ++x) s += glyph_pixel(c, x, y) ? '#' : '.';
    }
    return s;
}

TEST(BitmapFont, EveryPrintableCharacterHasItsOwnGlyph) {
    std::set<std::string> seen;
    for (char c = 33; c < 127; ++c) {
        const std::string bits = bits_of(c);
        EXPECT_NE(bits.find('#'), std::string::npos) << c;
        EXPECT_TRUE(seen.insert(bits).second) << "'" << c << "' looks like another character";
    }
    EXPECT_EQ(bits_of(' ').find('#'), std::string::npos);
    EXPECT_EQ(bits_of('\x01'), bits_of('?'));
}

TEST(BitmapFont, DrawsScaledTextAndClips) {
    Image8 img{40, 20, std::vector<unsigned char>(40 * 20 * 3, 255)};
    const unsigned char black[3] = {0, 0, 0};
    EXPECT_EQ(text_width("11", 2), (2 * kGlyphAdvance - 1) * 2);
    draw_text(img, 1, 2, "1", black, 2);
    // '1' has ink at its top row, column 2 -> pixels (1 + 4, 2) and (1 + 5, 3).
    auto at = [&](int x, int y) { return img.rgb[(static_cast<size_t>(y) * img.width + x) * 3]; };
    EXPECT_EQ(at(5, 2), 0);
    EXPECT_EQ(at(6, 3), 0);
    EXPECT_EQ(at(1, 2), 255);
    draw_text(img, 35, 15, "WWW", black, 3);  // mostly outside: must not write out of bounds
    EXPECT_EQ(at(35, 15), 0);
}

}  // namespace
}  // namespace lenslab
