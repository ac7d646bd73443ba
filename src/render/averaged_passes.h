#pragma once
// Runs an integrator that takes samples per pixel pass by pass, for interactive views: each
// pass adds one sample per pixel with a fresh seed to a running average. One integrator
// serves every pass, so what it builds in the first (the photon maps) is reused by the
// later ones; it relies on Integrator::render taking the seed and the sample count from the
// scene it is given (PixelIntegrator does).

#include <memory>
#include <vector>

#include "render/integrator.h"

namespace lenslab {

class AveragedPasses final : public ProgressiveIntegrator {
public:
    // `scene` must outlive this; its render.spp is the samples per pixel of each pass.
    AveragedPasses(const Scene& scene, std::unique_ptr<Integrator> integrator);

    bool add_pass(RenderControl& control) override;
    int passes() const override { return m_passes; }
    void develop(Film& film) const override;
    // The integrator's, with the passes run here.
    RenderStats stats(double seconds) const override;

private:
    const Scene& m_scene;
    std::unique_ptr<Integrator> m_integrator;
    int m_passes = 0;
    std::vector<double> m_sum;  // RGB per pixel
};

}  // namespace lenslab
