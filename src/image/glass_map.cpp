#include "image/glass_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "image/bitmap_font.h"
#include "optics/glass_library.h"
#include "optics/glass_search.h"

namespace lenslab {

namespace {

// Labelled where they are on the map: the standard crowns and flints of lens design.
const std::set<std::string>& glass_map_famous() {
    static const std::set<std::string> names = {
        "N-BK7",   "N-SF11",  "F2",           "N-SF6",  "SF5",     "N-FK51A",      "N-BAK4",
        "N-LAK22", "N-SF10",  "N-BAF10",      "N-SK16", "N-LASF9", "N-SF57",       "S-BSL7",
        "H-K9L",   "S-FPL51", "fused-silica", "water",  "PMMA",    "polycarbonate"};
    return names;
}

struct GlassMapColour {
    unsigned char rgb[3];
    const char* css;
};

// One colour per maker, in glass_makers() order, black for the built-in materials.
GlassMapColour glass_map_colour(const Glass& g) {
    static const GlassMapColour palette[] = {
        {{31, 119, 180}, "#1f77b4"},  {{214, 39, 40}, "#d62728"},  {{44, 160, 44}, "#2ca02c"},
        {{148, 103, 189}, "#9467bd"}, {{255, 127, 14}, "#ff7f0e"}, {{23, 190, 207}, "#17becf"},
        {{140, 86, 75}, "#8c564b"},   {{227, 119, 194}, "#e377c2"}};
    if (g.maker.empty()) return {{0, 0, 0}, "#000000"};
    const std::vector<std::string> makers = glass_makers();
    const auto it = std::find(makers.begin(), makers.end(), g.maker);
    const size_t i = it == makers.end() ? makers.size() : size_t(it - makers.begin());
    return palette[i % (sizeof palette / sizeof palette[0])];
}

std::string glass_map_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '&')
            out += "&amp;";
        else if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '"')
            out += "&quot;";
        else
            out += c;
    }
    return out;
}

std::string glass_map_number(double v, int decimals) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, v);
    return text;
}

// Grid steps: V_d every 10, n_d every 0.05 (0.1 over a wide range).
double glass_map_n_step(const GlassMapFrame& f) { return f.n_max - f.n_min > 0.6 ? 0.1 : 0.05; }

// The makers of the glasses shown, in order of first appearance (built-in first).
std::vector<const Glass*> glass_map_legend(const std::vector<const Glass*>& on_map) {
    std::vector<const Glass*> one_each;
    std::set<std::string> seen;
    for (const Glass* g : on_map)
        if (seen.insert(g->maker).second) one_each.push_back(g);
    return one_each;
}

}  // namespace

std::vector<const Glass*> glasses_on_map(const std::vector<const Glass*>& glasses) {
    std::vector<const Glass*> out;
    for (const Glass* g : glasses)
        if (std::isfinite(glass_n_d(*g)) && std::isfinite(glass_v_d(*g))) out.push_back(g);
    return out;
}

GlassMapFrame glass_map_frame(const std::vector<const Glass*>& on_map) {
    GlassMapFrame f;
    if (on_map.empty()) return f;
    double v0 = 1e300, v1 = -1e300, n0 = 1e300, n1 = -1e300;
    for (const Glass* g : on_map) {
        v0 = std::min(v0, glass_v_d(*g));
        v1 = std::max(v1, glass_v_d(*g));
        n0 = std::min(n0, glass_n_d(*g));
        n1 = std::max(n1, glass_n_d(*g));
    }
    f.v_min = std::floor(v0 / 10.0) * 10.0;
    f.v_max = std::max(std::ceil(v1 / 10.0) * 10.0, f.v_min + 10.0);
    if (f.v_max == v1) f.v_max += 10.0;  // no mark on the frame's edge
    if (f.v_min == v0) f.v_min = std::max(0.0, f.v_min - 10.0);
    f.n_min = std::floor(n0 / 0.05) * 0.05;
    f.n_max = std::max(std::ceil(n1 / 0.05) * 0.05, f.n_min + 0.05);
    if (f.n_max == n1) f.n_max += 0.05;
    if (f.n_min == n0) f.n_min -= 0.05;
    return f;
}

std::string glass_map_svg(const std::vector<const Glass*>& glasses) {
    const std::vector<const Glass*> on_map = glasses_on_map(glasses);
    const GlassMapFrame f = glass_map_frame(on_map);
    std::string s;
    s += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(f.width) +
         "\" height=\"" + std::to_string(f.height) + "\" viewBox=\"0 0 " + std::to_string(f.width) +
         " " + std::to_string(f.height) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    // Grid and tick labels.
    for (double v = f.v_min; v <= f.v_max + 1e-9; v += 10.0) {
        const std::string x = glass_map_number(f.x(v), 2);
        s += "<line x1=\"" + x + "\" y1=\"" + glass_map_number(f.top, 2) + "\" x2=\"" + x +
             "\" y2=\"" + glass_map_number(f.bottom, 2) + "\" stroke=\"#ddd\"/>\n";
        s += "<text x=\"" + x + "\" y=\"" + glass_map_number(f.bottom + 16, 2) +
             "\" text-anchor=\"middle\">" + glass_map_number(v, 0) + "</text>\n";
    }
    const double n_step = glass_map_n_step(f);
    for (double n = f.n_min; n <= f.n_max + 1e-9; n += n_step) {
        const std::string y = glass_map_number(f.y(n), 2);
        s += "<line x1=\"" + glass_map_number(f.left, 2) + "\" y1=\"" + y + "\" x2=\"" +
             glass_map_number(f.right, 2) + "\" y2=\"" + y + "\" stroke=\"#ddd\"/>\n";
        s += "<text x=\"" + glass_map_number(f.left - 6, 2) + "\" y=\"" + y +
             "\" text-anchor=\"end\" dominant-baseline=\"middle\">" + glass_map_number(n, 2) +
             "</text>\n";
    }
    s += "<rect x=\"" + glass_map_number(f.left, 2) + "\" y=\"" + glass_map_number(f.top, 2) +
         "\" width=\"" + glass_map_number(f.right - f.left, 2) + "\" height=\"" +
         glass_map_number(f.bottom - f.top, 2) + "\" fill=\"none\" stroke=\"black\"/>\n";
    s += "<text x=\"" + glass_map_number((f.left + f.right) / 2, 2) + "\" y=\"" +
         glass_map_number(f.height - 12, 2) +
         "\" text-anchor=\"middle\">Abbe number V_d (decreasing to the right)</text>\n";
    s += "<text x=\"16\" y=\"" + glass_map_number((f.top + f.bottom) / 2, 2) +
         "\" text-anchor=\"middle\" transform=\"rotate(-90 16 " +
         glass_map_number((f.top + f.bottom) / 2, 2) + ")\">refractive index n_d</text>\n";
    // The glasses, then the labels on top.
    std::set<std::string> labelled;
    std::string labels;
    for (const Glass* g : on_map) {
        const std::string x = glass_map_number(f.x(glass_v_d(*g)), 3);
        const std::string y = glass_map_number(f.y(glass_n_d(*g)), 3);
        const std::string maker = g->maker.empty() ? "builtin" : g->maker;
        s += "<circle class=\"glass\" cx=\"" + x + "\" cy=\"" + y + "\" r=\"3\" fill=\"" +
             glass_map_colour(*g).css + "\" data-name=\"" + glass_map_escape(g->name) +
             "\" data-maker=\"" + glass_map_escape(maker) + "\"><title>" +
             glass_map_escape(glass_label(*g)) + ": n_d " + glass_map_number(glass_n_d(*g), 5) +
             ", V_d " + glass_map_number(glass_v_d(*g), 2) + "</title></circle>\n";
        if (glass_map_famous().count(g->name) && labelled.insert(g->name).second) {
            labels += "<text class=\"label\" x=\"" + glass_map_number(f.x(glass_v_d(*g)) + 5, 2) +
                      "\" y=\"" + glass_map_number(f.y(glass_n_d(*g)) - 5, 2) + "\">" +
                      glass_map_escape(g->name) + "</text>\n";
        }
    }
    s += labels;
    // Legend: one swatch per maker shown.
    double ly = f.top + 14;
    for (const Glass* g : glass_map_legend(on_map)) {
        const std::string lx = glass_map_number(f.right - 90, 2);
        s += "<circle cx=\"" + lx + "\" cy=\"" + glass_map_number(ly, 2) + "\" r=\"4\" fill=\"" +
             glass_map_colour(*g).css + "\"/><text x=\"" + glass_map_number(f.right - 80, 2) +
             "\" y=\"" + glass_map_number(ly, 2) + "\" dominant-baseline=\"middle\">" +
             glass_map_escape(g->maker.empty() ? "built-in" : g->maker) + "</text>\n";
        ly += 16;
    }
    s += "</svg>\n";
    return s;
}

Image8 glass_map_image(const std::vector<const Glass*>& glasses) {
    const std::vector<const Glass*> on_map = glasses_on_map(glasses);
    const GlassMapFrame f = glass_map_frame(on_map);
    Image8 img;
    img.width = f.width;
    img.height = f.height;
    img.rgb.assign(size_t(img.width) * size_t(img.height) * 3, 255);
    auto put = [&](int x, int y, const unsigned char(&c)[3]) {
        if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
        unsigned char* p = &img.rgb[(size_t(y) * size_t(img.width) + size_t(x)) * 3];
        p[0] = c[0];
        p[1] = c[1];
        p[2] = c[2];
    };
    const unsigned char grid[3] = {221, 221, 221}, black[3] = {0, 0, 0};
    const int l = int(f.left), r = int(f.right), t = int(f.top), b = int(f.bottom);
    for (double v = f.v_min; v <= f.v_max + 1e-9; v += 10.0) {
        const int x = int(std::lround(f.x(v)));
        for (int y = t; y <= b; ++y) put(x, y, grid);
        const std::string text = glass_map_number(v, 0);
        draw_text(img, x - text_width(text, 2) / 2, b + 6, text, black, 2);
    }
    for (double n = f.n_min; n <= f.n_max + 1e-9; n += glass_map_n_step(f)) {
        const int y = int(std::lround(f.y(n)));
        for (int x = l; x <= r; ++x) put(x, y, grid);
        const std::string text = glass_map_number(n, 2);
        draw_text(img, l - 6 - text_width(text, 2), y - kGlyphHeight, text, black, 2);
    }
    for (int x = l; x <= r; ++x) put(x, t, black), put(x, b, black);
    for (int y = t; y <= b; ++y) put(l, y, black), put(r, y, black);
    const std::string axis = "V_d (decreasing to the right)";
    draw_text(img, (l + r - text_width(axis, 2)) / 2, f.height - 22, axis, black, 2);
    draw_text(img, 4, 8, "n_d", black, 2);
    for (const Glass* g : on_map) {
        const int cx = int(std::lround(f.x(glass_v_d(*g)))),
                  cy = int(std::lround(f.y(glass_n_d(*g))));
        const GlassMapColour c = glass_map_colour(*g);
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx)
                if (dx * dx + dy * dy <= 5) put(cx + dx, cy + dy, c.rgb);
    }
    std::set<std::string> labelled;
    for (const Glass* g : on_map) {
        if (!glass_map_famous().count(g->name) || !labelled.insert(g->name).second) continue;
        draw_text(img, int(f.x(glass_v_d(*g))) + 5, int(f.y(glass_n_d(*g))) - 12, g->name, black);
    }
    int ly = t + 8;
    for (const Glass* g : glass_map_legend(on_map)) {
        const GlassMapColour c = glass_map_colour(*g);
        for (int dy = -3; dy <= 3; ++dy)
            for (int dx = -3; dx <= 3; ++dx) put(r - 100 + dx, ly + 4 + dy, c.rgb);
        draw_text(img, r - 90, ly, g->maker.empty() ? "built-in" : g->maker, black);
        ly += 14;
    }
    return img;
}

}  // namespace lenslab
