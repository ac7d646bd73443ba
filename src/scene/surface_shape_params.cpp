#include "scene/surface_shape_params.h"

#include "scene/json_reader.h"

namespace lenslab {

ElementSpec declare_surface_shape(const std::string& shape, std::vector<ParamSpec> own,
                                  nlohmann::json example) {
    // No phrase: a key no shape takes is an "unknown key", as in any nested object.
    ElementSpec s{shape + " surface",
                  "",
                  {string_param("shape", "").needed().describe("\"" + shape + "\"")},
                  std::move(example)};
    for (ParamSpec& p : own) s.params.push_back(std::move(p));
    return s;
}

ParamSpec vertex_radius_param() {
    return number_param("radius", 0)
        .needed()
        .describe("R, the vertex radius of curvature; not 0 (signed, see the sign convention)")
        .in_editor("radius (signed)");
}

ParamSpec conic_constant_param() {
    return number_param("k", 0).describe("the conic constant").in_editor("conic constant k");
}

ParamSpec asphere_coefficients_param(size_t least, std::string doc, std::string label) {
    return nested_param(ParamKind::Array, "coefficients")
        .holding_numbers(least, 7)
        .describe(std::move(doc))
        .in_editor(std::move(label));
}

double read_vertex_radius(SpecReader& r) {
    const double radius = r.real("radius");
    if (radius == 0) {
        throw SceneError(r.child_path("radius"),
                         "must not be 0 (use {\"shape\": \"flat\"} for a plane)");
    }
    return radius;
}

std::vector<double> read_number_array(SpecReader& r, const std::string& key,
                                      const std::string& what) {
    const ParamSpec& p = r.spec().param(key);
    if (!r.has(key) && !p.required) return {};
    const nlohmann::json& j = r.require(key);
    const std::string path = r.child_path(key);
    if (!j.is_array() || j.size() < p.least_count || j.size() > p.most_count) {
        throw SceneError(path, "must be an " + p.written_as + what);
    }
    std::vector<double> out;
    for (size_t i = 0; i < j.size(); ++i) {
        out.push_back(JsonObjectReader::as_number(j[i], path + "[" + std::to_string(i) + "]"));
    }
    return out;
}

double kept_radius(const nlohmann::json& old, double diameter) {
    return kept_number(old, "radius", 2.0 * diameter);
}

double kept_number(const nlohmann::json& old, const std::string& key, double fallback) {
    return old.is_object() && old.contains(key) && old[key].is_number() ? old[key].get<double>()
                                                                        : fallback;
}

}  // namespace lenslab
