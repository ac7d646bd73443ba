#pragma once
// A dock with the ray diagram of the selected lens: the lens system on its axis, drawn from
// the same diagram model as `lenslab analyze --svg`, with its EFL and BFL. It follows the
// selection and redraws whenever the scene changes.

#include <QDockWidget>
#include <QLabel>
#include <optional>

#include "analysis/ray_diagram.h"

namespace lenslab::gui {

class SceneDocument;

// Paints a RayDiagram with QPainter, scaled to fit (true aspect).
class RayDiagramView : public QWidget {
    Q_OBJECT

public:
    explicit RayDiagramView(QWidget* parent = nullptr);
    void set_diagram(std::optional<RayDiagram> diagram);
    const std::optional<RayDiagram>& diagram() const { return m_diagram; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::optional<RayDiagram> m_diagram;
};

class RayDiagramDock : public QDockWidget {
    Q_OBJECT

public:
    RayDiagramDock(SceneDocument* document, QWidget* parent = nullptr);

    // Follows the editor's selection (a JSON pointer such as "/objects/2").
    void show_pointer(const QString& pointer);

    bool has_diagram() const { return m_view->diagram().has_value(); }
    RayDiagramView* view() const { return m_view; }
    // What the dock says above the picture: the figures, or why there is no diagram.
    QString message() const { return m_message->text(); }

private:
    void refresh();

    SceneDocument* m_document;
    QString m_pointer;
    RayDiagramView* m_view;
    QLabel* m_message;
};

}  // namespace lenslab::gui
