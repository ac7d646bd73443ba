#include "analysis/figures/map_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "image/bitmap_font.h"

namespace lenslab {

namespace {

constexpr unsigned char kMapInk[3] = {20, 20, 20};
constexpr unsigned char kNoValue[3] = {205, 205, 205};
constexpr int kMapMargin = 16, kMapGap = 14, kMapBarWidth = 22, kMapLine = 12;

std::string map_number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return text;
}

}  // namespace

Image8 map_figure_image(const MapFigure& figure, int panel_pixels) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const MapPanel& p : figure.panels) {
        if (p.values.size() != static_cast<size_t>(p.width) * p.height || p.width < 1)
            throw std::invalid_argument("a map panel's values do not fill it");
        for (double v : p.values)
            if (std::isfinite(v)) low = std::min(low, v), high = std::max(high, v);
    }
    if (!(high >= low)) low = 0, high = 1;  // nothing to show
    low = figure.low.value_or(low);
    high = figure.high.value_or(high);
    const bool log = figure.scale == ColourScale::Log;
    if (!(high > low)) high = low + 1;
    // Where on the bar (0 bottom, 1 top) a value lies.
    const auto position = [&](double v) {
        if (!log) return (v - low) / (high - low);
        return v > 0 ? 1.0 + std::log10(v / high) / kLogDecades : 0.0;
    };
    const int tick_count = log ? kLogDecades + 1 : 5;
    std::vector<std::string> ticks;
    for (int i = 0; i < tick_count; ++i) {
        const double f = static_cast<double>(i) / (tick_count - 1);
        ticks.push_back(map_number(log ? high * std::pow(10.0, -kLogDecades * (1 - f))
                                       : low + f * (high - low)));
    }
    int tick_width = 0;
    for (const std::string& t : ticks) tick_width = std::max(tick_width, text_width(t));

    int panels_height = 0;
    std::vector<int> heights;
    for (const MapPanel& p : figure.panels) {
        heights.push_back(std::max(
            1,
            static_cast<int>(std::lround(panel_pixels * static_cast<double>(p.height) / p.width))));
        panels_height = std::max(panels_height, heights.back());
    }
    const int count = static_cast<int>(figure.panels.size());
    const int map_y = kMapMargin + 2 * kMapLine + 10;
    const int bar_x = kMapMargin + count * (panel_pixels + kMapGap);
    int width = bar_x + kMapBarWidth + 6 + tick_width + kMapMargin;
    width = std::max(width, 2 * kMapMargin + text_width(figure.title, 2));
    for (const std::string& f : figure.footer)
        width = std::max(width, 2 * kMapMargin + text_width(f));
    const int label_y = map_y + panels_height + 6;
    const int height =
        label_y + kMapLine + 6 + static_cast<int>(figure.footer.size()) * kMapLine + kMapMargin;
    Image8 image{width, height,
                 std::vector<unsigned char>(static_cast<size_t>(width) * height * 3, 255)};
    draw_text(image, kMapMargin, kMapMargin, figure.title, kMapInk, 2);

    unsigned char c[3];
    for (int n = 0; n < count; ++n) {
        const MapPanel& p = figure.panels[static_cast<size_t>(n)];
        const int x0 = kMapMargin + n * (panel_pixels + kMapGap),
                  h = heights[static_cast<size_t>(n)];
        for (int y = 0; y < h; ++y) {
            const int row = std::min(p.height - 1, y * p.height / h);
            for (int x = 0; x < panel_pixels; ++x) {
                const int column = std::min(p.width - 1, x * p.width / panel_pixels);
                const double v = p.values[static_cast<size_t>(row) * p.width + column];
                if (!std::isfinite(v)) {
                    fill_rect(image, x0 + x, map_y + y, x0 + x + 1, map_y + y + 1, kNoValue);
                    continue;
                }
                inferno_rgb8(position(v), c);
                fill_rect(image, x0 + x, map_y + y, x0 + x + 1, map_y + y + 1, c);
            }
        }
        draw_text(image, x0, label_y, p.label, kMapInk);
    }
    // The colour bar: the range's bottom at the bottom, labelled ticks.
    for (int y = 0; y < panels_height; ++y) {
        inferno_rgb8(1.0 - (y + 0.5) / panels_height, c);
        fill_rect(image, bar_x, map_y + y, bar_x + kMapBarWidth, map_y + y + 1, c);
    }
    for (int i = 0; i < tick_count; ++i) {
        const double f = static_cast<double>(i) / (tick_count - 1);
        const int y = map_y + static_cast<int>(std::lround((panels_height - 1) * (1.0 - f)));
        fill_rect(image, bar_x + kMapBarWidth, y, bar_x + kMapBarWidth + 4, y + 1, kMapInk);
        draw_text(image, bar_x + kMapBarWidth + 6,
                  std::clamp(y - 3, map_y - 3, map_y + panels_height - 4),
                  ticks[static_cast<size_t>(i)], kMapInk);
    }
    draw_text(image, bar_x, map_y - kMapLine, figure.unit, kMapInk);
    int y = label_y + kMapLine + 6;
    for (const std::string& f : figure.footer) {
        draw_text(image, kMapMargin, y, f, kMapInk);
        y += kMapLine;
    }
    return image;
}

}  // namespace lenslab
