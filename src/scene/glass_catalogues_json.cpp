#include "scene/glass_catalogues_json.h"

#include <filesystem>

#include "optics/glass_catalogue_file.h"
#include "optics/user_glass_catalogues.h"
#include "scene/json_reader.h"
#include "util/scene_error.h"

namespace lenslab {

void read_glass_catalogues(const nlohmann::json& j, const std::string& base_dir) {
    if (!j.is_array()) throw SceneError("glass_catalogues", "must be an array of AGF file names");
    for (size_t i = 0; i < j.size(); ++i) {
        const std::string path = "glass_catalogues[" + std::to_string(i) + "]";
        if (!j[i].is_string() || j[i].get<std::string>().empty())
            throw SceneError(path, "must be the name of an AGF file");
        std::filesystem::path file = j[i].get<std::string>();
        if (file.is_relative() && !base_dir.empty()) file = std::filesystem::path(base_dir) / file;
        try {
            load_user_glass_catalogue(file.string());
        } catch (const GlassDataError& e) {
            throw SceneError(path, e.what());
        }
    }
}

}  // namespace lenslab
