// The biconic lens surface (`"shape": "biconic"`): a conic in x and another in y, declared and
// read here, one entry of surface_shapes.cpp's table.

#include "geometry/lens/biconic_surface.h"
#include "scene/surface_shape_params.h"
#include "scene/surface_shapes.h"

namespace lenslab {

namespace {

const ElementSpec& biconic_shape_spec() {
    static const ElementSpec spec = declare_surface_shape(
        "biconic",
        {number_param("radius_x", 0)
             .needed()
             .describe("vertex radius of the x-z section (0: straight, a cylinder)")
             .in_editor("radius in x (0: straight)"),
         number_param("radius_y", 0)
             .needed()
             .describe("vertex radius of the y-z section (0: straight)")
             .in_editor("radius in y (0: straight)"),
         number_param("k_x", 0).describe("conic constant in x").in_editor("conic k in x"),
         number_param("k_y", 0).describe("conic constant in y").in_editor("conic k in y")},
        {{"shape", "biconic"}, {"radius_x", 0}, {"radius_y", 2}});
    return spec;
}

}  // namespace

SurfaceShapeEntry biconic_surface_shape() {
    return {"biconic", biconic_shape_spec,
            [](SpecReader& r, double) -> std::shared_ptr<const LensSurface> {
                return std::make_shared<BiconicSurface>(r.real("radius_x"), r.real("radius_y"),
                                                        r.real("k_x"), r.real("k_y"));
            },
            [](const nlohmann::json& old, double diameter) {
                const double radius = kept_radius(old, diameter), k = kept_number(old, "k", 0);
                return nlohmann::json{{"shape", "biconic"},
                                      {"radius_x", radius},
                                      {"radius_y", radius},
                                      {"k_x", k},
                                      {"k_y", k}};
            }};
}

}  // namespace lenslab
