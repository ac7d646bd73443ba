#include "analysis/figures/ray_diagram.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/figures/plot_panel.h"
#include "analysis/system/grin_gap.h"
#include "analysis/system/real_ray.h"

namespace lenslab {

namespace {

constexpr DiagramColour kInk{30, 30, 30};
constexpr DiagramColour kGrey{120, 120, 120};

std::string short_glass(const std::string& glass) {
    const std::string prefix = "constant ";
    return glass.rfind(prefix, 0) == 0 ? glass.substr(prefix.size()) : glass;
}

// The closed outline of one lens in the meridional plane: the entry surface from the bottom
// edge to the top, then the exit surface back down.
DiagramPath lens_outline(const OpticalSystem& system, const SystemElement& e) {
    DiagramPath p;
    const SystemSurface& in = system.surfaces[e.first_surface];
    const SystemSurface& out = system.surfaces[e.last_surface];
    const int n = 64;
    for (int k = -n; k <= n; ++k) {
        const double y = e.semi_diameter * k / n;
        p.points.push_back({in.z_at(std::abs(y)), y});
    }
    for (int k = n; k >= -n; --k) {
        const double y = e.semi_diameter * k / n;
        p.points.push_back({out.z_at(std::abs(y)), y});
    }
    p.closed = true;
    p.filled = true;
    p.fill = kDiagramGlassFill;
    p.fill_opacity = 0.75;
    p.stroke = kDiagramGlassEdge;
    p.width = 1.5;
    return p;
}

// Where to stop drawing a ray that misses `s`: at the lens edge (the cylinder r = the
// semi-diameter) when it is inside the lens's radius and heads out through it, else where
// it passes the surface's vertex plane.
Vec3 clipped_end(const SystemSurface& s, const RealRay& r) {
    const Vec3& p = r.exit_point();
    const Vec3& d = r.direction;
    double t = (s.z - p.z) / d.z;
    const double a = d.x * d.x + d.y * d.y, b = p.x * d.x + p.y * d.y;
    const double c = p.x * p.x + p.y * p.y - s.semi_diameter * s.semi_diameter;
    if (c <= 0 && a > 0) {
        // The larger root of a t^2 + 2 b t + c = 0: c <= 0 puts it at t >= 0.
        t = std::min(t, (-b + std::sqrt(b * b - a * c)) / a);
    }
    return p + d * std::max(0.0, t);
}

// A mirror's profile in the meridional plane, a line on each side of any central hole.
std::vector<DiagramPath> mirror_outline(const SystemSurface& s) {
    std::vector<DiagramPath> out;
    const int n = 48;
    for (double side : {-1.0, 1.0}) {
        DiagramPath p;
        for (int k = 0; k <= n; ++k) {
            const double r =
                s.hole_semi_diameter + (s.semi_diameter - s.hole_semi_diameter) * k / n;
            p.points.push_back({s.z_at(r), side * r});
        }
        p.stroke = kInk;
        p.width = 2.5;
        out.push_back(p);
    }
    return out;
}

// A ray stopped where it left a gradient-index lens through its rim: its path ends there.
bool left_through_grin_rim(const OpticalSystem& system, const RealRay& r) {
    return r.surface > 0 && grin_gap(system, r.surface - 1);
}

}  // namespace

RayDiagram make_ray_diagram(const OpticalSystem& system, const LensReport& report,
                            const RayDiagramOptions& options) {
    RayDiagram d;
    const ParaxialResult& p = report.paraxial;
    const double a_max = system.max_semi_diameter();
    const double last = system.last_vertex();
    double z_far = last;  // the vertex furthest along the axis (a folded system's primary)
    for (const SystemSurface& s : system.surfaces) z_far = std::max(z_far, s.z);
    const double z_start = beam_start_z(system);

    // In view: the lenses, both focal points and the principal planes, with some room past
    // the rear focus for the rays to cross over. Far-off points (a weak lens) are clipped to
    // a few system lengths so the lenses stay visible.
    const double size = system.scale();
    const double reach = 40.0 * size;
    double z_lo = std::max(std::min({z_start, p.z_front_focus, p.z_front_principal,
                                     p.z_rear_principal, p.z_rear_focus}),
                           -reach);
    double z_hi = std::min(
        std::max({z_far, p.z_rear_focus, p.z_front_focus, p.z_front_principal, p.z_rear_principal}),
        z_far + reach);
    if (system.folded()) {
        // A telescope's principal planes and front focus lie far outside it: the view holds
        // the mirrors, the lenses and the image (the points outside it are left out).
        z_lo = std::min(z_start, p.z_rear_focus);
        z_hi = std::max(z_far, p.z_rear_focus);
    }
    const double span = z_hi - z_lo;
    d.z_min = z_lo - 0.04 * span;
    d.z_max = z_hi + 0.12 * span;
    d.y_max = 1.2 * a_max;
    d.y_min = -1.2 * a_max;

    for (size_t i = 0; i < system.elements.size(); ++i) {
        const SystemElement& e = system.elements[i];
        d.paths.push_back(lens_outline(system, e));
        DiagramText t;
        const SystemSurface& in = system.surfaces[e.first_surface];
        const SystemSurface& out = system.surfaces[e.last_surface];
        t.at = {0.5 * (in.z + out.z), -e.semi_diameter};
        t.text = short_glass(e.glass);
        t.colour = kDiagramGlassEdge;
        t.size = 12;
        // Neighbouring lenses (a cemented doublet) are often thinner than their names:
        // alternate the names between two rows.
        t.dy = i % 2 == 0 ? 16 : 30;
        d.labels.push_back(t);
    }

    for (const SystemSurface& s : system.surfaces) {
        if (!s.mirror) continue;
        for (DiagramPath& outline : mirror_outline(s)) d.paths.push_back(outline);
    }

    DiagramPath axis;
    axis.points = {{d.z_min, 0}, {d.z_max, 0}};
    axis.stroke = kGrey;
    axis.width = 1;
    axis.dash = 8;
    d.paths.push_back(axis);

    // A fan of meridional rays in each line; d last so that it is drawn on top.
    const double h = report.aperture_radius;
    const int n = std::max(2, options.rays_per_fan);
    const std::pair<double, DiagramColour> lines[] = {
        {kLineC, kDiagramRedC}, {kLineF, kDiagramBlueF}, {kLineD, kDiagramYellowGreenD}};
    for (const auto& [nm, colour] : lines) {
        for (int k = 0; k < n; ++k) {
            const double y0 = -h + 2.0 * h * k / (n - 1);
            std::vector<Vec3> path;  // curved through gradient-index lenses
            const RealRay r =
                trace_real_ray(system, {{0, y0, z_start}, {0, 0, 1}}, nm, Rims::Clip, &path);
            DiagramPath ray;
            ray.stroke = colour;
            ray.width = 1.1;
            ray.points.push_back({d.z_min, y0});
            for (size_t i = 1; i < path.size(); ++i) ray.points.push_back({path[i].z, path[i].y});
            if (r.fate == RayFate::Passed && r.direction.z * system.image_travel() > 0) {
                // Folded, the rays end at the image, the far end showing the mirrors.
                const double z_end = system.folded() ? p.z_rear_focus : d.z_max;
                const Vec3 end = at_plane(r.exit_point(), r.direction, z_end);
                ray.points.push_back({end.z, end.y});
                // A diverging system's focus is virtual: the rays seem to come from it.
                if (nm == kLineD && !system.folded() && p.z_rear_focus < last) {
                    DiagramPath back;
                    back.stroke = colour;
                    back.width = 0.8;
                    back.dash = 4;
                    const Vec3 start = at_plane(r.exit_point(), r.direction, p.z_rear_focus);
                    back.points = {{r.exit_point().z, r.exit_point().y}, {start.z, start.y}};
                    d.paths.push_back(back);
                }
            } else if (r.fate == RayFate::Missed && !left_through_grin_rim(system, r)) {
                const Vec3 stop = clipped_end(system.surfaces[r.surface], r);
                ray.points.push_back({stop.z, stop.y});
            }
            d.paths.push_back(ray);
        }
    }

    // Principal planes: dashed verticals across the lenses.
    const auto plane = [&](double z, const std::string& name, bool left) {
        if (z < d.z_min || z > d.z_max) return;
        DiagramPath line;
        line.points = {{z, -1.08 * a_max}, {z, 1.08 * a_max}};
        line.stroke = kInk;
        line.width = 1;
        line.dash = 5;
        d.paths.push_back(line);
        DiagramText t;
        t.at = {z, 1.08 * a_max};
        t.text = name;
        t.colour = kInk;
        t.dy = -5;
        // The planes are often close together: write each name on its outer side.
        t.anchor = left ? DiagramText::Anchor::End : DiagramText::Anchor::Start;
        t.dx = left ? -2 : 2;
        d.labels.push_back(t);
    };
    const bool h_first = p.z_front_principal <= p.z_rear_principal;
    plane(p.z_front_principal, "H", h_first);
    plane(p.z_rear_principal, "H'", !h_first);
    // Focal points: dots on the axis, labelled below.
    const auto focus = [&](double z, const std::string& name) {
        if (z < d.z_min || z > d.z_max) return;
        d.dots.push_back({{z, 0}, kInk, 4});
        DiagramText t;
        t.at = {z, 0};
        t.text = name;
        t.colour = kInk;
        t.dy = 20;
        d.labels.push_back(t);
    };
    focus(p.z_front_focus, "F");
    focus(p.z_rear_focus, "F'");

    const std::string unit = options.unit.empty() ? "units" : options.unit;
    d.subtitle = "rays from a point at infinity on the axis";
    d.title =
        "EFL " + printf_text("%.2f", p.efl) + " " + unit + ", BFL " + printf_text("%.2f", p.bfl) +
        " " + unit + " at " + printf_text("%.2f", p.wavelength_nm) + " nm" +
        (fraunhofer_name(p.wavelength_nm).empty() ? ""
                                                  : " (" + fraunhofer_name(p.wavelength_nm) + ")") +
        "; beam diameter " + printf_text("%.2f", 2.0 * h) + " " + unit;
    d.legend = {{kDiagramBlueF, printf_text("%.1f nm (F)", kLineF)},
                {kDiagramYellowGreenD, printf_text("%.1f nm (d)", kLineD)},
                {kDiagramRedC, printf_text("%.1f nm (C)", kLineC)}};
    d.scale_bar = diagram_round_length(0.2 * (d.z_max - d.z_min));
    d.scale_bar_label = printf_text("%g ", d.scale_bar) + unit;
    return d;
}

double diagram_round_length(double target) {
    const double p = std::pow(10.0, std::floor(std::log10(target)));
    for (double m : {5.0, 2.0, 1.0}) {
        if (m * p <= target) return m * p;
    }
    return p;
}

DiagramView fit_diagram(const RayDiagram& d, double width, double height, double margin, double top,
                        double bottom) {
    DiagramView v;
    const double w = std::max(1.0, width - 2.0 * margin);
    const double h = std::max(1.0, height - top - bottom);
    v.scale = std::min(w / (d.z_max - d.z_min), h / (d.y_max - d.y_min));
    // Centre the drawing in the space left over.
    v.left = margin + 0.5 * (w - (d.z_max - d.z_min) * v.scale);
    v.top = top + 0.5 * (h - (d.y_max - d.y_min) * v.scale);
    v.z_min = d.z_min;
    v.y_max = d.y_max;
    return v;
}

}  // namespace lenslab
