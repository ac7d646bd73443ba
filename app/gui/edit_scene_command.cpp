#include "edit_scene_command.h"

namespace lenslab::gui {

namespace {
// Every value edit shares one id; mergeWith then compares the pointers.
constexpr int kSetValueId = 1;
}  // namespace

EditSceneCommand::EditSceneCommand(SceneDocument* document, nlohmann::json before,
                                   nlohmann::json after, const QString& description,
                                   std::optional<SceneUpdate> first_redo, std::string merge_pointer)
    : QUndoCommand(description),
      m_document(document),
      m_before(std::move(before)),
      m_after(std::move(after)),
      m_first_redo(std::move(first_redo)),
      m_merge_pointer(std::move(merge_pointer)) {}

void EditSceneCommand::undo() { m_document->install(m_before); }

void EditSceneCommand::redo() {
    if (m_first_redo) {
        // Moved out and dropped: a later redo (after an undo) reads the document again.
        SceneUpdate update = std::move(*m_first_redo);
        m_first_redo.reset();
        m_document->install(m_after, std::move(update));
    } else {
        m_document->install(m_after);
    }
}

int EditSceneCommand::id() const { return m_merge_pointer.empty() ? -1 : kSetValueId; }

bool EditSceneCommand::mergeWith(const QUndoCommand* other) {
    // QUndoStack offers only a command with the same id, so `other` is a value edit too.
    const auto* next = static_cast<const EditSceneCommand*>(other);
    // The same description too: a whole element rewritten by two different fields (detector,
    // then photon target) stays two steps.
    if (next->m_document != m_document || next->m_merge_pointer != m_merge_pointer ||
        next->text() != text()) {
        return false;
    }
    m_after = next->m_after;
    // Edited back to where it began: the stack drops the step.
    setObsolete(m_after == m_before);
    return true;
}

}  // namespace lenslab::gui
