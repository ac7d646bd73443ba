#pragma once
// The scene being edited: its JSON document (the single source of truth, saved as it is),
// the file it came from, and the undo stack. Every edit is checked by the same reader the
// command line uses, so the editor cannot hold a scene that `lenslab render` would refuse.
// An edit is read once and that result installed, and rebuilds only what it changed: an edit
// of the camera (a camera drag), the render settings, the lights or the atmosphere alone keeps
// the installed objects and their BVH.

#include <QObject>
#include <QString>
#include <QUndoStack>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "scene/scene.h"
#include "scene/scene_json.h"

namespace lenslab::gui {

// What installing a checked document changes in the installed scene: a whole new scene, or
// only the blocks that differ among camera, render settings, lights and atmosphere (nothing
// set: nothing the scene holds differs, e.g. the description).
struct SceneUpdate {
    std::optional<Scene> scene;
    std::optional<CameraSettings> camera;
    std::optional<RenderSettings> render;
    std::optional<SceneLights> lights;
    // Set when the atmosphere differs: the new one, or none (clear air).
    std::optional<std::optional<Medium>> atmosphere;
};

class SceneDocument : public QObject {
    Q_OBJECT

public:
    explicit SceneDocument(QObject* parent = nullptr);

    const nlohmann::json& json() const { return m_json; }
    const Scene& scene() const { return m_scene; }
    const QString& path() const { return m_path; }
    // The file an untitled copy was opened from (an example), else empty.
    const QString& copied_from() const { return m_copied_from; }
    bool is_modified() const { return !m_undo.isClean(); }
    QUndoStack* undo_stack() { return &m_undo; }

    // Replaces the document with the built-in default scene (not modified, no path).
    void load_default();
    // Opens a scene file. On failure the current scene is kept and `error` says why. As a
    // copy (the examples): untitled, so Save asks where instead of overwriting the file;
    // relative file names in it (OBJ meshes) still read from its folder. A file with no
    // camera (a lens file for `lenslab analyze`) gets one that shows the whole scene
    // (scene/framing_camera.h), and camera_made() says so.
    bool open(const QString& path, QString* error, bool as_copy = false);
    bool camera_made() const { return m_camera_made; }
    // Writes the document atomically (a temporary file renamed over the target).
    bool save(const QString& path, QString* error);

    // Applies an edit as one undoable step. Refused (nothing changes, `error` says why)
    // when the resulting scene would not load.
    bool apply(const nlohmann::json& edited, const QString& description, QString* error);
    // Sets one value, e.g. pointer "/objects/2/radius". Successive sets of the same pointer
    // (spin box steps) merge into one undo step.
    bool set_value(const nlohmann::json::json_pointer& pointer, const nlohmann::json& value,
                   const QString& description, QString* error);

    // Interactive edits (camera drags): `preview` changes the document without an undo
    // step; `commit_preview` at the end of the drag records one step from `before` to now.
    bool preview(const nlohmann::json& edited);
    void commit_preview(const nlohmann::json& before, const QString& description);

    // Used by the undo command: installs an already validated document, reading only what
    // differs from the installed one; or with `update`, what reading it gave already.
    void install(const nlohmann::json& json);
    void install(const nlohmann::json& json, SceneUpdate update);

signals:
    void changed();       // the document (and so the scene) changed
    void path_changed();  // a new file name (open, save as)

private:
    // Reads `j` with the scene reader, only as far as it differs from the installed document
    // (the camera, render, lights or atmosphere blocks alone, or all of it). Throws SceneError.
    SceneUpdate read_update(const nlohmann::json& j) const;
    bool check(const nlohmann::json& j, SceneUpdate& out, QString* error) const;
    // `merge_pointer`: set for a set_value, whose step merges with the next one of the same
    // pointer.
    bool edit(const nlohmann::json& edited, const QString& description, QString* error,
              std::string merge_pointer);

    nlohmann::json m_json;
    Scene m_scene;
    QString m_path;
    QString m_copied_from;
    bool m_camera_made = false;
    std::string m_folder;  // where relative file names in the scene are read from
    QUndoStack m_undo;
};

}  // namespace lenslab::gui
