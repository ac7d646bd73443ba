// The polynomial freeform lens surfaces: `"xy_polynomial"` (Zemax's Extended Polynomial terms)
// and `"zernike"` (Noll-ordered Zernike terms), each an even asphere base plus a polynomial in
// x / R_n and y / R_n; declared and read here, two entries of surface_shapes.cpp's table.

#include "geometry/lens/polynomial_sag_surface.h"
#include "scene/surface_shape_params.h"
#include "scene/surface_shapes.h"

namespace lenslab {

namespace {

// The base and normalisation radius both shapes share, then their own terms.
std::vector<ParamSpec> freeform_params(ParamSpec terms) {
    return {number_param("radius", 0)
                .needed()
                .describe("R, the base's vertex radius (0: a flat base)")
                .in_editor("base radius (0: flat)"),
            conic_constant_param(),
            asphere_coefficients_param(0, "the base's [A4, A6, ..., A16]", "base A4, A6, ... A16"),
            number_param("normalization_radius", 0)
                .needed()
                .above(0)
                .describe("R_n: the terms are in x / R_n and y / R_n")
                .in_editor("normalization radius"),
            std::move(terms)};
}

const ElementSpec& xy_polynomial_shape_spec() {
    static const ElementSpec spec = declare_surface_shape(
        "xy_polynomial",
        freeform_params(nested_param(ParamKind::Array, "terms")
                            .needed()
                            .holding_numbers(1, 230)
                            .describe("coefficients of x, y, x^2, xy, y^2, x^3, x^2 y, ... (by "
                                      "degree, then by the power of y; Zemax's order) in x / R_n "
                                      "and y / R_n")
                            .in_editor("terms x, y, x², xy, y², x³, ...")),
        {{"shape", "xy_polynomial"},
         {"radius", 0},
         {"normalization_radius", 1},
         {"terms", {0, 0, 0.01, 0, 0.02}}});
    return spec;
}

const ElementSpec& zernike_shape_spec() {
    static const ElementSpec spec = declare_surface_shape(
        "zernike",
        freeform_params(nested_param(ParamKind::Array, "zernike")
                            .needed()
                            .holding_numbers(1, 231)
                            .describe("[Z1, Z2, ...]: Noll-ordered (Zemax's Standard) Zernike "
                                      "terms on the disc of radius R_n")
                            .in_editor("Zernike Z1, Z2, ... (Noll)")),
        {{"shape", "zernike"},
         {"radius", 0},
         {"normalization_radius", 1},
         {"zernike", {0, 0, 0, 0.01}}});
    return spec;
}

std::shared_ptr<const LensSurface> read_freeform(SpecReader& r, XyPolynomial terms,
                                                 const std::string& name) {
    return std::make_shared<PolynomialSagSurface>(
        r.real("radius"), r.real("k"), read_number_array(r, "coefficients", " [A4, A6, ..., A16]"),
        r.real("normalization_radius"), std::move(terms), name);
}

nlohmann::json start_freeform(const std::string& shape, const std::string& terms_key,
                              const nlohmann::json& old, double diameter) {
    nlohmann::json s{
        {"shape", shape}, {"radius", kept_radius(old, diameter)}, {"k", kept_number(old, "k", 0)}};
    if (old.is_object() && old.contains("coefficients")) s["coefficients"] = old["coefficients"];
    s["normalization_radius"] = diameter / 2;
    s[terms_key] = nlohmann::json::array({0.0});
    return s;
}

}  // namespace

SurfaceShapeEntry xy_polynomial_surface_shape() {
    return {"xy_polynomial", xy_polynomial_shape_spec,
            [](SpecReader& r, double) {
                return read_freeform(r, xy_polynomial_from_terms(read_number_array(r, "terms")),
                                     "XY polynomial");
            },
            [](const nlohmann::json& old, double diameter) {
                return start_freeform("xy_polynomial", "terms", old, diameter);
            }};
}

SurfaceShapeEntry zernike_surface_shape() {
    return {"zernike", zernike_shape_spec,
            [](SpecReader& r, double) {
                return read_freeform(r, zernike_sag_polynomial(read_number_array(r, "zernike")),
                                     "Zernike sag");
            },
            [](const nlohmann::json& old, double diameter) {
                return start_freeform("zernike", "zernike", old, diameter);
            }};
}

}  // namespace lenslab
