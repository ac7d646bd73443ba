// The lens surface shapes of revolution in closed form: flat, sphere, conic and even asphere
// (each an entry of surface_shapes.cpp's table).

#include "geometry/lens/asphere_surface.h"
#include "geometry/lens/conic_surface.h"
#include "geometry/lens/flat_surface.h"
#include "geometry/lens/spherical_surface.h"
#include "scene/surface_shape_params.h"
#include "scene/surface_shapes.h"

namespace lenslab {

namespace {

const std::string kCoefficientsWhat = " [A4, A6, ..., A16]";

const ElementSpec& flat_shape_spec() {
    static const ElementSpec spec = declare_surface_shape("flat", {}, {{"shape", "flat"}});
    return spec;
}

const ElementSpec& sphere_shape_spec() {
    static const ElementSpec spec = declare_surface_shape("sphere", {vertex_radius_param()},
                                                          {{"shape", "sphere"}, {"radius", 2}});
    return spec;
}

const ElementSpec& conic_shape_spec() {
    static const ElementSpec spec =
        declare_surface_shape("conic", {vertex_radius_param(), conic_constant_param().needed()},
                              {{"shape", "conic"}, {"radius", 2}, {"k", 0}});
    return spec;
}

const ElementSpec& asphere_shape_spec() {
    static const ElementSpec spec = declare_surface_shape(
        "asphere",
        {vertex_radius_param(), conic_constant_param(),
         asphere_coefficients_param(1, "[A4, A6, ..., A16]", "A4, A6, ... A16").needed()},
        {{"shape", "asphere"}, {"radius", 2}, {"coefficients", {0.001}}});
    return spec;
}

}  // namespace

SurfaceShapeEntry flat_surface_shape() {
    return {"flat", flat_shape_spec,
            [](SpecReader&, double) -> std::shared_ptr<const LensSurface> {
                return std::make_shared<FlatSurface>();
            },
            [](const nlohmann::json&, double) {
                return nlohmann::json{{"shape", "flat"}};
            }};
}

SurfaceShapeEntry sphere_surface_shape() {
    return {"sphere", sphere_shape_spec,
            [](SpecReader& r, double) -> std::shared_ptr<const LensSurface> {
                return std::make_shared<SphericalSurface>(read_vertex_radius(r));
            },
            [](const nlohmann::json& old, double diameter) {
                return nlohmann::json{{"shape", "sphere"}, {"radius", kept_radius(old, diameter)}};
            }};
}

SurfaceShapeEntry conic_surface_shape() {
    return {"conic", conic_shape_spec,
            [](SpecReader& r, double) -> std::shared_ptr<const LensSurface> {
                const double radius = read_vertex_radius(r);
                return std::make_shared<ConicSurface>(radius, r.real("k"));
            },
            [](const nlohmann::json& old, double diameter) {
                return nlohmann::json{{"shape", "conic"},
                                      {"radius", kept_radius(old, diameter)},
                                      {"k", kept_number(old, "k", 0)}};
            }};
}

SurfaceShapeEntry asphere_surface_shape() {
    return {"asphere", asphere_shape_spec,
            [](SpecReader& r, double) -> std::shared_ptr<const LensSurface> {
                const double radius = read_vertex_radius(r);
                const double k = r.real("k");
                return std::make_shared<AsphereSurface>(
                    radius, k, read_number_array(r, "coefficients", kCoefficientsWhat));
            },
            [](const nlohmann::json& old, double diameter) {
                nlohmann::json s{{"shape", "asphere"},
                                 {"radius", kept_radius(old, diameter)},
                                 {"k", kept_number(old, "k", 0)}};
                s["coefficients"] = old.is_object() && old.contains("coefficients")
                                        ? old["coefficients"]
                                        : nlohmann::json::array({0.0});
                return s;
            }};
}

}  // namespace lenslab
