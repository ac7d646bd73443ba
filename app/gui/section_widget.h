#pragma once
// The 2-D section view: the plane through the selected lens's axis
// (analysis/section/section_view.h) with every object's cross-section and the rays traced through
// them. It follows the selection, redraws on every scene change, and an object dragged in it moves
// by the same undoable edit as the property panel's (the rays follow while dragging).

#include <QPointF>
#include <QWidget>
#include <nlohmann/json.hpp>

#include "analysis/section/section_view.h"

namespace lenslab::gui {

class SceneDocument;

class SectionWidget : public QWidget {
    Q_OBJECT

public:
    explicit SectionWidget(SceneDocument* document, QWidget* parent = nullptr);

    // Follows the editor's selection (a JSON pointer such as "/objects/2").
    void show_pointer(const QString& pointer);
    // The plane shown: through the selected lens's axis (the default) or a plane of the
    // scene's axes, through the selected object.
    void set_plane_choice(SectionPlaneChoice choice);
    SectionPlaneChoice plane_choice() const { return m_plane_choice; }

    const SectionView& section() const { return m_section; }
    const RayDiagram& diagram() const { return m_diagram; }
    int selected_object() const { return m_selected; }  // index into Scene::objects, or -1
    // Where the drawing is placed now (kept from the press while dragging), and where a
    // point of the plane is drawn, in widget pixels.
    DiagramView placement() const;
    QPointF to_widget(const DiagramPoint& p) const;

    // An object is being dragged (the button down and moved): the 3-D view renders drafts.
    bool is_dragging() const { return m_dragged && m_drag_object >= 0; }

    // Writes the drawing as SVG, atomically; `error` says why not.
    bool export_svg(const QString& path, QString* error) const;

signals:
    void object_picked(int object);  // a click (not a drag) on an object's section
    void edit_refused(const QString& message);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    // Zooms about the point under the cursor; a new selection or plane fits the view again.
    void wheelEvent(QWheelEvent* event) override;

private:
    void refresh();
    DiagramPoint to_plane(const QPointF& p) const;
    int object_at(const QPointF& p) const;  // the object whose section is under p, or -1

    SceneDocument* m_document;
    QString m_pointer;
    int m_selected = -1;
    SectionPlaneChoice m_plane_choice = SectionPlaneChoice::Default;
    SectionPlane m_plane;
    SectionView m_section;
    RayDiagram m_diagram;
    SectionExtent m_extent;  // what is shown; see refresh()
    bool m_refit = true;
    int m_fitted_objects = -1;

    // A drag: the plane and placement stay as they were at the press, so the object
    // follows the mouse.
    int m_drag_object = -1;
    bool m_dragged = false;
    QPointF m_press;
    DiagramView m_drag_view;
    nlohmann::json m_before;
};

}  // namespace lenslab::gui
