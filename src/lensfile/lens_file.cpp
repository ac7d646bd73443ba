#include "lensfile/lens_file.h"

#include <filesystem>
#include <regex>

#include "lensfile/lens_file_text.h"
#include "lensfile/lens_file_tokens.h"
#include "lensfile/seq_reader.h"
#include "lensfile/zmx_reader.h"
#include "scene/scene_error.h"
#include "scene/scene_json.h"

namespace lenslab {

namespace {

// Builds the group as a scene would, so a lens the scene reader refuses is refused here,
// at the line of the element concerned.
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

ImportedLens import_lens_file(const std::string& path, const std::string& name) {
    const std::string extension = lens_file_upper(std::filesystem::path(path).extension().string());
    if (extension != ".ZMX" && extension != ".SEQ") {
        throw LensFileError(path, 0,
                            "not a lens file lenslab reads: it takes Zemax .zmx and CODE V .seq "
                            "files (by their extension)");
    }
    const std::vector<std::string> lines = decode_lens_file_lines(read_lens_file_bytes(path), path);
    const LensFilePrescription p =
        extension == ".ZMX" ? read_zmx(lines, path) : read_seq(lines, path);
    ImportedLens lens = lens_group_from_prescription(p, name);
    check_imported_lens(lens, path);
    return lens;
}

nlohmann::ordered_json imported_scene_json(const ImportedLens& lens, const std::string& path) {
    nlohmann::ordered_json group;
    group["name"] = lens.group["name"];
    group["type"] = "lens_group";
    group["vertex"] = {0, 0, 0};
    group["axis"] = {0, 0, 1};
    for (const auto& [key, value] : lens.group.items()) {
        if (key != "name" && key != "type") group[key] = value;
    }
    nlohmann::ordered_json scene;
    scene["version"] = 1;
    scene["description"] = "Imported from " + std::filesystem::path(path).filename().string() +
                           " by lenslab import; lengths in mm";
    scene["objects"] = nlohmann::ordered_json::array({group});
    scene["bench"] = lens.bench;
    return scene;
}

std::string lens_file_warnings_text(const ImportedLens& lens, const std::string& path) {
    std::string out;
    for (const LensFileWarning& w : lens.warnings) {
        out += path;
        if (w.line > 0) out.append(":").append(std::to_string(w.line));
        out.append(": warning: ").append(w.message).append("\n");
    }
    return out;
}

}  // namespace lenslab
