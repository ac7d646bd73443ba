#pragma once
// Linear, float, RGB pixel storage: the image before tone mapping.

#include <vector>

#include "optics/rgb.h"

namespace lenslab {

struct PixelRgb {
    float r = 0, g = 0, b = 0;
};

class Film {
public:
    Film() = default;
    Film(int width, int height) : m_width(width), m_height(height), m_pixels(size_t(width) * height) {}

    int width() const { return m_width; }
    int height() const { return m_height; }
    PixelRgb& at(int x, int y) { return m_pixels[size_t(y) * m_width + x]; }
    const PixelRgb& at(int x, int y) const { return m_pixels[size_t(y) * m_width + x]; }
    void set(int x, int y, const Rgb& c) {
        at(x, y) = {static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b)};
    }
    const std::vector<PixelRgb>& pixels() const { return m_pixels; }

private:
    int m_width = 0, m_height = 0;
    std::vector<PixelRgb> m_pixels;
};

}  // namespace lenslab
