#pragma once
// One undoable edit of the scene document: the document before and after. Scene files are
// small (tens of kilobytes), so whole snapshots keep every edit kind (a value, an added or
// deleted object, a camera drag) in one simple command.

#include <QUndoCommand>

#include <nlohmann/json.hpp>

namespace lenslab::gui {

class SceneDocument;

class EditSceneCommand : public QUndoCommand {
public:
    EditSceneCommand(SceneDocument* document, nlohmann::json before, nlohmann::json after,
                     const QString& description);

    void undo() override;
    void redo() override;

private:
    SceneDocument* m_document;
    nlohmann::json m_before, m_after;
};

}  // namespace lenslab::gui
