#include "render/averaged_passes.h"

#include "render/camera.h"

namespace lenslab {

AveragedPasses::AveragedPasses(const Scene& scene, std::unique_ptr<Integrator> integrator)
    : m_scene(scene),
      m_integrator(std::move(integrator)),
      m_sum(size_t(scene.render.width) * scene.render.height * 3, 0.0) {}

bool AveragedPasses::add_pass(RenderControl& control) {
    Scene pass = m_scene;
    // A different seed per pass gives independent samples; pass 0 keeps the scene's seed.
    pass.render.seed = m_scene.render.seed + static_cast<uint64_t>(m_passes) * 0x9E3779B9u;
    Film film(pass.render.width, pass.render.height);
    const Camera camera(pass.camera, pass.render.width, pass.render.height);
    if (!m_integrator->render(pass, camera, film, control)) return false;
    for (size_t i = 0; i < film.pixels().size(); ++i) {
        m_sum[3 * i + 0] += film.pixels()[i].r;
        m_sum[3 * i + 1] += film.pixels()[i].g;
        m_sum[3 * i + 2] += film.pixels()[i].b;
    }
    ++m_passes;
    return true;
}

void AveragedPasses::develop(Film& film) const {
    const double inv = m_passes > 0 ? 1.0 / m_passes : 0.0;
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) {
            const size_t i = 3 * (size_t(y) * film.width() + x);
            film.set(x, y, Rgb{m_sum[i], m_sum[i + 1], m_sum[i + 2]} * inv);
        }
    }
}

RenderStats AveragedPasses::stats(double seconds) const {
    RenderStats out = m_integrator->stats(seconds);
    out.passes = m_passes;
    return out;
}

}  // namespace lenslab
