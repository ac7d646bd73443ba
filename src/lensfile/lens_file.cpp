#include "lensfile/lens_file.h"

#include <filesystem>
#include <tuple>
#include <utility>

#include "lensfile/lens_file_text.h"
#include "lensfile/lens_file_tokens.h"
#include "lensfile/seq_reader.h"
#include "lensfile/zar_archive.h"
#include "lensfile/zmx_reader.h"

namespace lenslab {

namespace {

// The .zmx file packed in a Zemax archive (the first; the archive's glass catalogues and
// other files are left: the lens's glasses come from lenslab's catalogues), and the name
// its lines are reported under: "ARCHIVE.zar/LENS.zmx".
std::pair<std::string, std::string> zmx_in_archive(const std::string& path) {
    std::string names;
    for (ZarEntry& e : read_zar_archive(read_lens_file_bytes(path), path)) {
        const std::string upper = lens_file_upper(e.name);
        if (upper.size() > 4 && upper.substr(upper.size() - 4) == ".ZMX")
            return {std::move(e.data), path + "/" + e.name};
        names += (names.empty() ? "" : ", ") + e.name;
    }
    throw LensFileError(path, 0,
                        "the archive holds no .zmx file (it holds: " +
                            (names.empty() ? std::string("nothing") : names) + ")");
}

// Configuration `configuration` of a zoom (0: the file's own surfaces, the active one's): its
// thicknesses written into the surfaces.
void lf_apply_configuration(LensFilePrescription& p, int configuration) {
    const std::string count = std::to_string(p.configurations);
    if (configuration == 0) {
        if (p.configurations > 1) {
            p.warnings.push_back(
                {0, count + " configurations (MNUM): the lens as configuration " +
                        std::to_string(p.active_configuration) +
                        ", the one its surfaces hold (a configuration number takes another)"});
        }
        return;
    }
    if (configuration < 1 || configuration > p.configurations) {
        throw LensFileError(p.file, 0,
                            "configuration " + std::to_string(configuration) + ": the file has " +
                                count + " (MNUM), numbered from 1");
    }
    for (const LensFilePrescription::ConfigurationThickness& t : p.configuration_thicknesses) {
        if (t.configuration != configuration) continue;
        if (t.surface < 0 || t.surface >= static_cast<int>(p.surfaces.size())) {
            throw LensFileError(p.file, t.line,
                                "THIC: no surface " + std::to_string(t.surface) +
                                    " (the file has " + std::to_string(p.surfaces.size()) +
                                    ", from 0)");
        }
        p.surfaces[size_t(t.surface)].thickness = t.value;
    }
}

}  // namespace

bool is_lens_file_path(const std::string& path) {
    const std::string extension = lens_file_upper(std::filesystem::path(path).extension().string());
    return extension == ".ZMX" || extension == ".SEQ" || extension == ".ZAR";
}

ImportedLens read_lens_file(const std::string& path, const std::string& name, double scale,
                            int configuration) {
    const std::string extension = lens_file_upper(std::filesystem::path(path).extension().string());
    if (!is_lens_file_path(path)) {
        throw LensFileError(path, 0,
                            "not a lens file lenslab reads: it takes Zemax .zmx and .zar and "
                            "CODE V .seq files (by their extension)");
    }
    std::string bytes, file = path;
    if (extension == ".ZAR") {
        std::tie(bytes, file) = zmx_in_archive(path);
    } else {
        bytes = read_lens_file_bytes(path);
    }
    const std::vector<std::string> lines = decode_lens_file_lines(bytes, file);
    LensFilePrescription p = extension == ".SEQ" ? read_seq(lines, file) : read_zmx(lines, file);
    lf_apply_configuration(p, configuration);
    p.unit_mm *= scale;  // every length of the lens_group is the file's times unit_mm
    ImportedLens lens = lens_group_from_prescription(p, name);
    lens.file = file;
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
