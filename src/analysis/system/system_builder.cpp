#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/system/optical_system.h"
#include "analysis/system/system_builder_parts.h"
#include "geometry/lens/lens_solid.h"
#include "scene/interaction.h"
#include "scene/scattering.h"
#include "util/scene_error.h"

namespace lenslab {

namespace system_parts {

// The scene file's entry the object came from (a lens group's elements share one).
std::string object_path(const Scene& scene, int i) {
    const int entry = scene.objects[i].source >= 0 ? scene.objects[i].source : i;
    std::string path = "objects[" + std::to_string(entry) + "]";
    int element = 0, siblings = 0;
    for (int j = 0; j < static_cast<int>(scene.objects.size()); ++j) {
        if (j == i || scene.objects[j].source != entry) continue;
        ++siblings;
        if (j < i) ++element;
    }
    if (siblings > 0) path += ".elements[" + std::to_string(element) + "]";
    return path;
}

std::string describe_object(const Scene& scene, int i) {
    const std::string path = object_path(scene, i);
    const std::string& name = scene.objects[i].name;
    return name == path || name.empty() ? path : path + " ('" + name + "')";
}

std::string format(double v) {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
}

std::pair<Vec3, Vec3> vertices_met(const LensPrescription& p, double orientation) {
    const Vec3 half = p.axis * (0.5 * orientation * p.thickness);
    return {p.centre - half, p.centre + half};
}

SurfaceSpan measure_aim_span(const LensSurface& shape, double semi_diameter) {
    return intersect_span(shape, std::min(2.0 * semi_diameter, 0.999 * shape.max_semi_diameter()));
}

void add_surfaces(const Placed& p, int element, OpticalSystem& system) {
    const LensPrescription& pr = *p.lens;
    const bool forward = p.orientation * p.travel > 0;  // the front face is met first
    const std::string path = system.elements[element].path;
    const double a = 0.5 * pr.diameter;
    const Frame frame = lens_frame(pr);
    const auto make = [&](const std::shared_ptr<const LensSurface>& shape, double z,
                          const char* face) {
        SystemSurface s;
        if (p.posed) {
            const double side = face == std::string("front") ? -0.5 : 0.5;
            const Frame& f = system.frame;
            s.pose = SurfacePose{system.to_system(pr.centre + frame.w * (side * pr.thickness)),
                                 {f.to_local(frame.u), f.to_local(frame.v), f.to_local(frame.w)}};
        }
        s.shape = shape;
        s.orientation = p.orientation;
        s.z = z;
        s.travel = p.travel;
        s.semi_diameter = a;
        s.span = intersect_span(*shape, a);
        s.aim_span = measure_aim_span(*shape, a);
        VertexSag vertex;
        if (shape->is_rotationally_symmetric()) {
            vertex = shape->vertex_sag(a);
        } else {
            // A freeform face, for the system as designed: its curvature in the y-z section
            // (the meridional one), by a central difference over a thousandth of its radius.
            const double h = 1e-3 * a;
            vertex.curvature = (shape->sag_xy(0, h) + shape->sag_xy(0, -h)) / (h * h);
        }
        s.curvature = p.orientation * vertex.curvature;
        s.a4 = p.orientation * vertex.a4;
        s.label = path + "." + face;
        return s;
    };
    SystemElement& e = system.elements[element];
    SystemSurface in = make(forward ? pr.front : pr.back, p.z_first, forward ? "front" : "back");
    SystemSurface out = make(forward ? pr.back : pr.front, p.z_last, forward ? "back" : "front");
    out.element_before = element;
    in.element_after = element;

    // A cemented interface: the previous lens's exit surface has this lens's entry shape at
    // the same place. Then the two become one glass-to-glass surface.
    if (!system.surfaces.empty() && !system.surfaces.back().mirror) {
        SystemSurface& prev = system.surfaces.back();
        const double common = std::min(prev.semi_diameter, in.semi_diameter);
        const double scale =
            std::max({std::abs(p.z_last), 2.0 * system.max_semi_diameter(), 2.0 * a});
        double worst = INFINITY, largest = 0.0, worst_r = 0.0;
        for (int k = 0; k <= 64; ++k) {
            const double r = common * k / 64.0;
            const double gap = p.travel * (in.z_at(r) - prev.z_at(r));
            if (gap < worst) {
                worst = gap;
                worst_r = r;
            }
            largest = std::max(largest, std::abs(gap));
        }
        const double tol = kCementTolerance * scale;
        if (worst < -tol) {
            const SystemElement& before = system.elements[prev.element_before];
            throw SceneError(path, "overlaps " + before.path + " along the axis: at " +
                                       format(worst_r) + " from the axis its " +
                                       (forward ? "front" : "back") + " surface lies " +
                                       format(-worst) + " before " + prev.label);
        }
        const double c_tol = kCementTolerance * std::max({std::abs(prev.curvature),
                                                          std::abs(in.curvature), 1.0 / scale});
        if (largest <= tol && std::abs(prev.curvature - in.curvature) <= c_tol) {
            prev.element_after = element;
            prev.semi_diameter = common;
            prev.span = intersect_span(*prev.shape, common);
            prev.aim_span = measure_aim_span(*prev.shape, common);
            prev.label += " = " + in.label;
            e.first_surface = static_cast<int>(system.surfaces.size()) - 1;
            system.surfaces.push_back(out);
            e.last_surface = static_cast<int>(system.surfaces.size()) - 1;
            return;
        }
    }
    e.first_surface = static_cast<int>(system.surfaces.size());
    system.surfaces.push_back(in);
    system.surfaces.push_back(out);
    e.last_surface = e.first_surface + 1;
}

SystemElement make_element(const Scene& scene, int object) {
    const LensPrescription& lens = *scene.objects[object].shape->lens_prescription();
    SystemElement e;
    e.object = object;
    e.path = object_path(scene, object);
    e.name = scene.objects[object].name;
    const Material& m = scene.material_of(object);
    e.glass = m.glass.empty() ? m.index->describe() : m.glass;
    e.index = m.index;
    e.semi_diameter = 0.5 * lens.diameter;
    return e;
}

bool has_freeform_face(const LensPrescription& p) {
    return !p.front->is_rotationally_symmetric() || !p.back->is_rotationally_symmetric();
}

void check_lens_transparent(const Scene& scene, int i) {
    if (!(scene.material_of(i).transparency > 0.0)) {
        throw SceneError(object_path(scene, i) + ".material",
                         "transparency is 0: light does not pass this lens");
    }
}

}  // namespace system_parts

using namespace system_parts;

namespace {

// A lens of gradient index: the bench's paraxial and real traces need it symmetric about the
// system's axis (a radial profile centred on it, or an axial one along it).
void attach_grin(const Scene& scene, int object, const Vec3& axis, const Vec3& axis_point,
                 SystemElement& e) {
    const Material& m = scene.material_of(object);
    const GrinProfile& g = *m.grin;
    const std::string where = object_path(scene, object) + ".material";
    if (g.kind != GrinKind::Radial && g.kind != GrinKind::Axial) {
        throw SceneError(where, std::string("a ") + grin_kind_name(g.kind) +
                                    " GRIN lens is not a coaxial system the bench measures "
                                    "(radial and axial profiles are); trace or detect it");
    }
    const SceneObject& o = scene.objects[object];
    const Vec3 centre = grin_medium_of(o, m, kLineD).centre;  // where the renderer puts it
    const double size = length(o.shape->bounds().extent());
    const Vec3 offset = centre - axis_point;
    const double off_axis = length(offset - axis * dot(offset, axis));
    if (length(cross(normalize(g.axis), axis)) > kAxisAngleTolerance) {
        throw SceneError(where, "the GRIN profile's axis is not the lens system's axis");
    }
    if (g.kind == GrinKind::Radial && off_axis > kAxisOffsetTolerance * size) {
        throw SceneError(where, "the radial GRIN profile's centre lies " + format(off_axis) +
                                    " from the lens system's axis");
    }
    e.grin = m.grin;
    e.grin_centre = centre;
    e.solid = o.shape;
    std::ostringstream name;
    name << "GRIN " << grin_kind_name(g.kind) << " n0 = " << format(g.n0)
         << ", A = " << format(g.A);
    e.glass = name.str();
}

// Where a lens was designed to stand when it has been moved from there: its lens group's
// axis, or its own before its decentre and tilt keys; none for a lens never moved.
struct DesignedAxis {
    Vec3 axis, vertex;
};

std::optional<DesignedAxis> designed_axis(const Scene& scene, int i) {
    const SceneObject& o = scene.objects[i];
    if (length(o.group_axis) > 0) return DesignedAxis{o.group_axis, o.group_vertex};
    const LensPrescription& p = *o.shape->lens_prescription();
    if (length(p.designed_axis) > 0) return DesignedAxis{p.designed_axis, p.designed_vertex};
    return std::nullopt;
}

// Whether a designed axis is the system's (through `centre` along `axis`).
bool on_axis(const DesignedAxis& d, const Vec3& axis, const Vec3& centre, double largest) {
    const Vec3 offset = d.vertex - centre;
    return length(cross(axis, d.axis)) <= kAxisAngleTolerance &&
           length(offset - axis * dot(offset, axis)) <= kAxisOffsetTolerance * largest;
}

}  // namespace

OpticalSystem build_optical_system(const Scene& scene, std::optional<int> lens) {
    if (lens && (*lens < 0 || *lens >= static_cast<int>(scene.objects.size()))) {
        throw SceneError("objects", "is not a lens");
    }
    if (const std::optional<int> group = folded_group(scene, lens)) {
        return build_folded_system(scene, *group);
    }
    std::vector<int> lenses;
    OpticalSystem system;
    for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i) {
        if (scene.objects[i].shape->lens_prescription()) {
            lenses.push_back(i);
        } else {
            system.ignored.push_back(
                describe_object(scene, i) +
                (scene.objects[i].type == ObjectType::Mirror
                     ? ": a mirror (the bench does not yet measure systems with mirrors)"
                     : ": not a lens"));
        }
    }
    if (lenses.empty()) {
        throw SceneError("objects", "no lens in the scene (analyze measures lens objects)");
    }
    if (lens && std::find(lenses.begin(), lenses.end(), *lens) == lenses.end()) {
        throw SceneError(*lens >= 0 ? object_path(scene, *lens) : "objects", "is not a lens");
    }
    const int seed = lens ? *lens : lenses.front();
    const LensPrescription& seed_lens = *scene.objects[seed].shape->lens_prescription();
    // Lenses may be decentred or tilted from the axis they were designed on (a lens group's,
    // or a lens's own before its decentre and tilt keys): then the system's axis is that one.
    const std::optional<DesignedAxis> seed_design = designed_axis(scene, seed);
    const Vec3 axis = seed_design ? seed_design->axis : seed_lens.axis;
    Vec3 centre = seed_lens.centre;
    if (seed_design) {
        const Vec3 offset = centre - seed_design->vertex;
        if (length(cross(axis, seed_lens.axis)) > kAxisAngleTolerance ||
            length(offset - axis * dot(offset, axis)) > kAxisOffsetTolerance * seed_lens.diameter) {
            centre = seed_design->vertex;
        }
    }
    double largest = 0.0;
    for (int i : lenses) {
        largest = std::max(largest, scene.objects[i].shape->lens_prescription()->diameter);
    }

    std::vector<Placed> placed;
    for (int i : lenses) {
        const LensPrescription& p = *scene.objects[i].shape->lens_prescription();
        const double sine = length(cross(axis, p.axis));
        const Vec3 offset = p.centre - centre;
        const double off_axis = length(offset - axis * dot(offset, axis));
        const bool off = sine > kAxisAngleTolerance || off_axis > kAxisOffsetTolerance * largest;
        // A lens moved from an axis designed on this one, or a lens with a freeform face: its
        // surfaces placed by the lens's own frame (the face's x and y are the lens's).
        const std::optional<DesignedAxis> design = designed_axis(scene, i);
        const bool posable = design && on_axis(*design, axis, centre, largest);
        if ((off && posable) || (!off && has_freeform_face(p))) {
            check_lens_transparent(scene, i);
            if (scene.material_of(i).grin) {
                throw SceneError(object_path(scene, i) + ".material",
                                 "a gradient-index lens decentred, tilted or with a freeform face "
                                 "is not measured by the bench");
            }
            const double orientation = dot(p.axis, axis) > 0 ? 1.0 : -1.0;
            const double z_first = dot(vertices_met(p, orientation).first - centre, axis);
            Placed moved{i, &p, orientation, z_first, z_first + p.thickness};
            moved.posed = true;
            placed.push_back(moved);
            continue;
        }
        if (off) {
            std::ostringstream why;
            why << "not on the axis of " << describe_object(scene, seed) << ": ";
            if (sine > kAxisAngleTolerance) {
                why << "its axis is tilted by "
                    << format(std::asin(std::min(1.0, sine)) * 180 / M_PI) << " degrees";
            } else {
                why << "its centre lies " << format(off_axis) << " from that axis";
            }
            if (lens) {
                system.ignored.push_back(describe_object(scene, i) + ": " + why.str());
                continue;
            }
            why << " (all lenses must share one axis; pick one system with --lens NAME)";
            throw SceneError(object_path(scene, i), why.str());
        }
        check_lens_transparent(scene, i);
        const double orientation = dot(p.axis, axis) > 0 ? 1.0 : -1.0;
        const double zc = dot(offset, axis);
        placed.push_back({i, &p, orientation, zc - 0.5 * p.thickness, zc + 0.5 * p.thickness});
    }
    std::stable_sort(placed.begin(), placed.end(),
                     [](const Placed& a, const Placed& b) { return a.z_first < b.z_first; });
    // Elements cemented to a decentred or tilted one move with it: as designed, each begins
    // where the one before ends.
    for (size_t k = 1; k < placed.size(); ++k) {
        Placed& now = placed[k];
        const Placed& before = placed[k - 1];
        if (!now.posed || !before.posed) continue;
        const Vec3 end = vertices_met(*before.lens, before.orientation).second;
        const Vec3 start = vertices_met(*now.lens, now.orientation).first;
        if (length(end - start) > kCementTolerance * largest) continue;
        now.z_last = before.z_last + (now.z_last - now.z_first);
        now.z_first = before.z_last;
    }

    const double z0 = placed.front().z_first;
    system.origin = centre + axis * z0;
    system.frame = Frame::from_axis(axis);
    for (Placed& p : placed) {
        p.z_first -= z0;
        p.z_last -= z0;
        SystemElement e = make_element(scene, p.object);
        if (scene.material_of(p.object).grin) attach_grin(scene, p.object, axis, centre, e);
        system.elements.push_back(e);
        add_surfaces(p, static_cast<int>(system.elements.size()) - 1, system);
    }
    return system;
}

}  // namespace lenslab
