#pragma once
// What every integrator offers the render session.

#include <memory>
#include <string>

#include "image/film.h"
#include "optics/spectrum.h"
#include "render/camera.h"
#include "render/render_control.h"
#include "render/render_stats.h"
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
    // What the renders so far did (passes, photons, timings), with a summary line. `seconds`:
    // how long the caller's render took, for the rates in the summary.
    virtual RenderStats stats(double /*seconds*/) const { return {}; }
};

// A rectangle of pixels [x0, x1) x [y0, y1).
struct PixelWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

// Base for integrators that estimate radiance along independent camera rays. Handles the
// tiles, the threads, the per-pixel random streams and the pixel samples.
class PixelIntegrator : public Integrator {
public:
    bool render(const Scene& scene, const Camera& camera, Film& film,
                RenderControl& control) override;
    // Renders only the pixels of `window`, each exactly as render() would (every pixel has a
    // random stream of its own), and leaves the others black: a small part of an image at
    // far more samples than the whole could take (a caustic's reference, bench/).
    bool render_window(const Scene& scene, const Camera& camera, Film& film, RenderControl& control,
                       const PixelWindow& window);

protected:
    explicit PixelIntegrator(const Scene& scene) : m_scene(scene) {}
    // The linear sRGB of the radiance along `ray`. `w`: the camera sample's wavelengths, for
    // what depends on the wavelength (dispersion); light that does not may be coloured
    // exactly (render/path_colour.h). `split`: the wavelengths a path splits into at
    // dispersive glass, the same for every pixel's sample of this index; nullptr unless
    // splits_at_dispersion().
    virtual Rgb radiance(const Ray& ray, const SampledWavelengths& w,
                         const class DispersionSplit* split, class Rng& rng) const = 0;
    // Whether radiance() takes a split (render/dispersion_split.h).
    virtual bool splits_at_dispersion() const { return false; }
    const Scene& m_scene;
};

// An integrator whose image improves pass by pass and keeps what it learnt between passes
// (sppm's shrinking radii), so it cannot be run as independent passes and averaged. The
// render session runs passes until render.passes or render.time; the editor's viewport
// runs them one at a time and shows the image after each.
class ProgressiveIntegrator : public Integrator {
public:
    // Runs `scene.render.passes` passes, or as many as fit in `scene.render.time` seconds,
    // then develops the image into `film`.
    bool render(const Scene& scene, const Camera& camera, Film& film,
                RenderControl& control) override;

    // One more pass. Returns false, having changed nothing, when `control` was cancelled.
    virtual bool add_pass(RenderControl& control) = 0;
    virtual int passes() const = 0;
    // The estimate after the passes so far, into `film` (already sized; black before any).
    virtual void develop(Film& film) const = 0;
};

}  // namespace lenslab
