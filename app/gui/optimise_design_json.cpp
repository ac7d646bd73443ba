#include "optimise_design_json.h"

#include "optimize/model_glass.h"

namespace lenslab::gui {

nlohmann::json optimise_design_json(const nlohmann::json& scene, const OpticalSystem& system,
                                    const OptimiseChoices& choices) {
    using nlohmann::json;
    json variables = json::array();
    for (std::size_t i = 0; i < system.elements.size(); ++i) {
        const std::string& lens = system.elements[i].path;
        if (choices.vary_curvatures) {
            for (const char* surface : {"front", "back"}) {
                variables.push_back({{"type", "curvature"}, {"lens", lens}, {"surface", surface}});
            }
        }
        // No gap after the last lens: the image plane follows the paraxial focus.
        if (choices.vary_air_gaps && i + 1 < system.elements.size()) {
            variables.push_back({{"type", "air_gap"}, {"lens", lens}});
        }
        // The element's scene entry, "objects[i]": a lens of a model glass?
        const std::size_t open = lens.find('['), close = lens.find(']');
        if (!choices.vary_model_glasses || open == std::string::npos || close != lens.size() - 1)
            continue;
        const std::size_t index = std::stoul(lens.substr(open + 1, close - open - 1));
        if (is_model_glass(nlohmann::ordered_json(scene["objects"][index]))) {
            for (const char* type : {"n_d", "V_d"})
                variables.push_back({{"type", type}, {"lens", lens}});
        }
    }
    json operands = json::array();
    operands.push_back({{"type", "efl"}, {"target", choices.efl_target}, {"weight", 100}});
    operands.push_back({{"type", "rms_spot"}, {"weight", 1}});  // one per design field
    json design = {{"system", scene},
                   {"stop", choices.stop},
                   {"epd", choices.epd},
                   {"fields", choices.fields},
                   {"iterations", choices.iterations},
                   {"variables", variables},
                   {"operands", operands}};
    if (!choices.wavelengths.empty()) design["wavelengths"] = choices.wavelengths;
    if (choices.global_starts > 0) design["global_search"] = {{"starts", choices.global_starts}};
    if (choices.vary_model_glasses && choices.substitute_glasses)
        design["glass_substitution"] = json::object();
    return design;
}

}  // namespace lenslab::gui
