#include "edit_scene_command.h"

#include "scene_document.h"

namespace lenslab::gui {

EditSceneCommand::EditSceneCommand(SceneDocument* document, nlohmann::json before,
                                   nlohmann::json after, const QString& description)
    : QUndoCommand(description), m_document(document), m_before(std::move(before)),
      m_after(std::move(after)) {}

void EditSceneCommand::undo() { m_document->install(m_before); }
void EditSceneCommand::redo() { m_document->install(m_after); }

}  // namespace lenslab::gui
