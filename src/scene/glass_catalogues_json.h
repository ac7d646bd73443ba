#pragma once
// The scene's "glass_catalogues": the user's AGF files whose glasses its materials may name.

#include <nlohmann/json.hpp>
#include <string>

namespace lenslab {

// Loads each file of the array (paths relative to `base_dir`, the scene file's folder) as a
// user glass catalogue (optics/user_glass_catalogues.h). Throws SceneError naming the entry
// ("glass_catalogues[0]") and the file's own problem ("my.agf:12: ...").
void read_glass_catalogues(const nlohmann::json& j, const std::string& base_dir);

}  // namespace lenslab
