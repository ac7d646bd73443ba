#include "analysis/section/section_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "optics/spectrum.h"
#include "util/format_number.h"

namespace lenslab {

namespace {

constexpr DiagramColour kSectionMirror{150, 150, 160};
constexpr DiagramColour kSectionLamp{255, 200, 40};
constexpr DiagramColour kSectionSelected{255, 140, 0};

DiagramColour section_rgb_colour(const Rgb& c) {
    const auto channel = [](double v) { return int(std::lround(255 * std::clamp(v, 0.0, 1.0))); };
    return {channel(c.r), channel(c.g), channel(c.b)};
}

// Edge and fill of an object's cross-section, by what its material does to light.
void section_material_style(const Material& m, DiagramPath& path) {
    if (m.emission_intensity > 0) {
        path.fill = kSectionLamp;
        path.stroke = {180, 120, 0};
    } else if (m.transparency > 0) {
        path.fill = kDiagramGlassFill;
        path.stroke = kDiagramGlassEdge;
        path.fill_opacity = 0.6;
    } else if (m.specular > 0) {
        path.fill = kSectionMirror;
        path.stroke = {60, 60, 70};
    } else {
        path.fill = section_rgb_colour(m.color);
        path.stroke = {60, 60, 60};
    }
}

// A 1, 2 or 5 times a power of ten near a fifth of `extent`.
double section_scale_bar_length(double extent) { return diagram_round_length(extent / 5); }

// Whether some transparent material's index differs across the visible lines; if none
// does, every wavelength takes the same paths.
bool section_scene_disperses(const Scene& scene) {
    for (const Material& m : scene.materials) {
        if (m.transparency > 0 && m.ior(kLineF) != m.ior(kLineC)) return true;
    }
    return false;
}

// A colour of brightest channel 1 on the white page: brightest channel 0.8 after an
// sRGB-like curve.
DiagramColour section_on_white(const Rgb& c) {
    const auto encode = [](double v) { return 0.8 * std::pow(std::max(v, 0.0), 1 / 2.2); };
    return section_rgb_colour({encode(c.r), encode(c.g), encode(c.b)});
}

// A ray's colour on the white page: a wavelength's or a coloured light's own hue, brightest
// channel 0.8 after the sRGB-like curve; white light (a neutral colour) dark grey.
DiagramColour section_ray_colour(const SectionRayPath& r) {
    const Rgb& c = r.colour;
    const double low = std::min({c.r, c.g, c.b});
    if (r.whole_spectrum && low > 0.85) return {90, 90, 90};
    return section_on_white(c);
}

std::string section_legend_label(const SectionRayPath& r) {
    if (!r.whole_spectrum) return printf_text("%.1f nm", r.wavelength_nm);
    return std::min({r.colour.r, r.colour.g, r.colour.b}) > 0.85 ? "white light"
                                                                 : "the light's colour";
}

}  // namespace

DiagramColour wavelength_colour(double nm) {
    // The ray diagram's colours for its three lines, so the two views agree.
    const std::pair<double, DiagramColour> lines[] = {
        {kLineF, kDiagramBlueF}, {kLineD, kDiagramYellowGreenD}, {kLineC, kDiagramRedC}};
    for (const auto& [line, colour] : lines) {
        if (std::abs(nm - line) < 1e-3) return colour;
    }
    return section_on_white(wavelength_rgb(nm));
}

SectionView make_section_view(const Scene& scene, const SectionPlane& plane,
                              const SectionViewOptions& options) {
    SectionView view;
    view.plane = plane;
    double a0 = INFINITY, a1 = -INFINITY, b0 = INFINITY, b1 = -INFINITY;
    const auto extend = [&](const DiagramPoint& p) {
        a0 = std::min(a0, p.z);
        a1 = std::max(a1, p.z);
        b0 = std::min(b0, p.y);
        b1 = std::max(b1, p.y);
    };
    for (int i = 0; i < int(scene.objects.size()); ++i) {
        SectionObject object{i, section_outline(*scene.objects[i].shape, plane, options.outline)};
        if (object.curves.empty()) continue;
        for (const SectionCurve& c : object.curves) {
            for (const DiagramPoint& p : c.points) extend(p);
        }
        view.objects.push_back(std::move(object));
    }
    const std::vector<SectionSource> sources = section_sources(scene, plane, options.rays);
    for (const SectionSource& source : sources) {
        for (const Ray& r : source.rays) extend(plane.of(r.origin));
    }
    if (a0 > a1) a0 = b0 = -1, a1 = b1 = 1;  // nothing in the plane
    const double margin = 0.05 * std::max(a1 - a0, b1 - b0) + 1e-9;
    view.extent = {a0 - margin, a1 + margin, b0 - margin, b1 + margin};

    RayTreeOptions tree;
    tree.max_depth = options.rays.max_depth;
    tree.min_weight = options.rays.min_weight;
    const double reach =
        std::max(options.rays.escape_length, std::hypot(a1 - a0, b1 - b0) + 2 * margin);
    const bool disperses = section_scene_disperses(scene);
    int base = 0;  // the index of the source's first start ray
    for (const SectionSource& source : sources) {
        for (const SectionWavelength& w :
             section_wavelengths(*source.spectrum, options.rays.wavelengths_nm, disperses)) {
            tree.wavelength_nm = w.nm;
            for (size_t i = 0; i < source.rays.size(); ++i) {
                const size_t first = view.rays.size();
                append_ray_paths(trace_ray_tree(scene, source.rays[i], tree), w, reach, view.rays);
                // The tree's first path is the start ray's own (unless dropped at once).
                if (first < view.rays.size() &&
                    length(view.rays[first].points[0] - source.rays[i].origin) == 0.0)
                    view.rays[first].start = base + int(i);
            }
        }
        base += int(source.rays.size());
    }
    return view;
}

std::optional<SectionExtent> section_bounds(const SectionView& view, int object) {
    double a0 = INFINITY, a1 = -INFINITY, b0 = INFINITY, b1 = -INFINITY;
    for (const SectionObject& o : view.objects) {
        if (o.object != object) continue;
        for (const SectionCurve& c : o.curves) {
            for (const DiagramPoint& p : c.points) {
                a0 = std::min(a0, p.z), a1 = std::max(a1, p.z);
                b0 = std::min(b0, p.y), b1 = std::max(b1, p.y);
            }
        }
    }
    if (a0 > a1) return std::nullopt;
    return SectionExtent{a0, a1, b0, b1};
}

SectionExtent focus_extent(const SectionView& view, int object, double room_fraction) {
    const std::optional<SectionExtent> box = section_bounds(view, object);
    const double size = box ? std::max(box->a_max - box->a_min, box->b_max - box->b_min) : 0.0;
    if (!(size > 0)) return view.extent;  // missed by the plane, or cut in a single point
    const double room = room_fraction * size;
    return {box->a_min - room, box->a_max + room, box->b_min - room, box->b_max + room};
}

RayDiagram section_diagram(const Scene& scene, const SectionView& view, int selected) {
    RayDiagram d;
    d.z_min = view.extent.a_min, d.z_max = view.extent.a_max;
    d.y_min = view.extent.b_min, d.y_max = view.extent.b_max;
    d.title = "Section";
    d.subtitle = "rays traced in the plane through every object (reflection, refraction, TIR)";
    const SectionObject* chosen = nullptr;
    for (const SectionObject& o : view.objects) {
        if (o.object == selected) chosen = &o;
        for (const SectionCurve& c : o.curves) {
            DiagramPath path;
            path.points = c.points;
            section_material_style(scene.material_of(o.object), path);
            path.closed = c.closed;
            path.filled = c.closed;
            path.width = c.closed ? 1.2 : 2.0;
            d.paths.push_back(std::move(path));
        }
    }
    for (const SectionRayPath& r : view.rays) {
        DiagramPath path;
        for (const Vec3& p : r.points) path.points.push_back(view.plane.of(p));
        path.stroke = section_ray_colour(r);
        path.width = 1.0;  // a hairline: a thousand rays redraw at 60 frames per second
        path.stroke_opacity = std::clamp(0.15 + 0.85 * r.weight, 0.15, 1.0);
        d.paths.push_back(std::move(path));
    }
    if (chosen) {  // on top, so the selection shows through the rays
        for (const SectionCurve& c : chosen->curves) {
            DiagramPath path;
            path.points = c.points;
            path.closed = c.closed;
            path.stroke = kSectionSelected;
            path.width = 2.5;
            d.paths.push_back(std::move(path));
        }
    }
    for (const SectionRayPath& r : view.rays) {
        const LegendEntry entry{section_ray_colour(r), section_legend_label(r)};
        const auto same = [&](const LegendEntry& e) { return e.text == entry.text; };
        if (std::none_of(d.legend.begin(), d.legend.end(), same)) d.legend.push_back(entry);
    }
    d.scale_bar = section_scale_bar_length(d.z_max - d.z_min);
    d.scale_bar_label = printf_text("%g (scene units)", d.scale_bar);
    return d;
}

}  // namespace lenslab
