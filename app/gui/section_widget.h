#pragma once
// The 2-D section view: the plane through the selected lens's axis
// (analysis/section/section_view.h) with every object's cross-section and the rays traced
// through them, in their true colours. It follows the selection, redraws on every scene
// change, pans and zooms, and is a bench to teach with: an object dragged in it moves (with
// Shift: turns about its centre) by the same undoable edit as the property panel's while the
// rays follow; a clicked ray reports its angles at every surface; a ruler and a protractor
// measure the drawing.

#include <QPointF>
#include <QWidget>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "analysis/section/section_view.h"
#include "section_measure.h"

namespace lenslab::gui {

class SceneDocument;

// What a left drag does in the view: move (and pan on empty paper), measure a length, or
// lay the protractor's arms along the drawing.
enum class SectionTool { Move, Ruler, Protractor };

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
    // Rays per source: across the selection's beam and in each light's fan.
    void set_rays(int rays);
    int rays() const { return m_rays; }
    void set_tool(SectionTool tool);
    SectionTool tool() const { return m_tool; }
    // Shows every cross-section and where every ray starts (as a new selection does), or the
    // selected object with room of its own size around it.
    void fit_all();
    void fit_selection();

    const SectionView& section() const { return m_section; }
    const RayDiagram& diagram() const { return m_diagram; }
    int selected_object() const { return m_selected; }  // index into Scene::objects, or -1
    // Where the drawing is placed now (kept from the press while dragging), and where a
    // point of the plane is drawn, in widget pixels.
    DiagramView placement() const;
    // The ruler and protractor as laid, as drawing in the plane.
    MeasureDrawing measurements() const;
    QPointF to_widget(const DiagramPoint& p) const;

    // The ray last clicked (an index into section().rays, -1 for none) and its read-out.
    int inspected_ray() const { return m_inspected; }
    const QString& inspected_text() const { return m_inspected_text; }
    // The protractor's reading once both arms are laid, in degrees.
    std::optional<double> protractor_reading() const;

    // An object is being dragged (the button down and moved): the 3-D view renders drafts.
    bool is_dragging() const { return m_dragged && m_drag_object >= 0; }

    // Writes the drawing as SVG, or the view as it is (with its measurements) as PNG,
    // atomically; `error` says why not.
    bool export_svg(const QString& path, QString* error) const;
    bool export_png(const QString& path, QString* error);

signals:
    void object_picked(int object);  // a click (not a drag) on an object's section
    void edit_refused(const QString& message);
    void ray_inspected(const QString& text);  // empty: none
    void measured(const QString& text);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    // Zooms about the point under the cursor; a new selection or plane fits the view again.
    void wheelEvent(QWheelEvent* event) override;

private:
    void refresh();
    void show_extent(const SectionExtent& extent);  // widened to the widget's shape
    void inspect(int ray);
    void drag_object_to(const QPointF& at, bool turn);
    DiagramPoint to_plane(const QPointF& p) const;
    int object_at(const QPointF& p) const;  // the object whose section is under p, or -1
    int ray_at(const QPointF& p) const;     // the ray drawn nearest p (within a few pixels), or -1
    std::optional<SectionArm> arm_at(const QPointF& p) const;
    // Lays arms that lie on rays along the same rays as traced now; whether any moved.
    bool follow_rays(std::vector<SectionArm>& arms) const;

    SceneDocument* m_document;
    QString m_pointer;
    int m_selected = -1;
    SectionPlaneChoice m_plane_choice = SectionPlaneChoice::Default;
    SectionTool m_tool = SectionTool::Move;
    int m_rays = 15;
    SectionPlane m_plane;
    SectionView m_section;
    RayDiagram m_diagram;
    SectionExtent m_wanted;     // what was asked for: a fit, a zoom, a pan
    SectionExtent m_extent;     // what is shown: m_wanted widened to the widget's shape
    bool m_refit = true;        // fit all at the next refresh (a new selection or plane)
    bool m_refit_plane = true;  // the plane chosen again: not kept for a new selection
    bool m_has_plane = false;
    int m_fitted_objects = -1;

    int m_inspected = -1;
    QString m_inspected_text;
    std::optional<DiagramPoint> m_ruler_from, m_ruler_to;
    std::vector<SectionArm> m_arms;  // the protractor's, 0 to 2

    // A drag: the plane and placement stay as they were at the press, so the object
    // follows the mouse; on empty paper (or with the middle button) the view pans.
    int m_drag_object = -1;
    bool m_dragged = false;
    bool m_panning = false;
    QPointF m_press, m_last;
    DiagramView m_drag_view;
    DiagramPoint m_pivot;  // the dragged object's centre in the plane, for a turn
    nlohmann::json m_before;
};

}  // namespace lenslab::gui
