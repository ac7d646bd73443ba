#pragma once
// Move and rotate handles drawn over the 3-D view at the selection, as in Blender: three
// arrows along the scene's x, y and z (red, green, blue) drag the selection along that axis;
// three rings about the same axes turn it. They keep one size on screen whatever the
// distance. Only geometry lives here: the viewport turns drags into undoable edits.

#include <QPainter>
#include <QPointF>
#include <vector>

#include "view_camera.h"

namespace lenslab::gui {

enum class HandleKind { None, Move, Rotate };

struct Handle {
    HandleKind kind = HandleKind::None;
    int axis = 0;  // 0, 1, 2: the scene's x, y, z
};

class TransformHandles {
public:
    // Handles at `pivot`; rings only when the selection can turn (`rotates`).
    TransformHandles(const ViewCamera& view, const Vec3& pivot, bool rotates);

    void paint(QPainter& painter, const Handle& active) const;
    // The handle within reach of a widget point (arrows before rings), or kind None.
    Handle at(const QPointF& widget) const;

    // The distance along `axis` a drag from `from` to `to` on its arrow moves the selection.
    double move_distance(int axis, const QPointF& from, const QPointF& to) const;
    // The angle (radians, right-handed about +axis) a drag from `from` to `to` on a ring turns
    // it: the angle swept about the pivot on screen.
    double rotate_angle(int axis, const QPointF& from, const QPointF& to) const;
    // Snap steps (with Ctrl held): a round length near a tenth of an arrow, 15 degrees.
    double move_snap() const;
    static double rotate_snap();

    // For tests and the screenshot: a point on each arrow's shaft and on each ring.
    QPointF arrow_grip(int axis) const;
    std::optional<QPointF> ring_grip(int axis) const;
    bool has_arrow(int axis) const { return m_arrows[axis].visible; }

private:
    struct Arrow {
        QPointF base, tip;
        bool visible = false;  // false when the axis points at the eye (no length on screen)
    };

    Vec3 m_pivot;
    QPointF m_centre;
    double m_length = 1;  // an arrow's length in scene units
    Arrow m_arrows[3];
    std::vector<QPolygonF> m_rings[3];  // the parts of each ring in front of the eye
    bool m_axis_faces_eye[3] = {false, false, false};
    bool m_valid = false;
};

// The axis colours: x red, y green, z blue.
QColor handle_colour(int axis);

}  // namespace lenslab::gui
