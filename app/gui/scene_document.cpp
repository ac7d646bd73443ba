#include "scene_document.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include "edit_scene_command.h"
#include "scene/json_reader.h"
#include "scene/scene_json.h"

namespace lenslab::gui {

namespace {
// Files a scene names (OBJ meshes) are relative to the scene file's folder.
std::string folder_of(const QString& path) {
    return path.isEmpty() ? std::string() : QFileInfo(path).absolutePath().toStdString();
}
}  // namespace

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) { load_default(); }

void SceneDocument::load_default() {
    m_json = parse_json_strict(default_scene_text(), "default scene");
    m_scene = scene_from_json(m_json);
    m_path.clear();
    m_undo.clear();
    emit path_changed();
    emit changed();
}

bool SceneDocument::validate(const nlohmann::json& j, Scene& out, QString* error) const {
    try {
        out = scene_from_json(j, folder_of(m_path));
        return true;
    } catch (const SceneError& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
}

bool SceneDocument::open(const QString& path, QString* error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error) *error = path + ": cannot open: " + file.errorString();
        return false;
    }
    const std::string text = file.readAll().toStdString();
    nlohmann::json j;
    Scene scene;
    try {
        j = parse_json_strict(text, path.toStdString());
        if (!j.is_object()) throw SceneError(path.toStdString(), "the top level must be a JSON object { ... }");
        scene = scene_from_json(j, folder_of(path));
    } catch (const SceneError& e) {
        if (error) {
            const std::string where = e.path().rfind(path.toStdString(), 0) == 0 ? e.path() : path.toStdString() + ": " + e.path();
            *error = QString::fromStdString(where + ": " + e.reason());
        }
        return false;
    }
    m_json = std::move(j);
    m_scene = std::move(scene);
    m_path = path;
    m_undo.clear();
    emit path_changed();
    emit changed();
    return true;
}

bool SceneDocument::save(const QString& path, QString* error) {
    QSaveFile file(path);
    const std::string text = m_json.dump(2) + "\n";
    if (!file.open(QIODevice::WriteOnly) || file.write(text.data(), qint64(text.size())) != qint64(text.size()) ||
        !file.commit()) {
        if (error) *error = path + ": cannot save: " + file.errorString();
        return false;
    }
    m_path = path;
    m_undo.setClean();
    emit path_changed();
    return true;
}

bool SceneDocument::apply(const nlohmann::json& edited, const QString& description, QString* error) {
    Scene scene;
    if (!validate(edited, scene, error)) return false;
    m_undo.push(new EditSceneCommand(this, m_json, edited, description));
    return true;
}

bool SceneDocument::set_value(const nlohmann::json::json_pointer& pointer, const nlohmann::json& value,
                              const QString& description, QString* error) {
    nlohmann::json edited = m_json;
    edited[pointer] = value;
    return apply(edited, description, error);
}

bool SceneDocument::preview(const nlohmann::json& edited) {
    Scene scene;
    if (!validate(edited, scene, nullptr)) return false;
    m_json = edited;
    m_scene = std::move(scene);
    emit changed();
    return true;
}

void SceneDocument::commit_preview(const nlohmann::json& before, const QString& description) {
    if (before != m_json) m_undo.push(new EditSceneCommand(this, before, m_json, description));
}

void SceneDocument::install(const nlohmann::json& json) {
    m_json = json;
    m_scene = scene_from_json(m_json, folder_of(m_path));  // validated before it entered the stack
    emit changed();
}

}  // namespace lenslab::gui
