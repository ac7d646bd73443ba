#pragma once
// Shows the progressive render and turns the mouse into camera moves, selections and edits:
// left drag orbits about the point looked at, right or middle drag pans, the wheel zooms, a
// click selects the object or light under the cursor. Over the render: the selected
// object's outline, the lights' icons, and move/rotate handles at the selection whose drags
// are undoable edits (Ctrl snaps). After Add, the next click places the new object where it
// points, resting on the surface there.

#include <QImage>
#include <QPoint>
#include <QWidget>
#include <nlohmann/json.hpp>
#include <optional>

#include "light_icons.h"
#include "selection_outline.h"
#include "transform_handles.h"
#include "view_camera.h"

namespace lenslab::gui {

class SceneDocument;

class Viewport : public QWidget {
    Q_OBJECT

public:
    Viewport(SceneDocument* document, QWidget* parent = nullptr);

    void set_image(const QImage& image);
    const QImage& image() const { return m_image; }

    // The object whose surface is under a widget position, or -1.
    int pick(const QPoint& pos) const;

    // Follows the editor's selection (a JSON pointer such as "/objects/2" or "/lights/0").
    void show_pointer(const QString& pointer);
    // The film as drawn in the widget now.
    ViewCamera view_camera() const;
    // The handles at the selection, when an object or light is selected and in front.
    std::optional<TransformHandles> handles() const;
    // The selected object's outline (computed when drawn, kept until something changes).
    const SelectionOutline& outline();
    std::vector<LightIcon> light_icons() const;
    // The next click (not a drag) places scene entry `object` where it points; -1 cancels.
    void arm_placement(int object);
    int armed_placement() const { return m_placing; }
    // True while a drag (camera or handle) is under way: the render previews coarsely.
    bool is_interacting() const { return m_dragged && m_button != Qt::NoButton; }

signals:
    void object_picked(int object);  // a file entry of `objects`, or -1
    void light_picked(int light);    // an entry of `lights`
    void interaction_finished();     // a drag ended: time for the full render
    void edit_refused(const QString& message);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    QRect image_rect() const;  // where the image is drawn, aspect kept
    // The selection's list ("objects", "lights") and index, when one is selected.
    std::optional<std::pair<std::string, int>> selected_entry() const;
    std::optional<Vec3> selection_pivot() const;
    void drag_camera(const QPoint& delta);
    void drag_handle(const QPointF& at, bool snap);
    void place_armed(const QPoint& pos);

    SceneDocument* m_document;
    QImage m_image;
    QString m_pointer;
    QPoint m_press, m_last;
    Qt::MouseButton m_button = Qt::NoButton;
    bool m_dragged = false;
    nlohmann::json m_before;  // the document when the drag started

    // A handle drag: the handles as they were at the press, so the drag follows the mouse.
    std::optional<TransformHandles> m_drag_handles;
    Handle m_active;
    double m_turned = 0;  // the angle swept so far (unsnapped)
    Vec3 m_drag_pivot;

    SelectionOutline m_outline;
    bool m_outline_stale = true;
    int m_placing = -1;
};

}  // namespace lenslab::gui
