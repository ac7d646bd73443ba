#pragma once
// The scene's camera as the 3-D view shows it: the render's film fitted into a rectangle of
// the widget. Rays through widget points (picking, placing) and the widget points of scene
// points (handles, light icons) come from the renderer's own camera, so what is drawn over
// the render lies where the render shows it.

#include <QPointF>
#include <QRectF>
#include <optional>

#include "render/camera.h"
#include "scene/scene.h"

namespace lenslab::gui {

class ViewCamera {
public:
    // `image`: where the film is drawn in the widget.
    ViewCamera(const CameraSettings& settings, int film_width, int film_height,
               const QRectF& image);

    Ray ray(const QPointF& widget) const;
    // Where `p` is drawn, or nothing when it is behind the eye.
    std::optional<QPointF> project(const Vec3& p) const;
    // Scene units one widget pixel spans at the depth of `p` (handles keep their size on
    // screen whatever the distance).
    double units_per_pixel(const Vec3& p) const;
    const Vec3& eye() const { return m_settings.position; }
    const QRectF& image() const { return m_image; }

private:
    CameraSettings m_settings;
    Camera m_camera;
    int m_width, m_height;
    QRectF m_image;
};

}  // namespace lenslab::gui
