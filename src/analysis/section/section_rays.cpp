#include "analysis/section/section_rays.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/section/section_outline.h"

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
    PathFlattener(const SectionWavelength& wavelength, double escape_length,
                  std::vector<SectionRayPath>& out)
        : m_wavelength(wavelength), m_escape(escape_length), m_out(out) {}

    void start(const RayTreeNode& root) {
        m_out.push_back(path_from(root.from, root.weight));
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
        // What the path did at its new point: its own branch, or how it ended there.
        const RayTreeNode& own = strongest ? *strongest : first;
        m_out[path].hits.push_back({own.object, own.event.value_or(Event::Escape), own.normal,
                                    own.n_inside, own.n_outside});
        for (const RayTreeNode& c : node.children) {
            if (!continues(c)) continue;
            size_t branch = path;
            if (&c != strongest) {
                m_out.push_back(path_from(hit, c.weight));
                branch = m_out.size() - 1;
            }
            if (c.event == Event::Tir) m_out[branch].tir = true;
            follow(c, branch);
        }
    }

    static bool continues(const RayTreeNode& n) {
        return n.event == Event::Refract || n.event == Event::Reflect || n.event == Event::Tir;
    }

    SectionRayPath path_from(const Vec3& start, double weight) const {
        SectionRayPath path;
        path.points = {start};
        path.wavelength_nm = m_wavelength.nm;
        path.weight = weight * m_wavelength.weight;
        path.colour = m_wavelength.colour;
        path.whole_spectrum = m_wavelength.whole_spectrum;
        return path;
    }

    SectionWavelength m_wavelength;
    double m_escape;
    std::vector<SectionRayPath>& m_out;
};

}  // namespace

namespace {

// A colour clipped to the gamut's positive side and scaled to brightest channel 1 (white
// for black, which has no hue).
Rgb brightest_channel_one(Rgb c) {
    c = {std::max(c.r, 0.0), std::max(c.g, 0.0), std::max(c.b, 0.0)};
    const double peak = std::max({c.r, c.g, c.b});
    return peak > 0 ? c * (1 / peak) : Rgb{1, 1, 1};
}

}  // namespace

Rgb wavelength_rgb(double nm) { return brightest_channel_one(xyz_to_linear_srgb(cie_xyz_bar(nm))); }

std::vector<SectionWavelength> section_wavelengths(const Spectrum& s,
                                                   const std::vector<double>& spread,
                                                   bool disperses) {
    // The spectrum's quantiles (sample_wavelength draws in proportion to its power).
    const auto quantile = [&](double u) {
        double nm = kLineD;
        s.sample_wavelength(u, nm);
        return nm;
    };
    if (quantile(0.975) - quantile(0.025) <= 6.0) {  // a line: traced at its centre
        constexpr int kSteps = 64;
        double nm = 0;
        for (int i = 0; i < kSteps; ++i) nm += quantile((i + 0.5) / kSteps) / kSteps;
        return {{nm, 1, wavelength_rgb(nm), false}};
    }
    if (spread.empty()) return {};
    if (!disperses)
        return {{spread[spread.size() / 2], 1, brightest_channel_one(spectrum_to_rgb(s)), true}};
    std::vector<SectionWavelength> out;
    double strongest = 0;
    for (double nm : spread) strongest = std::max(strongest, s.eval(nm));
    for (double nm : spread) {
        const double weight = strongest > 0 ? s.eval(nm) / strongest : 1.0;
        if (weight > 0) out.push_back({nm, weight, wavelength_rgb(nm), false});
    }
    return out;
}

std::vector<SectionSource> section_sources(const Scene& scene, const SectionPlane& plane,
                                           const SectionRayOptions& options) {
    std::vector<SectionSource> sources;
    if (options.beam) {
        sources.push_back({{}, options.beam_spectrum ? options.beam_spectrum : d65_spectrum()});
        add_section_beam(*options.beam, plane, sources.back().rays);
    }
    const int fan = options.rays_per_light;
    if (fan <= 0) return sources;
    // The rays of a light the plane cuts are added to a new source of its spectrum.
    const auto rays_of = [&](const SpectrumPtr& spectrum) -> std::vector<Ray>& {
        sources.push_back({{}, spectrum});
        return sources.back().rays;
    };
    for (const PointLight& light : scene.point_lights) {
        if (std::abs(plane.distance(light.position)) < 1e-9)
            add_section_fan(light.position, 0.0, fan, plane, rays_of(light.spectrum));
    }
    for (const SpotLight& light : scene.spots) {
        if (std::abs(plane.distance(light.position)) < 1e-9 &&
            direction_in_section_plane(light.direction, plane)) {
            add_section_cone(light.position, light.direction,
                             light.cone_angle * std::numbers::pi / 180, fan, plane,
                             rays_of(light.spectrum));
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
                                 fan, plane, rays_of(light.spectrum));
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
                         plane, rays_of(light.spectrum));
    }
    for (const SphereEmitter& e : scene.emitters()) {
        const double d = plane.distance(e.sphere.centre);
        const double r = e.sphere.radius;
        if (std::abs(d) >= r) continue;
        // Just outside the sphere's section, so the rays leave the lamp rather than hit it.
        add_section_fan(e.sphere.centre - plane.normal() * d, std::sqrt(r * r - d * d) * (1 + 1e-6),
                        fan, plane, rays_of(e.radiance));
    }
    return sources;
}

std::vector<Ray> section_start_rays(const Scene& scene, const SectionPlane& plane,
                                    const SectionRayOptions& options) {
    std::vector<Ray> rays;
    for (const SectionSource& source : section_sources(scene, plane, options))
        rays.insert(rays.end(), source.rays.begin(), source.rays.end());
    return rays;
}

void append_ray_paths(const RayTree& tree, const SectionWavelength& wavelength,
                      double escape_length, std::vector<SectionRayPath>& out) {
    const size_t first = out.size();
    PathFlattener(wavelength, escape_length, out).start(tree.root);
    // A branch dropped at once (below the weight limit) leaves a single point.
    const auto single = std::remove_if(out.begin() + std::ptrdiff_t(first), out.end(),
                                       [](const SectionRayPath& p) { return p.points.size() < 2; });
    out.erase(single, out.end());
}

std::optional<SectionBeam> default_section_beam(const Scene& scene, int object,
                                                const SectionPlane& plane, int rays) {
    if (object < 0 || object >= int(scene.objects.size())) return std::nullopt;
    // A beam shows what glass or a mirror does; an opaque screen would only swallow it.
    const Material& m = scene.material_of(object);
    if (m.transparency <= 0 && m.specular <= 0) return std::nullopt;
    std::optional<OpticalAxis> axis = scene.objects[object].shape->optical_axis();
    // A lens or mirror cut across its axis gets the beam of any other object.
    if (axis && std::abs(dot(axis->direction, plane.normal())) > 1e-9) axis.reset();
    if (!axis) {
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
    const double width = 0.8 * axis->diameter;
    if (axis->reflects) {  // onto the mirror's face, from as far in front as it is wide
        const Vec3 start = axis->centre + axis->direction * (1.5 * axis->diameter);
        return SectionBeam{start, -axis->direction, width, rays};
    }
    Vec3 direction = axis->direction;
    std::optional<Vec3> light;
    if (!scene.emitters().empty()) light = scene.emitters().front().sphere.centre;
    if (!light && !scene.point_lights.empty()) light = scene.point_lights.front().position;
    if (light && dot(*light - axis->centre, direction) > 0) direction = -direction;
    const double distance = axis->thickness + 1.0 * axis->diameter;
    return SectionBeam{axis->centre - direction * distance, direction, width, rays};
}

}  // namespace lenslab
