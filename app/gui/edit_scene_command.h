#pragma once
// One undoable edit of the scene document: the document before and after. Scene files are
// small (tens of kilobytes), so whole snapshots keep every edit kind (a value, an added or
// deleted object, a camera drag) in one simple command. Successive edits of one value (the
// same pointer and description) merge into one step, as spin box steps should.

#include <QUndoCommand>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "scene_document.h"

namespace lenslab::gui {

class EditSceneCommand : public QUndoCommand {
public:
    // `first_redo`: what reading `after` gave (installed by the first redo, which push runs,
    // instead of reading it again). `merge_pointer`: the one value this edit sets, or "" for
    // an edit that never merges.
    EditSceneCommand(SceneDocument* document, nlohmann::json before, nlohmann::json after,
                     const QString& description, std::optional<SceneUpdate> first_redo = {},
                     std::string merge_pointer = {});

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    SceneDocument* m_document;
    nlohmann::json m_before, m_after;
    std::optional<SceneUpdate> m_first_redo;
    std::string m_merge_pointer;
};

}  // namespace lenslab::gui
