#include "render/render_session.h"

#include <tbb/task_arena.h>

#include <chrono>
#include <memory>
#include <string>

#include "render/camera.h"
#include "scene/limits.h"

namespace lenslab {

void check_image_resources(const RenderSettings& s) {
    if (auto problem = image_size_problem(s.width, s.height))
        throw ResourceError("image: " + *problem);
    // The film (3 floats a pixel) and, while it is written, one more copy of it (EXR).
    const uint64_t need =
        static_cast<uint64_t>(s.width) * static_cast<uint64_t>(s.height) * 2 * sizeof(PixelRgb);
    check_memory_budget(
        need, "image: " + std::to_string(s.width) + " x " + std::to_string(s.height) + " needs", "",
        "render a smaller image");
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
    result.cancelled = !finished;
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.stats = integrator->stats(result.seconds);
    return result;
}

}  // namespace lenslab
