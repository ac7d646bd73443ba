#include "scene/surface_json.h"

#include <algorithm>

#include "geometry/lens/asphere_surface.h"
#include "geometry/lens/conic_surface.h"
#include "geometry/lens/flat_surface.h"
#include "geometry/lens/sag_formula_surface.h"
#include "geometry/lens/spherical_surface.h"
#include "scene/json_reader.h"

namespace lenslab {

const std::vector<std::string> kSurfaceShapeNames{"flat", "sphere", "conic", "asphere", "sag"};

namespace {

// The keys each shape takes besides `shape`.
std::vector<std::string> keys_of(const std::string& shape) {
    if (shape == "sphere") return {"radius"};
    if (shape == "conic") return {"radius", "k"};
    if (shape == "asphere") return {"radius", "k", "coefficients"};
    if (shape == "sag") return {"formula"};
    return {};
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

double vertex_radius(JsonObjectReader& r) {
    const double radius = r.number("radius");
    if (radius == 0) {
        throw SceneError(r.child_path("radius"),
                         "must not be 0 (use {\"shape\": \"flat\"} for a plane)");
    }
    return radius;
}

std::vector<double> read_coefficients(JsonObjectReader& r) {
    const nlohmann::json& j = r.require("coefficients");
    const std::string path = r.child_path("coefficients");
    if (!j.is_array() || j.empty() || j.size() > AsphereSurface::kMaxCoefficients) {
        throw SceneError(path, "must be an array of 1 to 7 numbers [A4, A6, ..., A16]");
    }
    std::vector<double> out;
    for (size_t i = 0; i < j.size(); ++i) {
        out.push_back(JsonObjectReader::as_number(j[i], path + "[" + std::to_string(i) + "]"));
    }
    return out;
}

}  // namespace

std::shared_ptr<const LensSurface> read_lens_surface(const nlohmann::json& j,
                                                     const std::string& path,
                                                     double semi_diameter) {
    JsonObjectReader r(j, path, {"shape", "radius", "k", "coefficients", "formula"});
    const std::string shape = r.string("shape");
    if (std::find(kSurfaceShapeNames.begin(), kSurfaceShapeNames.end(), shape) ==
        kSurfaceShapeNames.end()) {
        throw SceneError(r.child_path("shape"), "unknown surface shape '" + shape + "' (known: " +
                                                    joined(kSurfaceShapeNames) + ")");
    }
    const std::vector<std::string> takes = keys_of(shape);
    for (const char* key : {"radius", "k", "coefficients", "formula"}) {
        if (r.has(key) && std::find(takes.begin(), takes.end(), key) == takes.end()) {
            throw SceneError(r.child_path(key),
                             with_article(shape) + " surface has no " + key +
                                 (takes.empty() ? "" : " (it takes " + joined(takes) + ")"));
        }
    }
    if (shape == "flat") return std::make_shared<FlatSurface>();
    if (shape == "sphere") return std::make_shared<SphericalSurface>(vertex_radius(r));
    if (shape == "conic") {
        const double radius = vertex_radius(r);
        return std::make_shared<ConicSurface>(radius, r.number("k"));
    }
    if (shape == "asphere") {
        const double radius = vertex_radius(r);
        const double k = r.number("k", 0.0);
        return std::make_shared<AsphereSurface>(radius, k, read_coefficients(r));
    }
    const std::string formula = r.string("formula");
    try {
        return std::make_shared<SagFormulaSurface>(formula, semi_diameter);
    } catch (const FormulaError& e) {
        throw SceneError(r.child_path("formula"), e.message());
    }
}

}  // namespace lenslab
