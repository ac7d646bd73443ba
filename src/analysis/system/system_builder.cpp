#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/system/optical_system.h"
#include "geometry/lens/lens_solid.h"
#include "geometry/lens/mirror_surface.h"
#include "scene/interaction.h"
#include "scene/scattering.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

// Axes this close to parallel (sine of the angle) and centres this close to the axis
// (relative to the largest lens diameter) count as one axis: hand-typed and generated
// scenes put coaxial lenses on exactly the same line, up to rounding.
constexpr double kAxisAngleTolerance = 1e-9;
constexpr double kAxisOffsetTolerance = 1e-9;
// Facing surfaces closer than this (relative to the system's size) are one cemented
// interface; the lead's shorthand and hand-written doublets place them exactly.
constexpr double kCementTolerance = 1e-9;

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

struct Placed {
    int object;
    const LensSolid* lens;
    double orientation;      // +1: lens axis along the system axis
    double z_first, z_last;  // the faces light meets first and last
    double travel = 1.0;     // the direction light crosses it (-1: after a mirror)
};

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

SurfaceSpan measure_aim_span(const LensSurface& shape, double semi_diameter) {
    return intersect_span(shape, std::min(2.0 * semi_diameter, 0.999 * shape.max_semi_diameter()));
}

// The two surfaces of a lens in the order light meets them, as system surfaces.
void add_surfaces(const Placed& p, int element, OpticalSystem& system) {
    const LensPrescription& pr = p.lens->prescription();
    const bool forward = p.orientation * p.travel > 0;  // the front face is met first
    const std::string path = system.elements[element].path;
    const double a = 0.5 * pr.diameter;
    const auto make = [&](const std::shared_ptr<const LensSurface>& shape, double z,
                          const char* face) {
        SystemSurface s;
        s.shape = shape;
        s.orientation = p.orientation;
        s.z = z;
        s.travel = p.travel;
        s.semi_diameter = a;
        s.span = intersect_span(*shape, a);
        s.aim_span = measure_aim_span(*shape, a);
        const VertexSag vertex = shape->vertex_sag(a);
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

// Where an object lies relative to the axis through `point` along `axis`: refused with
// `why` when tilted or off it.
void check_on_axis(const Scene& scene, int i, const Vec3& object_axis, const Vec3& centre,
                   const Vec3& axis, const Vec3& point, double size) {
    const double sine = length(cross(axis, object_axis));
    const Vec3 offset = centre - point;
    const double off_axis = length(offset - axis * dot(offset, axis));
    if (sine <= kAxisAngleTolerance && off_axis <= kAxisOffsetTolerance * size) return;
    throw SceneError(
        object_path(scene, i),
        sine > kAxisAngleTolerance
            ? "its axis is tilted by " + format(std::asin(std::min(1.0, sine)) * 180 / M_PI) +
                  " degrees from the folded system's axis"
            : "its centre lies " + format(off_axis) + " from the folded system's axis");
}

SystemElement make_element(const Scene& scene, int object) {
    const auto* solid = dynamic_cast<const LensSolid*>(scene.objects[object].shape.get());
    SystemElement e;
    e.object = object;
    e.path = object_path(scene, object);
    e.name = scene.objects[object].name;
    const Material& m = scene.material_of(object);
    e.glass = m.glass.empty() ? m.index->describe() : m.glass;
    e.index = m.index;
    e.semi_diameter = 0.5 * solid->prescription().diameter;
    return e;
}

void check_lens_faces(const Scene& scene, int i, const LensPrescription& p) {
    for (const auto& face : {p.front, p.back}) {
        if (!face->is_rotationally_symmetric()) {
            throw SceneError(object_path(scene, i) + (face == p.front ? ".front" : ".back"),
                             "a sag formula in x and y is not a surface of revolution; "
                             "the lens bench measures rotationally symmetric systems");
        }
    }
    if (!(scene.material_of(i).transparency > 0.0)) {
        throw SceneError(object_path(scene, i) + ".material",
                         "transparency is 0: light does not pass this lens");
    }
}

// The lens group holding a mirror that the system is built from: the one `lens` belongs to,
// else the first; none when no group holds a mirror (or `lens` is in none that does).
std::optional<int> folded_group(const Scene& scene, std::optional<int> lens) {
    std::optional<int> first;
    for (const SceneObject& o : scene.objects) {
        if (o.type != ObjectType::Mirror || o.source < 0) continue;
        if (lens && scene.objects[*lens].source == o.source) return o.source;
        if (!first) first = o.source;
    }
    if (lens) return std::nullopt;
    return first;
}

// A rigid turn of the scene that undoes the fold mirrors met so far: a flat mirror tilted
// from the axis and one square to it differ by a rotation of the space behind them (by twice
// the tilt, about the vertex), so the bench measures the folded system as the straight one,
// its rays the same up to that rotation (the image plane turned with it).
class Straightening {
public:
    Vec3 point(const Vec3& p) const { return m_origin + direction(p); }
    Vec3 direction(const Vec3& d) const { return m_x * d.x + m_y * d.y + m_z * d.z; }

    // At the fold mirror of vertex `vertex` and normal `normal` (both straightened), the
    // light arriving along `arriving`: turn what lies behind it so that the reflected light
    // runs back along -arriving.
    void unfold(const Vec3& vertex, const Vec3& normal, const Vec3& arriving) {
        const Vec3 reflected = arriving - normal * (2.0 * dot(arriving, normal));
        const Vec3 hinge = normalize(cross(reflected, -arriving));
        const double angle =
            std::atan2(length(cross(reflected, -arriving)), dot(reflected, -arriving));
        const auto turn = [&](const Vec3& v) {
            return v * std::cos(angle) + cross(hinge, v) * std::sin(angle) +
                   hinge * (dot(hinge, v) * (1.0 - std::cos(angle)));
        };
        // p -> vertex + turn(point(p) - vertex), written as origin + M p.
        m_origin = vertex + turn(m_origin - vertex);
        m_x = turn(m_x);
        m_y = turn(m_y);
        m_z = turn(m_z);
    }

private:
    Vec3 m_origin;  // point(p) = m_origin + M p, M's columns m_x, m_y, m_z
    Vec3 m_x{1, 0, 0}, m_y{0, 1, 0}, m_z{0, 0, 1};
};

// Whether a surface is a plane over the given semi-diameter (its sag nowhere off zero).
bool is_flat(const LensSurface& s, double semi_diameter) {
    for (int k = 0; k <= 32; ++k) {
        const double r = semi_diameter * k / 32;
        for (double phi : {0.0, 0.5 * M_PI, 0.25 * M_PI}) {
            if (std::abs(s.sag_xy(r * std::cos(phi), r * std::sin(phi))) > 1e-12 * semi_diameter)
                return false;
        }
    }
    return true;
}

// A folded system: the group's elements in its order, the direction of travel turning at
// each mirror.
OpticalSystem build_folded_system(const Scene& scene, int group) {
    OpticalSystem system;
    std::vector<int> sequence;
    for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i) {
        if (scene.objects[i].source == group) {
            sequence.push_back(i);
        } else {
            system.ignored.push_back(describe_object(scene, i) +
                                     ": not in the folded system of objects[" +
                                     std::to_string(group) + "]");
        }
    }
    // Every element of a group shares the group's axis; the first one met starts the system.
    const SceneObject& first = scene.objects[sequence.front()];
    Vec3 axis, start;
    double size = 0.0;
    for (int i : sequence) {
        if (const auto* m = dynamic_cast<const MirrorSurface*>(scene.objects[i].shape.get())) {
            size = std::max(size, m->prescription().diameter);
        } else if (const auto* l = dynamic_cast<const LensSolid*>(scene.objects[i].shape.get())) {
            size = std::max(size, l->prescription().diameter);
        }
    }
    if (const auto* m = dynamic_cast<const MirrorSurface*>(first.shape.get())) {
        // A first mirror may be a fold, tilted from the axis the light comes in along.
        axis = length(first.group_axis) > 0 ? first.group_axis : m->prescription().axis;
        start = m->prescription().vertex;
    } else {
        const LensPrescription& p = dynamic_cast<const LensSolid&>(*first.shape).prescription();
        axis = p.axis;
        start = p.centre - p.axis * (0.5 * p.thickness);
    }
    system.origin = start;
    system.frame = Frame::from_axis(axis);
    double travel = 1.0;
    Straightening straight;  // the scene as if every fold mirror faced the axis square on
    for (int i : sequence) {
        const SceneObject& o = scene.objects[i];
        if (const auto* m = dynamic_cast<const MirrorSurface*>(o.shape.get())) {
            const MirrorPrescription& p = m->prescription();
            const Vec3 vertex = straight.point(p.vertex);
            Vec3 facing = straight.direction(p.axis);
            if (length(cross(facing, axis)) > kAxisAngleTolerance) {
                if (!is_flat(*p.surface, 0.5 * p.diameter)) {
                    throw SceneError(object_path(scene, i),
                                     "a tilted curved mirror (an off-axis system) is not yet "
                                     "measured by the bench; flat fold mirrors are");
                }
                // A fold: on the straightened axis, a plane mirror square to it.
                straight.unfold(vertex, facing, axis * travel);
                facing = axis;
            }
            check_on_axis(scene, i, facing, vertex, axis, start, size);
            if (!p.surface->is_rotationally_symmetric()) {
                throw SceneError(object_path(scene, i) + ".mirror",
                                 "a sag formula in x and y is not a surface of revolution; "
                                 "the lens bench measures rotationally symmetric systems");
            }
            SystemSurface s;
            s.shape = p.surface;
            s.orientation = dot(facing, axis) > 0 ? 1.0 : -1.0;
            s.z = dot(vertex - start, axis);
            s.travel = travel;
            s.mirror = true;
            s.semi_diameter = 0.5 * p.diameter;
            s.hole_semi_diameter = 0.5 * p.hole_diameter;
            s.span = intersect_span(*p.surface, s.semi_diameter);
            s.aim_span = measure_aim_span(*p.surface, s.semi_diameter);
            const VertexSag vertex_sag = p.surface->vertex_sag(s.semi_diameter);
            s.curvature = s.orientation * vertex_sag.curvature;
            s.a4 = s.orientation * vertex_sag.a4;
            s.label = object_path(scene, i) + " (mirror)";
            system.surfaces.push_back(s);
            travel = -travel;
            continue;
        }
        const auto* solid = dynamic_cast<const LensSolid*>(o.shape.get());
        if (!solid) continue;  // a group holds lenses and mirrors only
        LensPrescription p = solid->prescription();
        p.centre = straight.point(p.centre);
        p.axis = straight.direction(p.axis);
        check_on_axis(scene, i, p.axis, p.centre, axis, start, size);
        check_lens_faces(scene, i, p);
        if (scene.material_of(i).grin) {
            throw SceneError(object_path(scene, i) + ".material",
                             "a gradient index in a system with mirrors is not measured by the "
                             "bench");
        }
        const double orientation = dot(p.axis, axis) > 0 ? 1.0 : -1.0;
        const double zc = dot(p.centre - start, axis);
        const double z_front = zc - orientation * 0.5 * p.thickness;
        const double z_back = zc + orientation * 0.5 * p.thickness;
        const bool forward = orientation * travel > 0;
        Placed placed{
            i, solid, orientation, forward ? z_front : z_back, forward ? z_back : z_front, travel};
        system.elements.push_back(make_element(scene, i));
        add_surfaces(placed, static_cast<int>(system.elements.size()) - 1, system);
    }
    return system;
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
        if (dynamic_cast<const LensSolid*>(scene.objects[i].shape.get())) {
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
    const auto* seed_solid = dynamic_cast<const LensSolid*>(scene.objects[seed].shape.get());
    const Vec3 axis = seed_solid->prescription().axis;
    const Vec3 centre = seed_solid->prescription().centre;
    double largest = 0.0;
    for (int i : lenses) {
        const auto* solid = dynamic_cast<const LensSolid*>(scene.objects[i].shape.get());
        largest = std::max(largest, solid->prescription().diameter);
    }

    std::vector<Placed> placed;
    for (int i : lenses) {
        const auto* solid = dynamic_cast<const LensSolid*>(scene.objects[i].shape.get());
        const LensPrescription& p = solid->prescription();
        const double sine = length(cross(axis, p.axis));
        const Vec3 offset = p.centre - centre;
        const double off_axis = length(offset - axis * dot(offset, axis));
        if (sine > kAxisAngleTolerance || off_axis > kAxisOffsetTolerance * largest) {
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
        check_lens_faces(scene, i, p);
        const double orientation = dot(p.axis, axis) > 0 ? 1.0 : -1.0;
        const double zc = dot(offset, axis);
        placed.push_back({i, solid, orientation, zc - 0.5 * p.thickness, zc + 0.5 * p.thickness});
    }
    std::stable_sort(placed.begin(), placed.end(),
                     [](const Placed& a, const Placed& b) { return a.z_first < b.z_first; });

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
