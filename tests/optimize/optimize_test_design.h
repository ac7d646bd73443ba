#pragma once
// Small designs for the optimiser's tests: a scene of lenses on the z axis (built with the
// bench tests' lens_scene_builder.h) inside a design whose other keys a test may replace.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../analysis/lens_scene_builder.h"
#include "optimize/lens_design.h"

namespace lenslab::test {

inline nlohmann::json scene_of(const std::vector<LensSpec>& lenses) {
    std::string objects;
    for (const LensSpec& l : lenses) objects += (objects.empty() ? "" : ",\n") + lens_json(l);
    return nlohmann::json::parse(R"({"objects": [)" + objects + "]}");
}

// A design of `lenses` with one field, the d line, an entrance pupil of 4 and an EFL operand;
// `edit` changes or adds keys.
inline nlohmann::json design_of(const std::vector<LensSpec>& lenses,
                                const nlohmann::json& edit = nlohmann::json::object()) {
    nlohmann::json d = {{"system", scene_of(lenses)},
                        {"stop", 1},
                        {"epd", 4},
                        {"fields", {0}},
                        {"wavelengths", {587.5618}},
                        {"variables", nlohmann::json::array()},
                        {"operands", nlohmann::json::array({{{"type", "efl"}, {"target", 100}}})}};
    d.update(edit);
    return d;
}

}  // namespace lenslab::test
