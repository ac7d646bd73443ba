// The toroidal lens surface (`"shape": "toroidal"`): a y curve (conic plus even terms) turned
// about an axis parallel to y, declared and read here, one entry of surface_shapes.cpp's table.

#include "geometry/lens/toroidal_surface.h"
#include "scene/surface_shape_params.h"
#include "scene/surface_shapes.h"

namespace lenslab {

namespace {

const ElementSpec& toroidal_shape_spec() {
    static const ElementSpec spec = declare_surface_shape(
        "toroidal",
        {number_param("radius", 0)
             .needed()
             .describe("vertex radius of the y-z curve (0: straight)")
             .in_editor("radius of the y curve (0: straight)"),
         conic_constant_param(),
         asphere_coefficients_param(0, "the y curve's [A4, A6, ..., A16]",
                                    "y curve A4, A6, ... A16"),
         number_param("radius_of_rotation", 0)
             .needed()
             .describe("distance from the vertex to the axis (parallel to y) the curve "
                       "turns about, signed as a radius (0: none, a cylinder)")
             .in_editor("radius of rotation (0: none)")},
        {{"shape", "toroidal"}, {"radius", 2}, {"radius_of_rotation", 3}});
    return spec;
}

}  // namespace

SurfaceShapeEntry toroidal_surface_shape() {
    return {"toroidal", toroidal_shape_spec,
            [](SpecReader& r, double) -> std::shared_ptr<const LensSurface> {
                return std::make_shared<ToroidalSurface>(
                    r.real("radius"), r.real("k"),
                    read_number_array(r, "coefficients", " [A4, A6, ..., A16]"),
                    r.real("radius_of_rotation"));
            },
            [](const nlohmann::json& old, double diameter) {
                const double radius = kept_radius(old, diameter);
                return nlohmann::json{{"shape", "toroidal"},
                                      {"radius", radius},
                                      {"radius_of_rotation", radius},
                                      {"k", kept_number(old, "k", 0)}};
            }};
}

}  // namespace lenslab
