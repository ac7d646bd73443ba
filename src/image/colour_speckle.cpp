#include "image/colour_speckle.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lenslab {

namespace {

// The pixel's chroma, its coordinates clamped into the picture.
std::array<double, 2> clamped_chroma(const Image8& image, int x, int y) {
    x = std::clamp(x, 0, image.width - 1);
    y = std::clamp(y, 0, image.height - 1);
    const unsigned char* p = &image.rgb[(static_cast<size_t>(y) * image.width + x) * 3];
    return {(p[0] - p[1]) / 255.0, (p[1] - p[2]) / 255.0};
}

}  // namespace

double colour_speckle(const Image8& image, const PixelDisc& disc) {
    if (image.width <= 0 || image.height <= 0) return 0;
    constexpr int kHalf = 2;  // the 5 x 5 neighbourhood
    const int x0 = std::max(0, static_cast<int>(std::floor(disc.cx - disc.radius)));
    const int x1 = std::min(image.width - 1, static_cast<int>(std::ceil(disc.cx + disc.radius)));
    const int y0 = std::max(0, static_cast<int>(std::floor(disc.cy - disc.radius)));
    const int y1 = std::min(image.height - 1, static_cast<int>(std::ceil(disc.cy + disc.radius)));
    double sum = 0;
    long count = 0;
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const double dx = x - disc.cx, dy = y - disc.cy;
            if (dx * dx + dy * dy > disc.radius * disc.radius) continue;
            double mean[2] = {0, 0};
            for (int j = -kHalf; j <= kHalf; ++j) {
                for (int i = -kHalf; i <= kHalf; ++i) {
                    const std::array<double, 2> c = clamped_chroma(image, x + i, y + j);
                    mean[0] += c[0];
                    mean[1] += c[1];
                }
            }
            const double n = (2 * kHalf + 1) * (2 * kHalf + 1);
            const std::array<double, 2> c = clamped_chroma(image, x, y);
            sum += std::abs(c[0] - mean[0] / n) + std::abs(c[1] - mean[1] / n);
            ++count;
        }
    }
    return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

}  // namespace lenslab
