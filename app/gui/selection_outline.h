#pragma once
// The selected object's silhouette outline, drawn over the render: rays through the view
// (every second widget pixel, inside the object's projected box) ask whether they meet one
// of the shapes the scene entry made. The whole silhouette is outlined, also where another
// object hides it, so a lens behind a stop is still found.

#include <QImage>
#include <QRect>

#include "scene/scene.h"
#include "view_camera.h"

namespace lenslab::gui {

struct SelectionOutline {
    QImage image;  // the outline on transparency, one pixel a cell
    QRect where;   // where it is drawn in the widget (cells scaled up)
};

// The outline of scene entry `source` (an index into the file's `objects`), in `colour`;
// empty when the entry has no shapes or none is in view.
SelectionOutline selection_outline(const Scene& scene, int source, const ViewCamera& view,
                                   const QColor& colour);

}  // namespace lenslab::gui
