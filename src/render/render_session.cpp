#include "render/render_session.h"

#include <chrono>
#include <memory>
#include <stdexcept>

#include <tbb/task_arena.h>

#include "render/camera.h"
#include "render/integrators/path.h"
#include "render/integrators/photon_map.h"
#include "render/integrators/sppm.h"
#include "render/integrators/whitted.h"

namespace lenslab {

std::unique_ptr<Integrator> make_integrator(const Scene& scene) {
    if (scene.render.integrator == "whitted") return std::make_unique<WhittedIntegrator>(scene);
    if (scene.render.integrator == "photon_map") return std::make_unique<PhotonMapIntegrator>(scene);
    if (scene.render.integrator == "sppm") return std::make_unique<SppmIntegrator>(scene);
    if (scene.render.integrator == "path") return std::make_unique<PathIntegrator>(scene);
    throw std::invalid_argument("unknown integrator '" + scene.render.integrator + "'");
}

RenderResult render_scene(const Scene& scene, RenderControl& control, int threads) {
    const auto start = std::chrono::steady_clock::now();
    RenderResult result;
    result.film = Film(scene.render.width, scene.render.height);
    const Camera camera(scene.camera, scene.render.width, scene.render.height);
    auto integrator = make_integrator(scene);
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    bool finished = false;
    arena.execute([&] { finished = integrator->render(scene, camera, result.film, control); });
    if (const auto* pm = dynamic_cast<const PhotonMapIntegrator*>(integrator.get())) {
        result.photons = pm->photon_stats();
    }
    if (const auto* sppm = dynamic_cast<const SppmIntegrator*>(integrator.get())) result.sppm = sppm->stats();
    result.cancelled = !finished;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace lenslab
