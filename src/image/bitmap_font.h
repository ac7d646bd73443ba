#pragma once
// A small built-in 5x7 pixel font (8 rows with descenders) (printable ASCII) for labelling images
// the program draws itself (detector maps and their colour bars), so no font files or libraries are
// needed.

#include <string>

#include "image/image_io.h"

namespace lenslab {

inline constexpr int kGlyphWidth = 5, kGlyphHeight = 8;  // row 7: descenders
// Pixels from one character's left edge to the next's, at scale 1.
inline constexpr int kGlyphAdvance = kGlyphWidth + 1;

// True where glyph `c` has ink at column x, row y (row 0 at the top). Characters outside
// printable ASCII draw as '?'.
bool glyph_pixel(char c, int x, int y);

// Width in pixels of `text` drawn at `scale`.
int text_width(const std::string& text, int scale = 1);

// Draws `text` with its top-left corner at (x, y), each font pixel a scale x scale block;
// whatever falls outside the image is clipped.
void draw_text(Image8& image, int x, int y, const std::string& text, const unsigned char (&rgb)[3],
               int scale = 1);

}  // namespace lenslab
