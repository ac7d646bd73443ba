#pragma once
// What every integrator offers the render session.

#include <memory>
#include <string>

#include "render/camera.h"
#include "render/film.h"
#include "optics/spectrum.h"
#include "render/render_control.h"
#include "scene/scene.h"

namespace lenslab {

class Integrator {
public:
    virtual ~Integrator() = default;
    // Fills `film` (already sized). Runs on the calling thread's TBB arena; stops early,
    // leaving unfinished pixels black, when `control` is cancelled. Returns true when every
    // pixel was finished.
    virtual bool render(const Scene& scene, const Camera& camera, Film& film,
                        RenderControl& control) = 0;
};

// Base for integrators that estimate radiance along independent camera rays. Handles the
// tiles, the threads, the per-pixel random streams and the pixel samples.
class PixelIntegrator : public Integrator {
public:
    bool render(const Scene& scene, const Camera& camera, Film& film,
                RenderControl& control) override;

protected:
    explicit PixelIntegrator(const Scene& scene) : m_scene(scene) {}
    // Radiance along `ray` at the sampled wavelengths.
    virtual SampledSpectrum radiance(const Ray& ray, const SampledWavelengths& w, class Rng& rng) const = 0;
    const Scene& m_scene;
};

}  // namespace lenslab
