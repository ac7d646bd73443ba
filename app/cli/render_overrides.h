#pragma once
// `lenslab render` (and `detect`) override the scene's `render` block with options generated
// from its declaration (render_settings_spec()): one option per declared key (max_depth ->
// --max-depth), described and range-checked as declared. The given values are collected as a
// JSON patch and applied to the scene file's JSON, which the scene reader then reads as
// usual, so there is no second set of checks.

#include <CLI/CLI.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/param_spec.h"
#include "scene/scene.h"

namespace lenslab::cli {

// The declared check of a parameter's option, run by CLI11 as the option is parsed: the same
// range_problem the scene (or design) reader uses, so the option and the file refuse the same
// values in the same words. `p` must outlive the option (a static declaration).
CLI::Validator declared_check(const ParamSpec& p);

class RenderOverrides {
public:
    // Adds the options for `keys` (every key declared for the command line when empty).
    explicit RenderOverrides(CLI::App& cmd, const std::vector<std::string>& keys = {});

    // The keys given on the command line, with their values, as a `render` object patch.
    const nlohmann::json& patch() const { return *m_patch; }
    bool given(const std::string& key) const { return m_patch->contains(key); }

    // The file's JSON (the built-in default scene when `path` is "") with the patch applied.
    // A time budget alone lifts the pass limit: `--time` without `--passes` sets passes 0.
    nlohmann::json patched_json(const std::string& path) const;

    // The scene `root` (from patched_json(path)) describes. Errors name the file as
    // load_scene_file's do; one a patched value causes names its option instead ("--seed:
    // ...", "image: ..." for the pixel count of --width and --height).
    Scene scene_from(const nlohmann::json& root, const std::string& path) const;

    // Both steps.
    Scene load(const std::string& path) const { return scene_from(patched_json(path), path); }

private:
    std::shared_ptr<nlohmann::json> m_patch;
};

}  // namespace lenslab::cli
