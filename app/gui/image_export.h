#pragma once
// File ▸ Export image: the scene rendered off-screen at its own resolution with its own
// integrator (what `lenslab render` writes, not the view's smaller preview), on a worker
// thread behind a progress dialog whose Cancel stops it; then written atomically as PNG or
// EXR (by the extension).

#include <QString>
#include <QWidget>

#include "scene/scene.h"

namespace lenslab::gui {

// Renders `scene` and writes it to `path`, the dialog over `parent`; returns when done.
// false: refused, failed or cancelled, `error` says which, and no file is left.
bool export_scene_image(const Scene& scene, const QString& path, QWidget* parent, QString* error);

}  // namespace lenslab::gui
