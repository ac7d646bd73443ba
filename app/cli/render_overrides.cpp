#include "render_overrides.h"

#include <algorithm>
#include <optional>

#include "scene/json_reader.h"
#include "scene/render_settings_json.h"
#include "scene/render_settings_spec.h"
#include "scene/scene_json.h"

namespace lenslab::cli {

namespace {

using nlohmann::json;

// The option's text as the JSON value the scene file would hold, or nothing when it is not
// one of the declared kind at all.
std::optional<json> value_of(const ParamSpec& p, const std::string& text) {
    switch (p.kind) {
        case ParamKind::WholeNumber: {
            int64_t v = 0;
            if (!CLI::detail::lexical_cast(text, v)) return std::nullopt;
            return v;
        }
        case ParamKind::Number:
        case ParamKind::Fraction: {
            double v = 0;
            if (!CLI::detail::lexical_cast(text, v)) return std::nullopt;
            return v;
        }
        case ParamKind::Boolean:
            if (text == "on" || text == "off") return text == "on";
            return std::nullopt;
        default:
            return text;
    }
}

std::string type_name(const ParamSpec& p) {
    switch (p.kind) {
        case ParamKind::WholeNumber:
            return "INT";
        case ParamKind::Number:
        case ParamKind::Fraction:
            return "NUMBER";
        case ParamKind::Boolean:
            return "on|off";
        default:
            return "TEXT";
    }
}

// What the help shows after the type: the docs' range, without its Markdown.
std::string help_range(const ParamSpec& p) {
    std::string text = p.kind == ParamKind::Boolean ? "on or off" : range_text(p);
    text.erase(std::remove(text.begin(), text.end(), '`'), text.end());
    return text;
}

}  // namespace

CLI::Validator declared_check(const ParamSpec& p) {
    return CLI::Validator(
        [&p](std::string& text) -> std::string {
            const std::optional<json> v = value_of(p, text);
            if (!v) {
                const char* kind = p.kind == ParamKind::WholeNumber ? "a whole number"
                                   : p.kind == ParamKind::Boolean   ? "on or off"
                                                                    : "a number";
                return std::string("must be ") + kind + ", got '" + text + "'";
            }
            std::optional<std::string> problem;
            if (v->is_number()) problem = range_problem(p, v->get<double>());
            if (p.kind == ParamKind::Choice) problem = choice_problem(p, text);
            return problem.value_or("");
        },
        help_range(p));
}

RenderOverrides::RenderOverrides(CLI::App& cmd, const std::vector<std::string>& keys)
    : m_patch(std::make_shared<json>(json::object())) {
    for (const ParamSpec& p : render_settings_spec().params) {
        const bool wanted = keys.empty() ? p.cli : std::count(keys.begin(), keys.end(), p.key) > 0;
        if (!wanted) continue;
        auto patch = m_patch;
        cmd.add_option_function<std::string>(
               p.option_name(),
               [patch, &p](const std::string& text) { (*patch)[p.key] = *value_of(p, text); },
               p.doc + " (overrides the scene)")
            ->type_name(type_name(p))
            ->check(declared_check(p));
    }
}

json RenderOverrides::patched_json(const std::string& path) const {
    json root = path.empty() ? parse_json_strict(default_scene_text(), "default scene")
                             : read_scene_json_file(path);
    // The file's own values are checked first, so an option does not hide a bad one.
    if (root.contains("render")) {
        try {
            (void)read_render_settings(root["render"]);
        } catch (const SceneError& e) {
            if (path.empty()) throw;
            throw SceneError(path + ": " + e.path(), e.reason());
        }
    }
    // A `render` that is not an object is left for the reader to refuse.
    if (!root.contains("render")) root["render"] = json::object();
    if (root["render"].is_object()) {
        root["render"].update(*m_patch);
        if (given("time") && !given("passes")) root["render"]["passes"] = 0;
    }
    return root;
}

Scene RenderOverrides::scene_from(const json& root, const std::string& path) const {
    try {
        return path.empty() ? scene_from_json(root) : scene_from_file_json(root, path);
    } catch (const SceneError& e) {
        // The reason is the reader's; only where it points changes, to the option given.
        const std::string where =
            path.empty() ? e.path() : e.path().substr(std::min(e.path().size(), path.size() + 2));
        if (where.rfind("render.", 0) == 0 && given(where.substr(7))) {
            throw SceneError(render_settings_spec().param(where.substr(7)).option_name(),
                             e.reason());
        }
        if (where == "render" && (given("width") || given("height")))
            throw SceneError("image", e.reason());
        throw;
    }
}

}  // namespace lenslab::cli
