#pragma once
// Runs one render of a scene: picks the integrator, sets the thread count, reports progress.

#include "image/film.h"
#include "render/integrator_registry.h"
#include "render/memory_budget.h"
#include "render/render_control.h"
#include "render/render_stats.h"
#include "scene/scene.h"

namespace lenslab {

struct RenderResult {
    Film film;
    double seconds = 0;
    bool cancelled = false;
    RenderStats stats;  // what the integrator reports; its summary's rates over `seconds`
};

// Refuses, before the film is allocated, an image beyond the pixel limit (src/scene/limits.h)
// or too large for the memory available. Throws ResourceError. render_scene calls it.
void check_image_resources(const RenderSettings& s);

// threads <= 0 means all hardware threads. The result is identical for any thread count.
RenderResult render_scene(const Scene& scene, RenderControl& control, int threads = 0);

}  // namespace lenslab
