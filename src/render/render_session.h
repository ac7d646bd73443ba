#pragma once
// Runs one render of a scene: picks the integrator, sets the thread count, reports progress.

#include "render/film.h"
#include "render/render_control.h"
#include "scene/scene.h"

namespace lenslab {

struct RenderResult {
    Film film;
    double seconds = 0;
    bool cancelled = false;
};

// threads <= 0 means all hardware threads. The result is identical for any thread count.
RenderResult render_scene(const Scene& scene, RenderControl& control, int threads = 0);

}  // namespace lenslab
