#include "scene/lens_group_json.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "geometry/lens/lens_clearance.h"
#include "geometry/lens/lens_solid.h"
#include "geometry/lens/mirror_surface.h"
#include "math/rigid_motion.h"
#include "scene/json_reader.h"
#include "scene/limits.h"
#include "scene/mirror_json.h"
#include "scene/object_spec.h"
#include "scene/spec_reader.h"
#include "scene/surface_json.h"

namespace lenslab {

namespace {

using nlohmann::json;

// One element as read, before the lenses are built.
struct GroupElement {
    std::string path, name;
    double thickness = 0, gap = 0, diameter = 0;
    const json* front = nullptr;
    const json* back = nullptr;    // nullptr: cemented to the next element's front
    const json* mirror = nullptr;  // a mirror element's surface (no front, back, thickness)
    double hole_diameter = 0;
    // A mirror's tilt_x or tilt_y; a lens element's decentre (across the axis) and tilts
    // (degrees, then about its own z).
    Decentring move;
    int material = 0;
};

ElementSpec declare_group() {
    // The common keys but material (each element names its own), detector and medium.
    ElementSpec s{"lens_group", "a lens group", {}, {}};
    for (const ParamSpec& p : object_common_spec().params) {
        if (p.key != "material" && p.key != "detector" && p.key != "medium") s.params.push_back(p);
    }
    s.params.push_back(point_param("vertex")
                           .describe("front vertex of the first element")
                           .in_editor("Front vertex"));
    s.params.push_back(
        direction_param("axis").describe("the optical axis, from front to back").in_editor("Axis"));
    s.params.push_back(number_param("diameter", 0)
                           .above(0)
                           .needed()
                           .describe("diameter of every element that does not give its own")
                           .in_editor("Diameter"));
    s.params.push_back(nested_param(ParamKind::Direction, "x_axis")
                           .meaning_auto("a fixed perpendicular to `axis`")
                           .describe("as for a lens"));
    s.params.push_back(nested_param(ParamKind::Array, "elements")
                           .needed()
                           .describe("the elements, front to back (at least one)"));
    s.example = nlohmann::json::parse(
        R"json({"type": "lens_group", "name": "doublet", "vertex": [0, 0, 0], "axis": [0, 0, 1], "diameter": 1, "elements": [{"name": "crown", "front": {"shape": "sphere", "radius": 1.8}, "thickness": 0.25, "material": {"color": 1, "transparency": 1, "glass": "N-BK7"}}, {"name": "flint", "front": {"shape": "sphere", "radius": -1.8}, "thickness": 0.1, "back": {"shape": "sphere", "radius": -30}, "material": {"color": 1, "transparency": 1, "glass": "F2"}}]})json");
    return s;
}

ElementSpec declare_element() {
    ElementSpec s{"lens_group element", "a lens group element", {}, {}};
    s.params.push_back(nested_param(ParamKind::String, "name")
                           .meaning_auto("`\"NAME element i\"`")
                           .describe("shown by lenslab trace"));
    s.params.push_back(nested_param(ParamKind::Object, "front")
                           .needed()
                           .as_written("[surface](#surfaces)")
                           .describe("its front face"));
    s.params.push_back(nested_param(ParamKind::Object, "back")
                           .meaning_auto("the next element's `front`")
                           .as_written("[surface](#surfaces)")
                           .describe("its back face; none when cemented to the next"));
    s.params.push_back(number_param("thickness", 0)
                           .above(0)
                           .needed()
                           .describe("centre thickness")
                           .in_editor("Centre thickness"));
    s.params.push_back(number_param("gap", 0)
                           .at_least(0)
                           .because("the air space after the element")
                           .describe("air space to the next element's front vertex (0: cemented)")
                           .in_editor("Air gap after"));
    s.params.push_back(nested_param(ParamKind::Number, "diameter")
                           .above(0)
                           .meaning_auto("the group's")
                           .describe("its diameter"));
    add_decentring_params(s, "element",
                          " (with the elements cemented to it; the axis goes on unmoved)");
    s.params.push_back(nested_param(ParamKind::Object, "material")
                           .needed()
                           .as_written("string or object")
                           .describe("its glass"));
    return s;
}

ElementSpec declare_mirror_element() {
    ElementSpec s{"lens_group mirror", "a lens group mirror", {}, {}};
    s.params.push_back(nested_param(ParamKind::String, "name")
                           .meaning_auto("`\"NAME element i\"`")
                           .describe("shown by lenslab trace"));
    s.params.push_back(nested_param(ParamKind::Object, "mirror")
                           .needed()
                           .as_written("[surface](#surfaces)")
                           .describe("its surface, signed along the group's `axis` as every face"));
    s.params.push_back(number_param("gap", 0)
                           .at_least(0)
                           .because("the distance light travels to the next element")
                           .describe("distance to the next element's vertex, the way the "
                                     "reflected light travels")
                           .in_editor("Gap after"));
    s.params.push_back(nested_param(ParamKind::Number, "diameter")
                           .above(0)
                           .meaning_auto("the group's")
                           .describe("its outer diameter"));
    s.params.push_back(number_param("hole_diameter", 0)
                           .at_least(0)
                           .because("a central hole, as a Cassegrain primary's")
                           .describe("diameter of a central hole (0: none)")
                           .in_editor("Hole diameter"));
    s.params.push_back(number_param("tilt_x", 0)
                           .above(-90)
                           .below(90)
                           .describe("degrees its normal is turned about the local x axis, "
                                     "+z towards -y: a fold; the axis follows the reflection")
                           .in_editor("Tilt about x (degrees)"));
    s.params.push_back(number_param("tilt_y", 0)
                           .above(-90)
                           .below(90)
                           .describe("degrees its normal is turned about the local y axis, "
                                     "+z towards +x (not with `tilt_x`)")
                           .in_editor("Tilt about y (degrees)"));
    s.params.push_back(nested_param(ParamKind::Object, "material")
                           .needed()
                           .as_written("string or object")
                           .describe("its coating (`\"specular\": 1`: a perfect mirror)"));
    return s;
}

// An element is a mirror when it says so, or when it has neither a lens's front nor its
// thickness (then its missing `mirror` is what is reported).
bool is_mirror_element(const json& e) {
    return e.is_object() &&
           (e.contains("mirror") || (!e.contains("front") && !e.contains("thickness")));
}

// Where the elements stand: the vertex light meets next, the axis frame (faces are signed
// along w) and the way light travels along w.
struct Placement {
    Vec3 at;
    Frame frame;
    double travel = 1;
    bool turned = false;  // a tilted mirror has turned the frame: x axes are given explicitly
};

// A mirror element as a mirror object: its vertex on the axis, its surface signed along the
// axis frame (the mirror's own axis then points along it, or turned by its tilt, whichever
// side the light comes from: the mirror reflects on both).
std::shared_ptr<const Shape> group_mirror(const GroupElement& e, const Placement& at,
                                          const Vec3& x_axis) {
    const Frame& f = at.frame;
    const Vec3 hinge = e.move.tilt_x != 0 ? f.u : f.v;
    const double tilt = (e.move.tilt_x != 0 ? e.move.tilt_x : e.move.tilt_y) * M_PI / 180.0;
    MirrorPrescription p;
    p.vertex = at.at;
    p.axis = turned(f.w, hinge, tilt);
    p.x_axis = at.turned || tilt != 0 ? turned(f.u, hinge, tilt) : x_axis;
    p.diameter = e.diameter;
    p.hole_diameter = e.hole_diameter;
    p.surface = read_lens_surface(*e.mirror, e.path + ".mirror", 0.5 * e.diameter);
    check_mirror_surface(*p.surface, e.diameter, e.path + ".mirror");
    return std::make_shared<MirrorSurface>(std::move(p));
}

// After a mirror: the light turns back along the axis, and a tilted mirror turns the axis
// frame by twice its tilt (the reflected axis is then -w, as Zemax's coordinate break, mirror,
// coordinate break and CODE V's BEN leave it).
void reflect_placement(const GroupElement& e, Placement& at) {
    if (e.move.tilt_x != 0 || e.move.tilt_y != 0) {
        const Vec3 hinge = e.move.tilt_x != 0 ? at.frame.u : at.frame.v;
        const double twice =
            2.0 * (e.move.tilt_x != 0 ? e.move.tilt_x : e.move.tilt_y) * M_PI / 180.0;
        at.frame = {turned(at.frame.u, hinge, twice), turned(at.frame.v, hinge, twice),
                    turned(at.frame.w, hinge, twice)};
        at.turned = true;
    }
    at.travel = -at.travel;
    at.at = at.at + at.frame.w * (at.travel * e.gap);
}

// Refuses element `e` and the next one when they overlap anywhere over their common aperture
// (checked alone, each is whole; apart on the axis, they may still cross towards the rim).
// A cemented pair shares one surface and is not checked.
void check_air_space(const GroupElement& e, const LensPrescription& p, const GroupElement& next,
                     const LensPrescription& next_p, double travel) {
    const double a = 0.5 * std::min(e.diameter, next.diameter);
    // Against the axis (after a mirror) the faces that meet are the solids' other two.
    const Clearance c = travel > 0 ? smallest_clearance(*p.back, *next_p.front, e.gap, a)
                                   : smallest_clearance(*next_p.back, *p.front, e.gap, a);
    if (!(c.gap < -1e-12 * std::max(1.0, e.gap))) return;
    const bool symmetric =
        p.back->is_rotationally_symmetric() && next_p.front->is_rotationally_symmetric();
    const std::string where =
        symmetric ? "at " + format_number(std::hypot(c.at.x, c.at.y)) + " from the axis"
                  : "at (x, y) = (" + format_number(c.at.x) + ", " + format_number(c.at.y) + ")";
    throw SceneError(e.path + ".gap",
                     e.path + " and " + next.path + " overlap: " + where + " the front of " +
                         next.path + " lies " + format_number(-c.gap) +
                         " in front of the back of " + e.path + " (the gap must be at least " +
                         format_number(e.gap - c.gap) + " for a common diameter of " +
                         format_number(2 * a) + ", or reduce the diameters)");
}

}  // namespace

const ElementSpec& lens_group_spec() {
    static const ElementSpec spec = declare_group();
    return spec;
}

const ElementSpec& lens_group_element_spec() {
    static const ElementSpec spec = declare_element();
    return spec;
}

const ElementSpec& lens_group_mirror_spec() {
    static const ElementSpec spec = declare_mirror_element();
    return spec;
}

std::vector<SceneObject> read_lens_group(const json& j, const std::string& path,
                                         const MaterialResolver& material) {
    SpecReader r(j, path, lens_group_spec());
    const std::string name = r.string("name", path);
    const std::optional<bool> photon_target = r.boolean("photon_target");
    const Vec3 vertex = r.point("vertex");
    const Vec3 axis = r.unit_vector("axis");
    const double group_diameter = r.real("diameter");
    const Vec3 x_axis = r.has("x_axis") ? r.unit_vector("x_axis") : Vec3{};
    if (r.has("x_axis") && length(cross(x_axis, axis)) < 1e-9) {
        throw SceneError(r.child_path("x_axis"), "must not be parallel to the axis");
    }

    const json& list = r.require("elements");
    const std::string list_path = r.child_path("elements");
    if (!list.is_array() || list.empty()) {
        throw SceneError(list_path, "must be a non-empty array of elements, front to back");
    }
    check_count(list.size(), kMaxObjects, list_path, "elements");
    std::vector<GroupElement> specs(list.size());
    for (size_t i = 0; i < list.size(); ++i) {
        GroupElement& e = specs[i];
        e.path = list_path + "[" + std::to_string(i) + "]";
        const bool is_mirror = is_mirror_element(list[i]);
        SpecReader er(list[i], e.path,
                      is_mirror ? lens_group_mirror_spec() : lens_group_element_spec());
        e.name = er.string("name", name + " element " + std::to_string(i + 1));
        e.gap = er.real("gap");
        e.diameter = er.has("diameter") ? er.real("diameter") : group_diameter;
        const bool last = i + 1 == list.size();
        if (is_mirror) {
            e.mirror = &er.require("mirror");
            e.hole_diameter = er.real("hole_diameter");
            e.move.tilt_x = er.real("tilt_x");
            e.move.tilt_y = er.real("tilt_y");
            if (e.move.tilt_x != 0 && e.move.tilt_y != 0) {
                throw SceneError(er.child_path("tilt_y"),
                                 "a mirror folds the axis about one of its axes: give tilt_x or "
                                 "tilt_y, not both");
            }
            if (!(e.hole_diameter < e.diameter)) {
                throw SceneError(er.child_path("hole_diameter"),
                                 "must be less than the mirror's diameter (" +
                                     format_number(e.diameter) + "), got " +
                                     format_number(e.hole_diameter));
            }
            if (!last && !(e.gap > 0)) {
                throw SceneError(er.child_path("gap"),
                                 "a mirror needs a gap to the next element (light cannot pass "
                                 "from a mirror straight into a glass)");
            }
            e.material = material(er, e.name);
            continue;
        }
        e.thickness = er.real("thickness");
        e.move.decenter_x = er.real("decenter_x");
        e.move.decenter_y = er.real("decenter_y");
        e.move.tilt_x = er.real("tilt_x");
        e.move.tilt_y = er.real("tilt_y");
        e.move.tilt_z = er.real("tilt_z");
        if (e.move.moves() && i > 0 && !specs[i - 1].mirror && !specs[i - 1].back) {
            throw SceneError(e.path,
                             "is cemented to " + specs[i - 1].path +
                                 ": decentre or tilt the cemented elements on the first of them");
        }
        e.front = &er.require("front");
        e.back = er.find("back");
        const bool mirror_next = !last && is_mirror_element(list[i + 1]);
        if (!e.back && (last || e.gap > 0 || mirror_next)) {
            throw SceneError(e.path,
                             last ? "the last element needs a back surface"
                                  : "an element followed by an air gap needs a back surface");
        }
        if (e.back && !last && e.gap == 0) {
            throw SceneError(er.child_path("back"),
                             mirror_next ? "an element before a mirror needs a gap to it (a "
                                           "mirror on a glass face is not yet supported)"
                                         : "an element with no gap after it is cemented: its "
                                           "back is the next element's front (give a gap, or "
                                           "leave out back)");
        }
        e.material = material(er, e.name);
    }

    std::vector<SceneObject> objects;
    std::optional<LensPrescription> previous;  // the element before, while not cemented to it
    // The decentre and tilts of a cemented run, while `moving`.
    RigidMotion motion{};
    bool moving = false;
    Placement at;
    at.at = vertex;
    const Vec3 x_perp = x_axis - axis * dot(x_axis, axis);
    at.frame = length(x_perp) > 1e-12
                   ? Frame{normalize(x_perp), cross(axis, normalize(x_perp)), axis}
                   : Frame::from_axis(axis);
    for (size_t i = 0; i < specs.size(); ++i) {
        const GroupElement& e = specs[i];
        SceneObject o;
        o.name = e.name;
        o.group = name;
        o.group_axis = axis;
        o.group_vertex = vertex;
        o.material = e.material;
        o.photon_target = photon_target;
        if (e.mirror) {
            o.type = ObjectType::Mirror;
            o.shape = group_mirror(e, at, x_axis);
            objects.push_back(std::move(o));
            previous.reset();
            reflect_placement(e, at);
            continue;
        }
        const double travel = at.travel;
        const json& back = e.back ? *e.back : *specs[i + 1].front;
        const std::string back_path = e.back ? e.path + ".back" : specs[i + 1].path + ".front";
        LensPrescription p;
        p.centre = at.at + at.frame.w * (travel * 0.5 * e.thickness);
        p.axis = at.frame.w;
        p.thickness = e.thickness;
        p.diameter = e.diameter;
        // Faces are signed along the axis whichever way light crosses them; against it, the
        // face met first is the solid's back.
        const auto front = read_lens_surface(*e.front, e.path + ".front", 0.5 * e.diameter);
        const auto rear = read_lens_surface(back, back_path, 0.5 * e.diameter);
        p.front = travel > 0 ? front : rear;
        p.back = travel > 0 ? rear : front;
        p.x_axis = at.turned ? at.frame.u : x_axis;
        if (auto problem = LensSolid::check_prescription(p)) {
            const bool first_face = (problem->field == "front") == (travel > 0);
            const std::string field = problem->field == "x_axis" ? r.child_path("x_axis")
                                      : problem->field == "front" || problem->field == "back"
                                          ? (first_face ? e.path + ".front" : back_path)
                                          : e.path + "." + problem->field;
            throw SceneError(field, problem->reason);
        }
        // Air spaces are checked as designed, before the decentres and tilts.
        if (previous) check_air_space(specs[i - 1], *previous, e, p, travel);
        previous.reset();
        if (e.back) previous = p;
        if (e.move.moves()) {
            motion = rigid_motion(e.move, at.at, at.frame);
            moving = true;
        }
        if (moving) {
            p.x_axis = motion.direction(at.frame.u);
            p.centre = motion.point(p.centre);
            p.axis = motion.direction(p.axis);
        }
        if (e.back) moving = false;
        o.type = ObjectType::Lens;
        o.shape = std::make_shared<LensSolid>(std::move(p));
        objects.push_back(std::move(o));
        at.at = at.at + at.frame.w * (travel * (e.thickness + e.gap));
    }
    return objects;
}

}  // namespace lenslab
