#include "render/progressive_render.h"

#include <tbb/task_arena.h>

#include "render/integrator_registry.h"

namespace lenslab {

ProgressiveRender::ProgressiveRender(const Scene& scene, int threads)
    : m_scene(scene), m_threads(threads) {
    m_scene.render.spp = 1;
    m_integrator = make_progressive_integrator(m_scene);
}

ProgressiveRender::~ProgressiveRender() = default;

bool ProgressiveRender::add_pass(RenderControl& control) {
    bool finished = false;
    tbb::task_arena arena(m_threads > 0 ? m_threads : tbb::task_arena::automatic);
    arena.execute([&] { finished = m_integrator->add_pass(control); });
    return finished;
}

Film ProgressiveRender::image() const {
    Film film(m_scene.render.width, m_scene.render.height);
    m_integrator->develop(film);
    return film;
}

}  // namespace lenslab
