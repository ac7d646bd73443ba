#include "render/progressive_render.h"

#include <tbb/task_arena.h>

#include "render/camera.h"
#include "render/integrators/photon_map.h"
#include "render/render_session.h"

namespace lenslab {

ProgressiveRender::ProgressiveRender(const Scene& scene, int threads)
    : m_scene(scene), m_threads(threads),
      m_sum(size_t(scene.render.width) * scene.render.height * 3, 0.0) {
    m_scene.render.spp = 1;
    if (m_scene.render.integrator == "sppm") {
        m_sppm = std::make_unique<SppmIntegrator>(m_scene);
        m_sum = {};
    }
}

ProgressiveRender::~ProgressiveRender() = default;

bool ProgressiveRender::add_pass(RenderControl& control) {
    if (m_sppm) {
        bool finished = false;
        tbb::task_arena arena(m_threads > 0 ? m_threads : tbb::task_arena::automatic);
        arena.execute([&] { finished = m_sppm->add_pass(control); });
        if (finished) ++m_passes;
        return finished;
    }
    Scene pass = m_scene;
    // A different seed per pass gives independent samples; pass 0 keeps the scene's seed.
    pass.render.seed = m_scene.render.seed + static_cast<uint64_t>(m_passes) * 0x9E3779B9u;
    auto integrator = make_integrator(pass);
    auto* photon = dynamic_cast<PhotonMapIntegrator*>(integrator.get());
    if (photon && m_photons) photon->set_photon_map(m_photons);

    Film film(pass.render.width, pass.render.height);
    const Camera camera(pass.camera, pass.render.width, pass.render.height);
    bool finished = false;
    tbb::task_arena arena(m_threads > 0 ? m_threads : tbb::task_arena::automatic);
    arena.execute([&] { finished = integrator->render(pass, camera, film, control); });
    if (!finished) return false;

    if (photon && !m_photons) {
        m_photons = photon->shared_photon_map();
        m_photon_stats = photon->photon_stats();
    }
    for (size_t i = 0; i < film.pixels().size(); ++i) {
        m_sum[3 * i + 0] += film.pixels()[i].r;
        m_sum[3 * i + 1] += film.pixels()[i].g;
        m_sum[3 * i + 2] += film.pixels()[i].b;
    }
    ++m_passes;
    return true;
}

Film ProgressiveRender::image() const {
    Film film(m_scene.render.width, m_scene.render.height);
    if (m_sppm) {
        m_sppm->develop(film);
        return film;
    }
    const double inv = m_passes > 0 ? 1.0 / m_passes : 0.0;
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) {
            const size_t i = 3 * (size_t(y) * film.width() + x);
            film.set(x, y, Rgb{m_sum[i], m_sum[i + 1], m_sum[i + 2]} * inv);
        }
    }
    return film;
}

}  // namespace lenslab
