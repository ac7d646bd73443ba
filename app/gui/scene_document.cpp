#include "scene_document.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <algorithm>
#include <set>

#include "edit_scene_command.h"
#include "scene/framing_camera.h"
#include "scene/json_reader.h"
#include "scene/medium.h"
#include "scene/render_settings_json.h"

namespace lenslab::gui {

namespace {
// Files a scene names (OBJ meshes) are relative to the scene file's folder.
std::string folder_of(const QString& path) {
    return path.isEmpty() ? std::string() : QFileInfo(path).absolutePath().toStdString();
}

// The top-level keys whose values differ between `a` and `b` (present in one only counts).
std::set<std::string> differing_blocks(const nlohmann::json& a, const nlohmann::json& b) {
    std::set<std::string> keys;
    for (const auto& [key, value] : a.items()) {
        const auto it = b.find(key);
        if (it == b.end() || *it != value) keys.insert(key);
    }
    for (const auto& [key, value] : b.items()) {
        if (!a.contains(key)) keys.insert(key);
    }
    return keys;
}

// Blocks the installed scene can take alone, keeping its objects, materials and BVH.
bool updatable_alone(const std::string& key) {
    return key == "camera" || key == "render" || key == "lights" || key == "atmosphere";
}
}  // namespace

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) { load_default(); }

void SceneDocument::load_default() {
    m_json = parse_json_strict(default_scene_text(), "default scene");
    m_scene = scene_from_json(m_json);
    m_path.clear();
    m_copied_from.clear();
    m_folder.clear();
    m_undo.clear();
    emit path_changed();
    emit changed();
}

SceneUpdate SceneDocument::read_update(const nlohmann::json& j) const {
    SceneUpdate update;
    const std::set<std::string> blocks = differing_blocks(m_json, j);
    // The camera is required: removing it goes through the whole reader for its message.
    // An atmosphere with a density is bounded over the whole scene: read with it.
    const bool alone = j.is_object() && j.contains("camera") &&
                       std::all_of(blocks.begin(), blocks.end(), updatable_alone) &&
                       !(j.contains("atmosphere") && atmosphere_needs_region(j.at("atmosphere")));
    if (!alone) {
        update.scene = scene_from_json(j, m_folder);
        return update;
    }
    // Read as scene_from_json reads them: an absent block means its defaults.
    if (blocks.count("camera")) update.camera = camera_from_json(j.at("camera"));
    if (blocks.count("render")) {
        update.render =
            j.contains("render") ? read_render_settings(j.at("render")) : RenderSettings{};
    }
    if (blocks.count("lights")) {
        update.lights = j.contains("lights") ? lights_from_json(j.at("lights")) : SceneLights{};
    }
    if (blocks.count("atmosphere")) {
        update.atmosphere.emplace(
            j.contains("atmosphere") ? read_atmosphere(j.at("atmosphere"), Aabb{}) : std::nullopt);
    }
    return update;
}

bool SceneDocument::check(const nlohmann::json& j, SceneUpdate& out, QString* error) const {
    try {
        out = read_update(j);
        return true;
    } catch (const SceneError& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
}

bool SceneDocument::open(const QString& path, QString* error, bool as_copy) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error) *error = path + ": cannot open: " + file.errorString();
        return false;
    }
    const std::string text = file.readAll().toStdString();
    nlohmann::json j;
    Scene scene;
    bool made = false;
    try {
        j = parse_json_strict(text, path.toStdString());
        if (!j.is_object())
            throw SceneError(path.toStdString(), "the top level must be a JSON object { ... }");
        made = !j.contains("camera");
        if (made) {
            j["camera"] =
                framing_camera_json(scene_from_json(j, folder_of(path), {.require_camera = false}));
        }
        scene = scene_from_json(j, folder_of(path));
    } catch (const SceneError& e) {
        if (error) {
            const std::string where = e.path().rfind(path.toStdString(), 0) == 0
                                          ? e.path()
                                          : path.toStdString() + ": " + e.path();
            *error = QString::fromStdString(where + ": " + e.reason());
        }
        return false;
    }
    m_json = std::move(j);
    m_scene = std::move(scene);
    m_camera_made = made;
    m_path = as_copy ? QString() : path;
    m_copied_from = as_copy ? path : QString();
    m_folder = folder_of(path);
    m_undo.clear();
    emit path_changed();
    emit changed();
    return true;
}

bool SceneDocument::save(const QString& path, QString* error) {
    QSaveFile file(path);
    const std::string text = m_json.dump(2) + "\n";
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(text.data(), qint64(text.size())) != qint64(text.size()) || !file.commit()) {
        if (error) *error = path + ": cannot save: " + file.errorString();
        return false;
    }
    m_path = path;
    m_copied_from.clear();
    m_folder = folder_of(path);
    m_undo.setClean();
    emit path_changed();
    return true;
}

bool SceneDocument::apply(const nlohmann::json& edited, const QString& description,
                          QString* error) {
    return edit(edited, description, error, {});
}

bool SceneDocument::edit(const nlohmann::json& edited, const QString& description, QString* error,
                         std::string merge_pointer) {
    SceneUpdate update;
    if (!check(edited, update, error)) return false;
    // The command's first redo installs what was read here: no second build.
    m_undo.push(new EditSceneCommand(this, m_json, edited, description, std::move(update),
                                     std::move(merge_pointer)));
    return true;
}

bool SceneDocument::set_value(const nlohmann::json::json_pointer& pointer,
                              const nlohmann::json& value, const QString& description,
                              QString* error) {
    nlohmann::json edited = m_json;
    edited[pointer] = value;
    return edit(edited, description, error, pointer.to_string());
}

bool SceneDocument::preview(const nlohmann::json& edited) {
    SceneUpdate update;
    if (!check(edited, update, nullptr)) return false;
    install(edited, std::move(update));
    return true;
}

void SceneDocument::commit_preview(const nlohmann::json& before, const QString& description) {
    // The previews installed the document already: the first redo changes nothing.
    if (before == m_json) return;
    m_undo.push(new EditSceneCommand(this, before, m_json, description, SceneUpdate{}));
}

void SceneDocument::install(const nlohmann::json& json) {
    install(json, read_update(json));  // validated before it entered the stack
}

void SceneDocument::install(const nlohmann::json& json, SceneUpdate update) {
    // Nothing the BVH holds depends on the camera, the render settings, the lights or the
    // atmosphere.
    if (update.scene) {
        m_scene = std::move(*update.scene);
    } else {
        if (update.camera) m_scene.camera = *update.camera;
        if (update.render) m_scene.render = *update.render;
        if (update.lights) m_scene.set_lights(std::move(*update.lights));
        if (update.atmosphere) m_scene.atmosphere = *update.atmosphere;
    }
    m_json = json;
    emit changed();
}

}  // namespace lenslab::gui
