#pragma once
// The mean green value of a scene's rendered image: the radiance closed forms predict, over
// pixels that all see the same thing (the media tests' measure).

#include "render/render_session.h"

namespace lenslab::testing {

inline double mean_green_of_render(const Scene& scene) {
    RenderControl control;
    const RenderResult result = render_scene(scene, control);
    double mean = 0;
    for (const PixelRgb& p : result.film.pixels()) mean += p.g / result.film.pixels().size();
    return mean;
}

}  // namespace lenslab::testing
