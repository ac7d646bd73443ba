#pragma once
// Runs one render of a scene: picks the integrator, sets the thread count, reports progress.

#include <memory>
#include <optional>
#include <string>
#include <vector>

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

// Every integrator make_integrator knows, by the name the scene file and --integrator use
// (kIntegratorNames): tests iterate over it, so a new integrator is covered once listed.
const std::vector<std::string>& integrator_names();

// The integrator the scene's render block asks for.
std::unique_ptr<class Integrator> make_integrator(const Scene& scene);

// Refuses, before the film is allocated, an image beyond the pixel limit (src/scene/limits.h)
// or too large for the memory available. Throws ResourceError. render_scene calls it.
void check_image_resources(const RenderSettings& s);

// threads <= 0 means all hardware threads. The result is identical for any thread count.
RenderResult render_scene(const Scene& scene, RenderControl& control, int threads = 0);

}  // namespace lenslab
