#include "scene/object_types.h"

#include "geometry/implicit_solid.h"
#include "geometry/lens/lens_solid.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "math/rigid_motion.h"
#include "scene/box_corners_json.h"
#include "scene/box_json.h"
#include "scene/lens_group_json.h"
#include "scene/mesh_json.h"
#include "scene/mirror_json.h"
#include "scene/object_spec.h"
#include "scene/planar_json.h"
#include "scene/spec_reader.h"
#include "scene/surface_json.h"

namespace lenslab {

namespace {

using nlohmann::json;

// A length one form requires: absent is "missing (required)", as for any required key.
double form_length(SpecReader& r, const std::string& key) {
    (void)r.require(key);
    return r.real(key);
}

std::shared_ptr<const Shape> read_lens(SpecReader& r) {
    const Vec3 centre = r.point("center");
    const Vec3 axis = r.unit_vector("axis");
    LensPrescription p;
    const bool report_form = r.has("curvature_radius") || r.has("aperture_radius");
    const bool prescription_form =
        r.has("thickness") || r.has("diameter") || r.has("front") || r.has("back");
    if (!report_form && !prescription_form) {
        throw SceneError(r.path(),
                         "a lens needs either curvature_radius and aperture_radius (the report's "
                         "form) or thickness, diameter, front and back (a prescription)");
    }
    if (report_form) {
        // A decentre or tilt of 0 (the declaration's default, written out) moves nothing.
        const auto moves = [&r](const char* key) {
            for (const char* move : {"decenter_x", "decenter_y", "tilt_x", "tilt_y", "tilt_z"}) {
                if (std::string(key) == move) return r.real(key) != 0;
            }
            return true;
        };
        for (const char* key : {"thickness", "diameter", "front", "back", "x_axis", "decenter_x",
                                "decenter_y", "tilt_x", "tilt_y", "tilt_z"}) {
            if (r.has(key) && moves(key)) {
                throw SceneError(r.child_path(key),
                                 "belongs to the prescription form; the report form "
                                 "(curvature_radius, aperture_radius) cannot take it");
            }
        }
        const double radius = form_length(r, "curvature_radius");
        const double aperture = form_length(r, "aperture_radius");
        if (aperture > radius) {
            throw SceneError(r.child_path("aperture_radius"),
                             "two spheres of radius " + format_number(radius) +
                                 " cannot meet in a circle of radius " + format_number(aperture) +
                                 " (must be <= curvature_radius)");
        }
        p = LensSolid::symmetric_biconvex(centre, axis, radius, aperture);
    } else {
        p.centre = centre;
        p.axis = axis;
        p.thickness = form_length(r, "thickness");
        p.diameter = form_length(r, "diameter");
        p.front = read_lens_surface(r.require("front"), r.child_path("front"), 0.5 * p.diameter);
        p.back = read_lens_surface(r.require("back"), r.child_path("back"), 0.5 * p.diameter);
        if (r.has("x_axis")) p.x_axis = r.unit_vector("x_axis");
    }
    if (auto problem = LensSolid::check_prescription(p)) {
        throw SceneError(r.child_path(problem->field), problem->reason);
    }
    const Decentring move{r.real("decenter_x"), r.real("decenter_y"), r.real("tilt_x"),
                          r.real("tilt_y"), r.real("tilt_z")};
    if (move.moves()) {
        // Pivoting on the front vertex, as a lens group's element does.
        const Frame frame = lens_frame(p);
        p.designed_axis = p.axis;
        p.designed_vertex = p.centre - p.axis * (0.5 * p.thickness);
        const RigidMotion motion = rigid_motion(move, p.designed_vertex, frame);
        p.centre = motion.point(p.centre);
        p.axis = motion.direction(p.axis);
        p.x_axis = motion.direction(frame.u);
    }
    return std::make_shared<LensSolid>(std::move(p));
}

std::shared_ptr<const Shape> read_triangle(SpecReader& r) {
    const json& v = r.require("vertices");
    const std::string vpath = r.child_path("vertices");
    if (!v.is_array() || v.size() != 3) {
        throw SceneError(vpath, "must be an array of 3 points [[x,y,z], [x,y,z], [x,y,z]]");
    }
    Vec3 p[3];
    for (int i = 0; i < 3; ++i) p[i] = JsonObjectReader::as_vec3(v[i], element_path(vpath, i));
    // Relative to the edges, so tiny triangles in a large-unit scene are fine: the sine of
    // the angle at vertex 0 must not vanish.
    const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    if (!(length(cross(e1, e2)) > 1e-10 * length(e1) * length(e2))) {
        throw SceneError(vpath, "the three vertices are collinear (zero area)");
    }
    return std::make_shared<Triangle>(p[0], p[1], p[2]);
}

std::shared_ptr<const Shape> read_implicit(SpecReader& r) {
    const std::string formula = r.text("formula");
    const Aabb box = read_box_corners(r.require("bounds"), r.child_path("bounds"));
    const int steps = static_cast<int>(r.whole("steps"));
    const Vec3 centre = r.point("center");
    std::shared_ptr<ImplicitSolid> solid;
    try {
        solid =
            std::make_shared<ImplicitSolid>(formula, box, steps, centre, r.child_path("formula"));
    } catch (const FormulaError& e) {
        throw SceneError(r.child_path("formula"), e.message());
    }
    if (auto problem = solid->check_values()) throw SceneError(r.child_path("formula"), *problem);
    return solid;
}

std::shared_ptr<const Shape> read_sphere(SpecReader& r) {
    return std::make_shared<Sphere>(r.point("center"), r.real("radius"));
}

// A declared kind's reader, given the SpecReader read_object made for it.
template <std::shared_ptr<const Shape> (*Read)(SpecReader&)>
std::shared_ptr<const Shape> declared(SpecReader& r, const std::string&) {
    return Read(r);
}

std::vector<ObjectTypeEntry> make_table() {
    // clang-format off
    return {
        //  type          ObjectType             declaration        reader                         detector size   emit  mesh check
        {"sphere",     ObjectType::Sphere,    &sphere_spec,     &declared<read_sphere>,       nullptr,     true,  false},
        {"triangle",   ObjectType::Triangle,  &triangle_spec,   &declared<read_triangle>,     "vertices",  false, false},
        {"disc",       ObjectType::Disc,      &disc_spec,       &declared<read_disc>,         "radius",    false, false},
        {"rectangle",  ObjectType::Rectangle, &rectangle_spec,  &declared<read_rectangle>,    "size",      false, false},
        {"lens",       ObjectType::Lens,      &lens_spec,       &declared<read_lens>,         nullptr,     false, false},
        {"lens_group", ObjectType::Lens,      &lens_group_spec, nullptr,                      nullptr,     false, false},  // read by scene_from_json
        {"mesh",       ObjectType::Mesh,      &mesh_spec,       &read_mesh,                  nullptr,     false, true},
        {"prism",      ObjectType::Mesh,      &prism_spec,      &declared<read_prism>,        nullptr,     false, false},  // closed by construction
        {"implicit",   ObjectType::Implicit,  &implicit_spec,   &declared<read_implicit>,     nullptr,     false, false},
        {"box",        ObjectType::Mesh,      &box_spec,        &declared<read_box>,          nullptr,     false, false},  // closed by construction
        {"mirror",     ObjectType::Mirror,    &mirror_spec,     &declared<read_mirror>,       nullptr,     false, false},
    };
    // clang-format on
}

}  // namespace

const std::vector<ObjectTypeEntry>& object_types() {
    static const std::vector<ObjectTypeEntry> table = make_table();
    return table;
}

const ObjectTypeEntry* find_object_type(const std::string& name) {
    for (const ObjectTypeEntry& e : object_types()) {
        if (e.name == name) return &e;
    }
    return nullptr;
}

std::string unknown_object_type_message(const std::string& name) {
    std::vector<std::string> names;
    std::string known;
    for (const ObjectTypeEntry& e : object_types()) {
        names.push_back(e.name);
        known += (known.empty() ? "" : ", ") + e.name;
    }
    // Read by scene_from_json beside lens_group (a file's lens, not a declared shape).
    names.push_back("lens_file");
    known += ", lens_file";
    const std::string best = closest_match(name, names);
    return "unknown object type '" + name + "' (known: " + known +
           (best.empty() ? "" : "; did you mean '" + best + "'?") + ")";
}

}  // namespace lenslab
