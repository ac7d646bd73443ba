#include "scene/lens_file_json.h"

#include <filesystem>

#include "scene/lens_file_import.h"
#include "scene/object_spec.h"
#include "scene/spec_reader.h"

namespace lenslab {

namespace {

ElementSpec declare_lens_file() {
    ElementSpec s{"lens_file", "a lens file", {}, {}};
    for (const ParamSpec& p : object_common_spec().params) {
        if (p.key != "material" && p.key != "detector" && p.key != "medium") s.params.push_back(p);
    }
    s.params.push_back(string_param("file", "")
                           .needed()
                           .describe("a Zemax .zmx or CODE V .seq file, relative to the scene"));
    s.params.push_back(point_param("vertex").describe("front vertex of the first element"));
    s.params.push_back(direction_param("axis").describe("the optical axis, from front to back"));
    s.params.push_back(nested_param(ParamKind::Direction, "x_axis")
                           .meaning_auto("a fixed perpendicular to `axis`")
                           .describe("as for a lens"));
    s.params.push_back(whole_param("configuration", 0, 0, 1000)
                           .describe("a zoom's configuration, from 1 (Zemax MNUM and THIC); 0: "
                                     "the one the file's surfaces hold"));
    return s;
}

}  // namespace

const ElementSpec& lens_file_spec() {
    static const ElementSpec spec = declare_lens_file();
    return spec;
}

nlohmann::json lens_group_from_lens_file(const nlohmann::json& j, const std::string& path,
                                         const std::string& base_dir, nlohmann::json* bench) {
    SpecReader r(j, path, lens_file_spec());
    const std::string name = r.string("name", path);
    const std::string file = r.text("file");
    if (file.empty()) throw SceneError(r.child_path("file"), "must name a .zmx or .seq file");
    const std::filesystem::path where =
        base_dir.empty() ? std::filesystem::path(file) : std::filesystem::path(base_dir) / file;
    ImportedLens lens;
    try {
        lens =
            import_lens_file(where.string(), name, 1.0, static_cast<int>(r.whole("configuration")));
    } catch (const LensFileError& e) {
        throw SceneError(r.child_path("file"), e.what());
    }
    if (bench) *bench = lens.bench;
    nlohmann::json group = lens.group;
    for (const char* key : {"vertex", "axis", "x_axis", "photon_target"}) {
        if (j.contains(key)) group[key] = j.at(key);
    }
    return group;
}

}  // namespace lenslab
