#include "scene/mirror_json.h"

#include <cmath>

#include "geometry/lens/mirror_surface.h"
#include "scene/object_spec.h"
#include "scene/surface_json.h"

namespace lenslab {

namespace {

ElementSpec declare_mirror() {
    ElementSpec s = shape_spec("mirror", "a mirror", false);
    s.params.push_back(point_param("vertex").describe("the surface's vertex").in_editor("Vertex"));
    s.params.push_back(direction_param("axis")
                           .describe("the side the mirror faces; a surface of positive radius "
                                     "(centre of curvature on that side) is concave towards it")
                           .in_editor("Axis (faces)"));
    s.params.push_back(nested_param(ParamKind::Object, "surface")
                           .needed()
                           .as_written("[surface](#surfaces)")
                           .describe("its shape, as a lens's face"));
    s.params.push_back(number_param("diameter", 0)
                           .above(0)
                           .needed()
                           .describe("outer diameter")
                           .in_editor("Diameter"));
    s.params.push_back(number_param("hole_diameter", 0)
                           .at_least(0)
                           .because("a central hole, as a Cassegrain primary's")
                           .describe("diameter of a central hole (0: none); less than `diameter`")
                           .in_editor("Hole diameter"));
    s.params.push_back(nested_param(ParamKind::Direction, "x_axis")
                           .meaning_auto("a fixed perpendicular to `axis`")
                           .describe("where the surface's local x axis points (for a sag in x "
                                     "and y)")
                           .in_editor("Local x axis"));
    s.example = nlohmann::json::parse(
        R"json({"type": "mirror", "name": "paraboloid", "vertex": [0, 0, 0], "axis": [0, 0, 1], "surface": {"shape": "conic", "radius": 4, "k": -1}, "diameter": 1, "material": {"color": 0, "specular": 1}})json");
    return s;
}

}  // namespace

const ElementSpec& mirror_spec() {
    static const ElementSpec spec = declare_mirror();
    return spec;
}

void check_mirror_surface(const LensSurface& surface, double diameter, const std::string& path) {
    const double a = 0.5 * diameter;
    if (a > surface.max_semi_diameter()) {
        throw SceneError(path, surface.describe() + " cannot span the diameter " +
                                   format_number(diameter) + " (its largest is " +
                                   format_number(2 * surface.max_semi_diameter()) + ")");
    }
    // A typed formula may be undefined somewhere on the disc: refused, not rendered with holes.
    for (const DiscPoint& q : disc_sample_points(a, surface.is_rotationally_symmetric())) {
        if (std::isfinite(surface.sag_xy(q.x, q.y))) continue;
        const std::string why = surface.why_undefined(q.x, q.y);
        throw SceneError(path, "sag undefined at (x, y) = (" + format_number(q.x) + ", " +
                                   format_number(q.y) + ") inside the diameter" +
                                   (why.empty() ? "" : " (" + why + ")"));
    }
}

std::shared_ptr<const Shape> read_mirror(SpecReader& r) {
    MirrorPrescription p;
    p.vertex = r.point("vertex");
    p.axis = r.unit_vector("axis");
    p.diameter = r.real("diameter");
    p.hole_diameter = r.real("hole_diameter");
    if (!(p.hole_diameter < p.diameter)) {
        throw SceneError(r.child_path("hole_diameter"), "must be less than diameter (" +
                                                            format_number(p.diameter) + "), got " +
                                                            format_number(p.hole_diameter));
    }
    if (r.has("x_axis")) {
        p.x_axis = r.unit_vector("x_axis");
        if (length(cross(p.x_axis, p.axis)) < 1e-9) {
            throw SceneError(r.child_path("x_axis"), "must not be parallel to the axis");
        }
    }
    p.surface = read_lens_surface(r.require("surface"), r.child_path("surface"), 0.5 * p.diameter);
    check_mirror_surface(*p.surface, p.diameter, r.child_path("surface"));
    return std::make_shared<MirrorSurface>(std::move(p));
}

}  // namespace lenslab
