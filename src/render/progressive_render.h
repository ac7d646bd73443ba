#pragma once
// A render that improves pass by pass, for interactive views. A progressive integrator
// (sppm) runs its own passes, and lives as long as the render; the others add one sample
// per pixel with a fresh seed each pass to a running average, the photon maps traced once,
// with the first pass, and reused by the later ones (render/averaged_passes.h).

#include <memory>

#include "image/film.h"
#include "render/integrator.h"
#include "render/render_control.h"
#include "render/render_stats.h"
#include "scene/scene.h"

namespace lenslab {

class ProgressiveRender {
public:
    // threads <= 0: all cores. The scene is copied; later edits need a new ProgressiveRender.
    // Throws std::invalid_argument for an unknown integrator.
    explicit ProgressiveRender(const Scene& scene, int threads = 0);
    ~ProgressiveRender();
    ProgressiveRender(const ProgressiveRender&) = delete;
    ProgressiveRender& operator=(const ProgressiveRender&) = delete;

    // Renders one more pass and adds it to the image. Returns false, adding nothing, when
    // `control` was cancelled before the pass finished.
    bool add_pass(RenderControl& control);

    int passes() const { return m_integrator->passes(); }
    Film image() const;  // the image after the passes so far (black before the first)
    // The integrator's statistics after the passes so far; `seconds`: the time they took.
    RenderStats stats(double seconds) const { return m_integrator->stats(seconds); }

private:
    Scene m_scene;
    int m_threads;
    std::unique_ptr<ProgressiveIntegrator> m_integrator;  // refers to m_scene
};

}  // namespace lenslab
