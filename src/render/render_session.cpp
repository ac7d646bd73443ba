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
#include "scene/limits.h"

namespace lenslab {

const std::vector<std::string>& integrator_names() { return kIntegratorNames; }

std::unique_ptr<Integrator> make_integrator(const Scene& scene) {
    if (scene.render.integrator == "whitted") return std::make_unique<WhittedIntegrator>(scene);
    if (scene.render.integrator == "photon_map") return std::make_unique<PhotonMapIntegrator>(scene);
    if (scene.render.integrator == "sppm") return std::make_unique<SppmIntegrator>(scene);
    if (scene.render.integrator == "path") return std::make_unique<PathIntegrator>(scene);
    throw std::invalid_argument("unknown integrator '" + scene.render.integrator + "'");
}

void check_image_resources(const RenderSettings& s) {
    if (auto problem = image_size_problem(s.width, s.height)) throw ResourceError("image: " + *problem);
    // The film (3 floats a pixel) and, while it is written, one more copy of it (EXR).
    const uint64_t need = static_cast<uint64_t>(s.width) * static_cast<uint64_t>(s.height) * 2 * sizeof(PixelRgb);
    const uint64_t have = available_memory_bytes();
    if (need > have / 10 * 8) {
        throw ResourceError("image: " + std::to_string(s.width) + " x " + std::to_string(s.height) +
                            " needs " + std::to_string(need >> 20) + " MiB, but only " +
                            std::to_string(have >> 20) + " MiB of memory is available; render a smaller image");
    }
}

RenderResult render_scene(const Scene& scene, RenderControl& control, int threads) {
    check_image_resources(scene.render);
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
