#pragma once
// A render that improves pass by pass, for interactive views. With sppm a pass is one sppm
// pass (camera paths, photons, radius update) of one integrator that lives as long as the
// render. With the other integrators each pass adds one sample per pixel with a fresh seed
// to a running average; the photon maps are traced once, with the first pass, and reused by
// the later ones.

#include <memory>
#include <optional>
#include <vector>

#include "render/film.h"
#include "render/integrators/sppm.h"
#include "render/photon_tracer.h"
#include "render/render_control.h"
#include "scene/scene.h"

namespace lenslab {

class PhotonMap;

class ProgressiveRender {
public:
    // threads <= 0: all cores. The scene is copied; later edits need a new ProgressiveRender.
    explicit ProgressiveRender(const Scene& scene, int threads = 0);
    ~ProgressiveRender();
    ProgressiveRender(const ProgressiveRender&) = delete;
    ProgressiveRender& operator=(const ProgressiveRender&) = delete;

    // Renders one more pass and adds it to the image. Returns false, adding nothing, when
    // `control` was cancelled before the pass finished.
    bool add_pass(RenderControl& control);

    int passes() const { return m_passes; }
    Film image() const;  // the image after the passes so far (black before the first)
    const std::optional<PhotonTracingStats>& photon_stats() const { return m_photon_stats; }
    // Set when the scene's integrator is sppm.
    const SppmStats* sppm_stats() const { return m_sppm ? &m_sppm->stats() : nullptr; }

private:
    Scene m_scene;
    int m_threads;
    int m_passes = 0;
    std::vector<double> m_sum;  // RGB per pixel, averaged integrators
    std::shared_ptr<const PhotonMap> m_photons;
    std::optional<PhotonTracingStats> m_photon_stats;
    std::unique_ptr<SppmIntegrator> m_sppm;  // refers to m_scene
};

}  // namespace lenslab
