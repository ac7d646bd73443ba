#include "scene/surface_json.h"

#include <algorithm>

#include "geometry/lens/asphere_surface.h"
#include "geometry/lens/biconic_surface.h"
#include "geometry/lens/conic_surface.h"
#include "geometry/lens/flat_surface.h"
#include "geometry/lens/polynomial_sag_surface.h"
#include "geometry/lens/sag_formula_surface.h"
#include "geometry/lens/spherical_surface.h"
#include "geometry/lens/toroidal_surface.h"
#include "scene/json_reader.h"
#include "scene/spec_reader.h"

namespace lenslab {

const std::vector<std::string> kSurfaceShapeNames{
    "flat", "sphere", "conic", "asphere", "biconic", "toroidal", "xy_polynomial", "zernike", "sag"};

namespace {

ParamSpec shape_param(const std::string& shape) {
    return string_param("shape", "").needed().describe("\"" + shape + "\"");
}

ParamSpec radius_param() {
    return number_param("radius", 0)
        .needed()
        .describe("R, the vertex radius of curvature; not 0 (signed, see the sign convention)")
        .in_editor("radius (signed)");
}

ParamSpec k_param() {
    return number_param("k", 0).describe("the conic constant").in_editor("conic constant k");
}

// The even asphere base and normalisation radius of the polynomial freeforms.
std::vector<ParamSpec> freeform_base(ParamSpec terms) {
    return {number_param("radius", 0)
                .needed()
                .describe("R, the base's vertex radius (0: a flat base)")
                .in_editor("base radius (0: flat)"),
            k_param(),
            nested_param(ParamKind::Array, "coefficients")
                .as_written("array of 0 to 7 numbers")
                .describe("the base's [A4, A6, ..., A16]"),
            number_param("normalization_radius", 0)
                .needed()
                .above(0)
                .describe("R_n: the terms are in x / R_n and y / R_n")
                .in_editor("normalization radius"),
            std::move(terms)};
}

ElementSpec declare(const std::string& shape, std::vector<ParamSpec> own) {
    // No phrase: a key no shape takes is an "unknown key", as in any nested object.
    ElementSpec s{shape + " surface", "", {shape_param(shape)}, {}};
    for (ParamSpec& p : own) s.params.push_back(std::move(p));
    return s;
}

std::vector<ElementSpec> declare_surfaces() {
    return {
        declare("flat", {}),
        declare("sphere", {radius_param()}),
        declare("conic", {radius_param(), k_param().needed()}),
        declare("asphere", {radius_param(), k_param(),
                            nested_param(ParamKind::Array, "coefficients")
                                .needed()
                                .as_written("array of 1 to 7 numbers")
                                .describe("[A4, A6, ..., A16]")}),
        declare("biconic",
                {number_param("radius_x", 0)
                     .needed()
                     .describe("vertex radius of the x-z section (0: straight, a cylinder)")
                     .in_editor("radius in x (0: straight)"),
                 number_param("radius_y", 0)
                     .needed()
                     .describe("vertex radius of the y-z section (0: straight)")
                     .in_editor("radius in y (0: straight)"),
                 number_param("k_x", 0).describe("conic constant in x").in_editor("conic k in x"),
                 number_param("k_y", 0).describe("conic constant in y").in_editor("conic k in y")}),
        declare("toroidal",
                {number_param("radius", 0)
                     .needed()
                     .describe("vertex radius of the y-z curve (0: straight)")
                     .in_editor("radius of the y curve (0: straight)"),
                 k_param(),
                 nested_param(ParamKind::Array, "coefficients")
                     .as_written("array of 0 to 7 numbers")
                     .describe("the y curve's [A4, A6, ..., A16]"),
                 number_param("radius_of_rotation", 0)
                     .needed()
                     .describe("distance from the vertex to the axis (parallel to y) the curve "
                               "turns about, signed as a radius (0: none, a cylinder)")
                     .in_editor("radius of rotation (0: none)")}),
        declare("xy_polynomial",
                freeform_base(nested_param(ParamKind::Array, "terms")
                                  .needed()
                                  .as_written("array of 1 to 230 numbers")
                                  .describe("coefficients of x, y, x^2, xy, y^2, x^3, x^2 y, ... "
                                            "(by degree, then by the power of y; Zemax's order) "
                                            "in x / R_n and y / R_n"))),
        declare("zernike",
                freeform_base(nested_param(ParamKind::Array, "zernike")
                                  .needed()
                                  .as_written("array of 1 to 231 numbers")
                                  .describe("[Z1, Z2, ...]: Noll-ordered (Zemax's Standard) "
                                            "Zernike terms on the disc of radius R_n"))),
        declare("sag", {string_param("formula", "")
                            .needed()
                            .describe("z(r) or z(x, y), 0 on the axis")
                            .in_editor("z(r) or z(x, y)")}),
    };
}

// Every key some shape takes.
std::vector<std::string> all_surface_keys() {
    std::vector<std::string> out;
    for (const ElementSpec& s : surface_specs()) {
        for (const std::string& key : s.keys()) {
            if (std::find(out.begin(), out.end(), key) == out.end()) out.push_back(key);
        }
    }
    return out;
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

double vertex_radius(SpecReader& r) {
    const double radius = r.real("radius");
    if (radius == 0) {
        throw SceneError(r.child_path("radius"),
                         "must not be 0 (use {\"shape\": \"flat\"} for a plane)");
    }
    return radius;
}

std::vector<double> read_coefficients(JsonObjectReader& r, bool may_be_empty = false) {
    if (may_be_empty && !r.has("coefficients")) return {};
    const nlohmann::json& j = r.require("coefficients");
    const std::string path = r.child_path("coefficients");
    if (!j.is_array() || (j.empty() && !may_be_empty) ||
        j.size() > AsphereSurface::kMaxCoefficients) {
        throw SceneError(path, std::string("must be an array of ") + (may_be_empty ? "0" : "1") +
                                   " to 7 numbers [A4, A6, ..., A16]");
    }
    std::vector<double> out;
    for (size_t i = 0; i < j.size(); ++i) {
        out.push_back(JsonObjectReader::as_number(j[i], path + "[" + std::to_string(i) + "]"));
    }
    return out;
}

std::vector<double> read_numbers(JsonObjectReader& r, const std::string& key, size_t most,
                                 const std::string& what) {
    const nlohmann::json& j = r.require(key);
    const std::string path = r.child_path(key);
    if (!j.is_array() || j.empty() || j.size() > most) {
        throw SceneError(path, "must be an array of 1 to " + std::to_string(most) + " " + what);
    }
    std::vector<double> out;
    for (size_t i = 0; i < j.size(); ++i) {
        out.push_back(JsonObjectReader::as_number(j[i], path + "[" + std::to_string(i) + "]"));
    }
    return out;
}

}  // namespace

const std::vector<ElementSpec>& surface_specs() {
    static const std::vector<ElementSpec> specs = declare_surfaces();
    return specs;
}

const ElementSpec* surface_spec(const std::string& shape) {
    for (const ElementSpec& s : surface_specs()) {
        if (s.name == shape + " surface") return &s;
    }
    return nullptr;
}

const ElementSpec& flat_surface_spec() { return *surface_spec("flat"); }
const ElementSpec& sphere_surface_spec() { return *surface_spec("sphere"); }
const ElementSpec& conic_surface_spec() { return *surface_spec("conic"); }
const ElementSpec& asphere_surface_spec() { return *surface_spec("asphere"); }
const ElementSpec& sag_surface_spec() { return *surface_spec("sag"); }

std::shared_ptr<const LensSurface> read_lens_surface(const nlohmann::json& j,
                                                     const std::string& path,
                                                     double semi_diameter) {
    static const std::vector<std::string> any_shape = all_surface_keys();
    JsonObjectReader any(j, path, any_shape);
    const std::string shape = any.string("shape");
    const ElementSpec* spec = surface_spec(shape);
    if (!spec) {
        throw SceneError(any.child_path("shape"), "unknown surface shape '" + shape + "' (known: " +
                                                      joined(kSurfaceShapeNames) + ")");
    }
    std::vector<std::string> takes = spec->keys();
    takes.erase(takes.begin());  // shape
    for (const std::string& key : any_shape) {
        if (any.has(key) && !spec->find(key)) {
            throw SceneError(any.child_path(key),
                             with_article(shape) + " surface has no " + key +
                                 (takes.empty() ? "" : " (it takes " + joined(takes) + ")"));
        }
    }
    // Only the shape's own keys are left: read them as declared.
    SpecReader r(j, path, *spec);
    if (shape == "flat") return std::make_shared<FlatSurface>();
    if (shape == "sphere") return std::make_shared<SphericalSurface>(vertex_radius(r));
    if (shape == "conic") {
        const double radius = vertex_radius(r);
        return std::make_shared<ConicSurface>(radius, r.real("k"));
    }
    if (shape == "asphere") {
        const double radius = vertex_radius(r);
        const double k = r.real("k");
        return std::make_shared<AsphereSurface>(radius, k, read_coefficients(r));
    }
    if (shape == "biconic") {
        return std::make_shared<BiconicSurface>(r.real("radius_x"), r.real("radius_y"),
                                                r.real("k_x"), r.real("k_y"));
    }
    if (shape == "toroidal") {
        return std::make_shared<ToroidalSurface>(r.real("radius"), r.real("k"),
                                                 read_coefficients(r, true),
                                                 r.real("radius_of_rotation"));
    }
    if (shape == "xy_polynomial" || shape == "zernike") {
        const bool xy = shape == "xy_polynomial";
        XyPolynomial terms =
            xy ? xy_polynomial_from_terms(read_numbers(r, "terms", 230, "numbers"))
               : zernike_sag_polynomial(read_numbers(r, "zernike", 231, "numbers"));
        return std::make_shared<PolynomialSagSurface>(
            r.real("radius"), r.real("k"), read_coefficients(r, true),
            r.real("normalization_radius"), std::move(terms), xy ? "XY polynomial" : "Zernike sag");
    }
    const std::string formula = r.text("formula");
    try {
        return std::make_shared<SagFormulaSurface>(formula, semi_diameter, r.child_path("formula"));
    } catch (const FormulaError& e) {
        throw SceneError(r.child_path("formula"), e.message());
    }
}

}  // namespace lenslab
