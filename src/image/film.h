#pragma once
// Linear, float, RGB pixel storage: the image before tone mapping.

#include <limits>
#include <vector>

#include "optics/rgb.h"
#include "util/huge_pages.h"

namespace lenslab {

struct PixelRgb {
    float r = 0, g = 0, b = 0;
};

// Relative luminance of linear sRGB (Rec. 709 weights).
inline double luminance(const PixelRgb& p) { return 0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b; }

class Film {
public:
    Film() = default;
    // The pixels are advised onto huge pages before they are zeroed: a 900 x 900 film is
    // 2,400 small pages, and their first-touch faults (microseconds each in a virtual machine)
    // took 30 ms on one thread before a render could start.
    Film(int width, int height) : m_width(width), m_height(height) {
        const size_t count = size_t(width) * size_t(height);
        m_pixels.reserve(count);
        advise_huge_pages(m_pixels.data(), count * sizeof(PixelRgb));
        m_pixels.resize(count);
    }

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
