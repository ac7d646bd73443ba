#include "optimize/glass_choice.h"

#include "analysis/system/optical_system.h"
#include "optimize/design_variable.h"
#include "scene/json_reader.h"
#include "scene/scene_json.h"

namespace lenslab {

std::string lens_glass(const nlohmann::ordered_json& scene, int object) {
    return scene["objects"][object]["material"]["glass"].get<std::string>();
}

void set_lens_glass(nlohmann::ordered_json& scene, int object, const std::string& glass) {
    scene["objects"][object]["material"]["glass"] = glass;
}

GlassChoice read_glass_choice(const nlohmann::json& spec, const std::string& path,
                              const nlohmann::ordered_json& scene, const std::string& base_dir,
                              const std::vector<double>& wavelengths) {
    JsonObjectReader reader(spec, path, {"lens", "glasses"}, "a glass choice");
    GlassChoice choice;
    choice.path = path;
    choice.lens = reader.string("lens");
    choice.object = find_design_lens(scene, choice.lens, reader.child_path("lens"));
    const nlohmann::ordered_json& material = scene["objects"][choice.object]["material"];
    if (!material.is_object() || !material.contains("glass")) {
        throw SceneError(reader.child_path("lens"),
                         "the lens '" + choice.lens +
                             "' needs its material written inline with a \"glass\" to choose "
                             "among glasses");
    }
    const nlohmann::json& glasses = reader.require("glasses");
    if (!glasses.is_array() || glasses.empty()) {
        throw SceneError(reader.child_path("glasses"), "must be a non-empty array of glass names");
    }
    for (size_t i = 0; i < glasses.size(); ++i) {
        const std::string at = reader.child_path("glasses") + "[" + std::to_string(i) + "]";
        if (!glasses[i].is_string()) throw SceneError(at, "must be a glass name");
        const std::string name = glasses[i].get<std::string>();
        // The glass as the scene reader takes it: unknown names are refused here, not later.
        nlohmann::ordered_json trial = scene;
        set_lens_glass(trial, choice.object, name);
        try {
            const OpticalSystem system = build_optical_system(
                scene_from_json(nlohmann::json(trial), base_dir, {.require_camera = false}));
            for (double nm : wavelengths) check_wavelength(system, nm, "the wavelength");
        } catch (const SceneError& e) {
            throw SceneError(at, e.reason());
        }
        choice.glasses.push_back(name);
    }
    return choice;
}

}  // namespace lenslab
