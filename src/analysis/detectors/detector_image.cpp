#include "analysis/detectors/detector_image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "image/bitmap_font.h"

namespace lenslab {

namespace {

constexpr unsigned char kLegendInk[3] = {20, 20, 20};
constexpr unsigned char kMarker[3] = {0, 220, 255};
constexpr unsigned char kOffSurface[3] = {205, 205, 205};
constexpr int kLegendMargin = 16, kBarWidth = 22, kLine = 12;  // line pitch of the 5x7 font

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

}  // namespace

std::string irradiance_unit(const DetectorMeasurement& m) { return "W/" + m.settings.unit + "^2"; }

Image8 detector_image(const DetectorMeasurement& m, ColourScale scale, int map_size) {
    const DetectorGrid& g = m.grid;
    const double width = g.u_max() - g.u_min(), height = g.v_max() - g.v_min();
    const double px_per_unit = map_size / std::max(width, height);
    const int map_w = std::max(1, static_cast<int>(std::lround(width * px_per_unit)));
    const int map_h = std::max(1, static_cast<int>(std::lround(height * px_per_unit)));
    const std::string unit = m.settings.unit;
    const std::vector<std::string> footer{
        "total " + number(m.total_power) + " W   peak " + number(m.peak_irradiance) + " " +
            irradiance_unit(m),
        "centroid (u, v) = (" + number(m.centroid_u) + ", " + number(m.centroid_v) + ") " + unit +
            "   rms radius " + number(m.rms_radius) + " " + unit,
        "u " + number(g.u_min()) + " to " + number(g.u_max()) + " " + unit + " (right), v " +
            number(g.v_min()) + " to " + number(g.v_max()) + " " + unit +
            " (up); all wavelengths " + number(m.settings.band_edges.front()) + "-" +
            number(m.settings.band_edges.back()) + " nm",
    };
    const bool log = scale == ColourScale::Log;
    const std::string title =
        m.name + ": irradiance (" + irradiance_unit(m) + (log ? ", log scale)" : ")");
    // The colour bar's scale: the peak over cells at least half on the surface, so a
    // sliver of a rim cell cannot set it.
    const double top = m.peak_irradiance > 0 ? m.peak_irradiance : 1.0;
    // Where on the bar (0 bottom, 1 top) an irradiance lies.
    auto position = [&](double e) {
        if (!log) return e / top;
        return e > 0 ? 1.0 + std::log10(e / top) / kLogDecades : 0.0;
    };
    // Ticks: quarters of the peak, or one per decade.
    const int tick_count = log ? kLogDecades + 1 : 5;
    std::vector<std::string> ticks;
    std::vector<double> tick_at;
    for (int i = 0; i < tick_count; ++i) {
        const double f = static_cast<double>(i) / (tick_count - 1);
        ticks.push_back(number(log ? top * std::pow(10.0, -kLogDecades * (1 - f)) : top * f));
        tick_at.push_back(f);
    }
    int tick_w = 0;
    for (const std::string& t : ticks) tick_w = std::max(tick_w, text_width(t));

    const int map_x = kLegendMargin, map_y = kLegendMargin + 2 * kLine + 6;
    const int bar_x = map_x + map_w + 14;
    int img_w = bar_x + kBarWidth + 6 + tick_w + kLegendMargin;
    img_w = std::max(img_w, kLegendMargin + text_width(title, 2) + kLegendMargin);
    for (const std::string& f : footer) img_w = std::max(img_w, 2 * kLegendMargin + text_width(f));
    const int img_h = map_y + map_h + 10 + static_cast<int>(footer.size()) * kLine + kLegendMargin;

    Image8 img{img_w, img_h,
               std::vector<unsigned char>(static_cast<size_t>(img_w) * img_h * 3, 255)};
    draw_text(img, kLegendMargin, kLegendMargin, title, kLegendInk, 2);

    // The map: each pixel shows the cell under its centre; row 0 is the highest v.
    unsigned char c[3];
    for (int y = 0; y < map_h; ++y) {
        const double v = g.v_max() - (y + 0.5) / px_per_unit;
        for (int x = 0; x < map_w; ++x) {
            const double u = g.u_min() + (x + 0.5) / px_per_unit;
            const int cell = g.cell_at(u, v);
            if (g.cell_area(cell) <= 0) {
                fill_rect(img, map_x + x, map_y + y, map_x + x + 1, map_y + y + 1, kOffSurface);
                continue;
            }
            inferno_rgb8(position(m.irradiance(cell)), c);
            fill_rect(img, map_x + x, map_y + y, map_x + x + 1, map_y + y + 1, c);
        }
    }
    if (m.total_power > 0) {  // the centroid: a small cross
        const int cx =
            map_x + static_cast<int>(std::lround((m.centroid_u - g.u_min()) * px_per_unit));
        const int cy =
            map_y + static_cast<int>(std::lround((g.v_max() - m.centroid_v) * px_per_unit));
        fill_rect(img, cx - 6, cy, cx - 2, cy + 1, kMarker);
        fill_rect(img, cx + 3, cy, cx + 7, cy + 1, kMarker);
        fill_rect(img, cx, cy - 6, cx + 1, cy - 2, kMarker);
        fill_rect(img, cx, cy + 3, cx + 1, cy + 7, kMarker);
    }

    // The colour bar, 0 at the bottom, the peak at the top, with five labelled ticks.
    for (int y = 0; y < map_h; ++y) {
        inferno_rgb8(1.0 - (y + 0.5) / map_h, c);
        fill_rect(img, bar_x, map_y + y, bar_x + kBarWidth, map_y + y + 1, c);
    }
    for (int i = 0; i < tick_count; ++i) {
        const int y =
            map_y +
            static_cast<int>(std::lround((map_h - 1) * (1.0 - tick_at[static_cast<size_t>(i)])));
        fill_rect(img, bar_x + kBarWidth, y, bar_x + kBarWidth + 4, y + 1, kLegendInk);
        draw_text(img, bar_x + kBarWidth + 6, std::clamp(y - 3, map_y - 3, map_y + map_h - 4),
                  ticks[static_cast<size_t>(i)], kLegendInk);
    }
    draw_text(img, bar_x, map_y - kLine, irradiance_unit(m), kLegendInk);

    int y = map_y + map_h + 10;
    for (const std::string& f : footer) {
        draw_text(img, kLegendMargin, y, f, kLegendInk);
        y += kLine;
    }
    return img;
}

}  // namespace lenslab
