#pragma once
// Runs one render of a scene: picks the integrator, sets the thread count, reports progress.

#include <optional>

#include "render/film.h"
#include "render/photon_tracer.h"
#include "render/render_control.h"
#include "scene/scene.h"

namespace lenslab {

struct RenderResult {
    Film film;
    double seconds = 0;
    bool cancelled = false;
    std::optional<PhotonTracingStats> photons;  // set by the photon-map integrator
};

// threads <= 0 means all hardware threads. The result is identical for any thread count.
RenderResult render_scene(const Scene& scene, RenderControl& control, int threads = 0);

}  // namespace lenslab
