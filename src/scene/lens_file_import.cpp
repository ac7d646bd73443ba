#include "scene/lens_file_import.h"

#include <regex>

#include "lensfile/lens_file_error.h"
#include "scene/scene_json.h"
#include "util/scene_error.h"

namespace lenslab {

namespace {

void check_imported_lens(const ImportedLens& lens, const std::string& path) {
    nlohmann::json scene = {{"objects", nlohmann::json::array({lens.group})}};
    scene["objects"][0]["vertex"] = {0, 0, 0};
    scene["objects"][0]["axis"] = {0, 0, 1};
    try {
        (void)scene_from_json(scene, "", {.require_camera = false});
    } catch (const SceneError& e) {
        static const std::regex element(R"(elements\[(\d+)\])");
        std::smatch m;
        int line = 0;
        if (std::regex_search(e.path(), m, element)) {
            const size_t i = std::stoul(m[1]);
            if (i < lens.element_lines.size()) line = lens.element_lines[i];
        }
        std::string where = e.path();
        const size_t at = where.find("elements[");
        where = at == std::string::npos ? "the lens" : where.substr(at);
        throw LensFileError(path, line, where + ": " + e.reason());
    }
}

}  // namespace

ImportedLens import_lens_file(const std::string& path, const std::string& name, double scale,
                              int configuration) {
    ImportedLens lens = read_lens_file(path, name, scale, configuration);
    check_imported_lens(lens, lens.file);
    return lens;
}

}  // namespace lenslab
