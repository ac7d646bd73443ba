#pragma once
// Linear, float, RGB pixel storage: the image before tone mapping.

#include <limits>
#include <vector>

#include "optics/rgb.h"

namespace lenslab {

struct PixelRgb {
    float r = 0, g = 0, b = 0;
};

// Relative luminance of linear sRGB (Rec. 709 weights).
inline double luminance(const PixelRgb& p) { return 0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b; }

class Film {
public:
    Film() = default;
    Film(int width, int height)
        : m_width(width), m_height(height), m_pixels(size_t(width) * height) {}

    int width() const { return m_width; }
    int height() const { return m_height; }
    PixelRgb& at(int x, int y) { return m_pixels[size_t(y) * m_width + x]; }
    const PixelRgb& at(int x, int y) const { return m_pixels[size_t(y) * m_width + x]; }
    // Stores a linear value, clamped to what a float holds: no Inf or NaN in a pixel.
    void set(int x, int y, const Rgb& c) {
        at(x, y) = {to_float(c.r), to_float(c.g), to_float(c.b)};
    }
    const std::vector<PixelRgb>& pixels() const { return m_pixels; }

private:
    static float to_float(double v) {
        if (!(v > 0.0)) return 0.0f;  // negative and NaN
        return v < std::numeric_limits<float>::max() ? static_cast<float>(v)
                                                     : std::numeric_limits<float>::max();
    }

    int m_width = 0, m_height = 0;
    std::vector<PixelRgb> m_pixels;
};

}  // namespace lenslab
