#include <cmath>

#include "analysis/system/system_builder_parts.h"
#include "geometry/lens/mirror_surface.h"
#include "util/scene_error.h"

namespace lenslab::system_parts {

namespace {

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

}  // namespace

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

namespace {

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

}  // namespace

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
        const Shape& shape = *scene.objects[i].shape;
        if (const MirrorPrescription* m = shape.mirror_prescription()) {
            size = std::max(size, m->diameter);
        } else if (const LensPrescription* l = shape.lens_prescription()) {
            size = std::max(size, l->diameter);
        }
    }
    if (const MirrorPrescription* m = first.shape->mirror_prescription()) {
        // A first mirror may be a fold, tilted from the axis the light comes in along.
        axis = length(first.group_axis) > 0 ? first.group_axis : m->axis;
        start = m->vertex;
    } else {
        const LensPrescription& p = *first.shape->lens_prescription();
        axis = p.axis;
        start = p.centre - p.axis * (0.5 * p.thickness);
    }
    system.origin = start;
    system.frame = Frame::from_axis(axis);
    double travel = 1.0;
    Straightening straight;  // the scene as if every fold mirror faced the axis square on
    for (int i : sequence) {
        const SceneObject& o = scene.objects[i];
        if (const MirrorPrescription* mirror = o.shape->mirror_prescription()) {
            const MirrorPrescription& p = *mirror;
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
        const LensPrescription* lens = o.shape->lens_prescription();
        if (!lens) continue;  // a group holds lenses and mirrors only
        LensPrescription p = *lens;
        p.centre = straight.point(p.centre);
        p.axis = straight.direction(p.axis);
        check_on_axis(scene, i, p.axis, p.centre, axis, start, size);
        check_lens_transparent(scene, i);
        if (has_freeform_face(p)) {
            throw SceneError(
                object_path(scene, i) + (p.front->is_rotationally_symmetric() ? ".back" : ".front"),
                "a freeform face (not a surface of revolution) in a system with "
                "mirrors is not yet measured by the bench");
        }
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
            i, lens, orientation, forward ? z_front : z_back, forward ? z_back : z_front, travel};
        system.elements.push_back(make_element(scene, i));
        add_surfaces(placed, static_cast<int>(system.elements.size()) - 1, system);
    }
    return system;
}

}  // namespace lenslab::system_parts
