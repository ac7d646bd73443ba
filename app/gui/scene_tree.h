#pragma once
// The scene as a tree: camera, render settings, the atmosphere (when there is one),
// materials, objects and lights. Each item carries the JSON pointer of what it shows
// ("/objects/3"), which is what selection means everywhere in the editor.

#include <QTreeWidget>

namespace lenslab::gui {

class SceneDocument;

class SceneTree : public QTreeWidget {
    Q_OBJECT

public:
    SceneTree(SceneDocument* document, QWidget* parent = nullptr);

    QString selected_pointer() const;
    void select_pointer(const QString& pointer);

signals:
    void pointer_selected(const QString& pointer);

private:
    void rebuild();

    SceneDocument* m_document;
};

}  // namespace lenslab::gui
