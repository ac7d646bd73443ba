// The typed lens surface (`"shape": "sag"`): z(r) or z(x, y) as a formula, declared and read
// here, one entry of surface_shapes.cpp's table.

#include "geometry/lens/sag_formula_surface.h"
#include "scene/json_reader.h"
#include "scene/surface_shape_params.h"
#include "scene/surface_shapes.h"
#include "util/format_number.h"

namespace lenslab {

namespace {

const ElementSpec& sag_shape_spec() {
    static const ElementSpec spec =
        declare_surface_shape("sag",
                              {string_param("formula", "")
                                   .needed()
                                   .describe("z(r) or z(x, y), 0 on the axis")
                                   .in_editor("z(r) or z(x, y)")},
                              {{"shape", "sag"}, {"formula", "r^2/4"}});
    return spec;
}

// A number as a formula term: negative ones in parentheses.
std::string formula_term(double v) {
    std::string s = format_number(v);
    if (v < 0) {  // built in place: GCC 12 warns falsely (-Wrestrict) on "(" + s + ")"
        s.insert(0, 1, '(');
        s.push_back(')');
    }
    return s;
}

// The sag formula of a conic or even asphere with `old`'s parameters, so that switching a
// face to "sag" keeps its shape and shows how it is written.
std::string sag_formula_of(const nlohmann::json& old) {
    if (!old.is_object() || !old.contains("radius") || !old["radius"].is_number()) return "0";
    const double radius = old["radius"].get<double>(), k = kept_number(old, "k", 0);
    const std::string q = k == 0 ? "" : formula_term(1 + k) + "*";
    std::string f = "r^2/(" + formula_term(radius) + "*(1 + sqrt(1 - " + q + "r^2/" +
                    formula_term(radius) + "^2)))";
    if (old.contains("coefficients") && old["coefficients"].is_array()) {
        int power = 4;
        for (const nlohmann::json& a : old["coefficients"]) {
            if (a.is_number() && a.get<double>() != 0)
                f += " + " + formula_term(a.get<double>()) + "*r^" + std::to_string(power);
            power += 2;
        }
    }
    return f;
}

}  // namespace

SurfaceShapeEntry sag_surface_shape() {
    return {"sag", sag_shape_spec,
            [](SpecReader& r, double semi_diameter) -> std::shared_ptr<const LensSurface> {
                const std::string formula = r.text("formula");
                try {
                    return std::make_shared<SagFormulaSurface>(formula, semi_diameter,
                                                               r.child_path("formula"));
                } catch (const FormulaError& e) {
                    throw SceneError(r.child_path("formula"), e.message());
                }
            },
            [](const nlohmann::json& old, double) {
                const bool typed =
                    old.is_object() && old.contains("formula") && old["formula"].is_string();
                return nlohmann::json{
                    {"shape", "sag"},
                    {"formula", typed ? old["formula"].get<std::string>() : sag_formula_of(old)}};
            },
            SagFormulaSurface::check};
}

}  // namespace lenslab
