#include "analysis/section/section_rays.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/section/section_outline.h"
#include "geometry/lens/lens_solid.h"

namespace lenslab {

namespace {

// `count` rays around `centre` in the plane, leaving a circle of `radius` (the section of
// an emitting sphere, so they do not start inside it).
void add_section_fan(const Vec3& centre, double radius, int count, const SectionPlane& plane,
                     std::vector<Ray>& out) {
    for (int i = 0; i < count; ++i) {
        const double angle = 2 * std::numbers::pi * (i + 0.5) / count;
        const Vec3 d = plane.u * std::cos(angle) + plane.v * std::sin(angle);
        out.push_back({centre + d * radius, d});
    }
}

// `count` rays from `apex` within `half_angle` (radians) of `axis`, which lies in the plane:
// a spot light's cone cut by the plane.
void add_section_cone(const Vec3& apex, const Vec3& axis, double half_angle, int count,
                      const SectionPlane& plane, std::vector<Ray>& out) {
    const Vec3 across = normalize(cross(plane.normal(), axis));
    for (int i = 0; i < count; ++i) {
        const double angle = half_angle * (2.0 * (i + 0.5) / count - 1.0);
        out.push_back({apex, axis * std::cos(angle) + across * std::sin(angle)});
    }
}

void add_section_beam(const SectionBeam& beam, const SectionPlane& plane, std::vector<Ray>& out) {
    const Vec3 across = normalize(cross(plane.normal(), beam.direction));
    for (int i = 0; i < beam.rays; ++i) {
        const double s = beam.rays > 1 ? beam.width * (double(i) / (beam.rays - 1) - 0.5) : 0.0;
        out.push_back({beam.origin + across * s, beam.direction});
    }
}

bool direction_in_section_plane(const Vec3& direction, const SectionPlane& plane) {
    return std::abs(dot(direction, plane.normal())) < 1e-9;
}

class PathFlattener {
public:
    PathFlattener(double wavelength_nm, double escape_length, std::vector<SectionRayPath>& out)
        : m_wavelength(wavelength_nm), m_escape(escape_length), m_out(out) {}

    void start(const RayTreeNode& root) {
        m_out.push_back({{root.from}, m_wavelength, root.weight, false});
        follow(root, m_out.size() - 1);
    }

private:
    // `node`'s outgoing ray is the end of path `path`; its children say where it went.
    void follow(const RayTreeNode& node, size_t path) {
        if (node.children.empty()) return;
        const RayTreeNode& first = node.children.front();
        const Vec3 end = node.to.value_or(node.from);
        const Vec3 hit = first.to ? *first.to : end + node.direction * m_escape;
        m_out[path].points.push_back(hit);
        const RayTreeNode* strongest = nullptr;
        for (const RayTreeNode& c : node.children) {
            if (continues(c) && (!strongest || c.weight > strongest->weight)) strongest = &c;
        }
        for (const RayTreeNode& c : node.children) {
            if (!continues(c)) continue;
            size_t branch = path;
            if (&c != strongest) {
                m_out.push_back({{hit}, m_wavelength, c.weight, false});
                branch = m_out.size() - 1;
            }
            if (c.event == Event::Tir) m_out[branch].tir = true;
            follow(c, branch);
        }
    }

    static bool continues(const RayTreeNode& n) {
        return n.event == Event::Refract || n.event == Event::Reflect || n.event == Event::Tir;
    }

    double m_wavelength, m_escape;
    std::vector<SectionRayPath>& m_out;
};

}  // namespace

std::vector<Ray> section_start_rays(const Scene& scene, const SectionPlane& plane,
                                    const SectionRayOptions& options) {
    std::vector<Ray> rays;
    if (options.beam) add_section_beam(*options.beam, plane, rays);
    const int fan = options.rays_per_light;
    if (fan <= 0) return rays;
    for (const PointLight& light : scene.point_lights) {
        if (std::abs(plane.distance(light.position)) < 1e-9)
            add_section_fan(light.position, 0.0, fan, plane, rays);
    }
    for (const SpotLight& light : scene.spots) {
        if (std::abs(plane.distance(light.position)) < 1e-9 &&
            direction_in_section_plane(light.direction, plane)) {
            add_section_cone(light.position, light.direction,
                             light.cone_angle * std::numbers::pi / 180, fan, plane, rays);
        }
    }
    for (const BeamLight& light : scene.beams) {
        const double d = plane.distance(light.origin);
        if (!direction_in_section_plane(light.direction, plane) || std::abs(d) >= light.radius)
            continue;
        const Vec3 centre = light.origin - plane.normal() * d;
        if (light.fan_angle > 0) {
            // A fan shows as the rays of its sheet when the sheet lies in the plane.
            if (direction_in_section_plane(light.fan_axis, plane)) {
                add_section_cone(centre, light.direction, light.fan_angle * std::numbers::pi / 360,
                                 fan, plane, rays);
            }
            continue;
        }
        // The disc's chord in the plane, cut to the slit's strip where there is one.
        const Vec3 across = normalize(cross(plane.normal(), light.direction));
        const double half = std::sqrt(light.radius * light.radius - d * d);
        double s0 = -half, s1 = half;
        if (light.slit_width > 0) {
            const Vec3 slit_across = normalize(cross(light.direction, light.slit_axis));
            const double at = dot(centre - light.origin, slit_across);
            const double rate = dot(across, slit_across), h = 0.5 * light.slit_width;
            if (std::abs(rate) < 1e-12) {
                if (std::abs(at) > h) continue;
            } else {
                const double a = (-h - at) / rate, b = (h - at) / rate;
                s0 = std::max(s0, std::min(a, b));
                s1 = std::min(s1, std::max(a, b));
            }
            if (!(s1 > s0)) continue;
        }
        add_section_beam({centre + across * (0.5 * (s0 + s1)), light.direction, s1 - s0, fan},
                         plane, rays);
    }
    for (const SphereEmitter& e : scene.emitters()) {
        const double d = plane.distance(e.sphere->centre());
        const double r = e.sphere->radius();
        if (std::abs(d) >= r) continue;
        // Just outside the sphere's section, so the rays leave the lamp rather than hit it.
        add_section_fan(e.sphere->centre() - plane.normal() * d,
                        std::sqrt(r * r - d * d) * (1 + 1e-6), fan, plane, rays);
    }
    return rays;
}

void append_ray_paths(const RayTree& tree, double wavelength_nm, double escape_length,
                      std::vector<SectionRayPath>& out) {
    const size_t first = out.size();
    PathFlattener(wavelength_nm, escape_length, out).start(tree.root);
    // A branch dropped at once (below the weight limit) leaves a single point.
    const auto single = std::remove_if(out.begin() + std::ptrdiff_t(first), out.end(),
                                       [](const SectionRayPath& p) { return p.points.size() < 2; });
    out.erase(single, out.end());
}

std::optional<SectionBeam> default_section_beam(const Scene& scene, int object,
                                                const SectionPlane& plane, int rays) {
    if (object < 0 || object >= int(scene.objects.size())) return std::nullopt;
    const auto* lens = dynamic_cast<const LensSolid*>(scene.objects[object].shape.get());
    // A lens cut across its axis gets the beam of any other object.
    if (lens && std::abs(dot(lens->prescription().axis, plane.normal())) > 1e-9) lens = nullptr;
    if (!lens) {
        double a0 = INFINITY, a1 = -INFINITY, b0 = INFINITY, b1 = -INFINITY;
        for (const SectionCurve& c : section_outline(*scene.objects[object].shape, plane)) {
            for (const DiagramPoint& p : c.points) {
                a0 = std::min(a0, p.z), a1 = std::max(a1, p.z);
                b0 = std::min(b0, p.y), b1 = std::max(b1, p.y);
            }
        }
        if (a0 > a1) return std::nullopt;
        const double size = std::max(a1 - a0, b1 - b0);
        return SectionBeam{plane.at(a0 - size, 0.5 * (b0 + b1)), plane.u, 0.8 * (b1 - b0), rays};
    }
    const LensPrescription& p = lens->prescription();
    Vec3 direction = p.axis;
    std::optional<Vec3> light;
    if (!scene.emitters().empty()) light = scene.emitters().front().sphere->centre();
    if (!light && !scene.point_lights.empty()) light = scene.point_lights.front().position;
    if (light && dot(*light - p.centre, direction) > 0) direction = -direction;
    const double distance = p.thickness + 1.0 * p.diameter;
    return SectionBeam{p.centre - direction * distance, direction, 0.8 * p.diameter, rays};
}

}  // namespace lenslab
