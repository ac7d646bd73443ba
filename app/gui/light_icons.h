#pragma once
// Lights drawn over the 3-D view as small glyphs where they are (a sun for a point light, a
// disc with an arrow along the beam for a beam), so they can be seen, clicked and dragged;
// the render itself shows only what they light.

#include <QPainter>
#include <QPointF>
#include <nlohmann/json.hpp>
#include <vector>

#include "view_camera.h"

namespace lenslab::gui {

struct LightIcon {
    int index = -1;  // into the document's `lights`
    Vec3 position;   // a point light's position, a beam's origin
    QPointF at;      // where it is drawn
    // A light that shines one way (a beam, a spot, an area light): a point along its direction
    // (or normal), on screen.
    std::optional<QPointF> beam_towards;
};

// The icons of a document's `lights` (as read: checked already) that are in front of the eye.
std::vector<LightIcon> light_icons(const nlohmann::json& document, const ViewCamera& view);
void paint_light_icon(QPainter& painter, const LightIcon& icon, bool selected);
// The icon under a widget point (the nearest within reach), or -1: its light's index.
int light_icon_at(const std::vector<LightIcon>& icons, const QPointF& widget);

}  // namespace lenslab::gui
