#include "image/false_colour.h"

#include <algorithm>
#include <cmath>

#include "image/colormap.h"

namespace lenslab {

void inferno_rgb8(double t, unsigned char (&out)[3]) {
    const Rgb c = inferno(t);
    out[0] = static_cast<unsigned char>(std::lround(255 * c.r));
    out[1] = static_cast<unsigned char>(std::lround(255 * c.g));
    out[2] = static_cast<unsigned char>(std::lround(255 * c.b));
}

void fill_rect(Image8& image, int x0, int y0, int x1, int y1, const unsigned char (&rgb)[3]) {
    for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y) {
        for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x) {
            unsigned char* p = &image.rgb[(static_cast<size_t>(y) * image.width + x) * 3];
            p[0] = rgb[0];
            p[1] = rgb[1];
            p[2] = rgb[2];
        }
    }
}

}  // namespace lenslab
