#pragma once
// Runs one render of a scene: picks the integrator, sets the thread count, reports progress.

#include <memory>
#include <optional>

#include "render/film.h"
#include "render/integrators/sppm.h"
#include "render/photon_tracer.h"
#include "render/render_control.h"
#include "scene/scene.h"

namespace lenslab {

struct RenderResult {
    Film film;
    double seconds = 0;
    bool cancelled = false;
    std::optional<PhotonTracingStats> photons;  // set by the photon-map integrator
    std::optional<SppmStats> sppm;              // set by sppm
};

// The integrator the scene's render block asks for; every name in kIntegratorNames.
std::unique_ptr<class Integrator> make_integrator(const Scene& scene);

// threads <= 0 means all hardware threads. The result is identical for any thread count.
RenderResult render_scene(const Scene& scene, RenderControl& control, int threads = 0);

}  // namespace lenslab
