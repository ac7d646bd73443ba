#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>

#include "math/rng.h"
#include "render/integrator.h"

namespace lenslab {

namespace {

constexpr int kTileSize = 16;

// Stream index for a pixel: distinct per pixel, independent of which thread runs it.
uint64_t pixel_stream(int x, int y, int width) {
    return static_cast<uint64_t>(y) * static_cast<uint64_t>(width) + static_cast<uint64_t>(x);
}

}  // namespace

bool PixelIntegrator::render(const Scene& scene, const Camera& camera, Film& film,
                             RenderControl& control) {
    const int w = film.width(), h = film.height();
    const int tiles_x = (w + kTileSize - 1) / kTileSize;
    const int tiles_y = (h + kTileSize - 1) / kTileSize;
    const int tiles = tiles_x * tiles_y;
    const int spp = scene.render.spp;
    // Stratify the pixel samples on a sqrt(spp) grid when spp is square, else jitter.
    const int strata = static_cast<int>(std::lround(std::sqrt(spp)));
    const bool stratified = strata * strata == spp;
    std::atomic<int> done{0};

    tbb::parallel_for(
        tbb::blocked_range<int>(0, tiles, 1), [&](const tbb::blocked_range<int>& range) {
            for (int tile = range.begin(); tile != range.end(); ++tile) {
                if (control.cancelled()) return;
                const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
                for (int y = y0; y < std::min(y0 + kTileSize, h); ++y) {
                    for (int x = x0; x < std::min(x0 + kTileSize, w); ++x) {
                        // Checked per pixel: one pixel of a deep scene at many spp can take long.
                        if (control.cancelled()) return;
                        Rng rng(scene.render.seed, pixel_stream(x, y, w));
                        Rgb sum;
                        for (int s = 0; s < spp; ++s) {
                            double jx = rng.uniform(), jy = rng.uniform();
                            if (stratified) {
                                jx = ((s % strata) + jx) / strata;
                                jy = ((s / strata) + jy) / strata;
                            }
                            // Each camera sample carries its own four wavelengths; the hero
                            // wavelengths of a pixel's samples are stratified too, visited in a
                            // scrambled order so they do not follow the sample positions.
                            const double u_lambda = ((s * 7919 + 13) % spp + rng.uniform()) / spp;
                            const SampledWavelengths lambdas = SampledWavelengths::sample(u_lambda);
                            const Rgb l =
                                radiance(camera.generate_ray(x + jx, y + jy), lambdas, rng);
                            // A non-finite sample would poison the pixel; it is a bug, but the
                            // picture must stay usable (no NaN may reach a pixel), and
                            // the count tells the user.
                            if (l.is_finite()) {
                                sum += l;
                            } else {
                                control.count_non_finite_sample();
                            }
                        }
                        film.set(x, y, sum * (1.0 / spp));
                    }
                }
                control.report(static_cast<double>(++done) / tiles);
            }
        });
    return done == tiles;
}

}  // namespace lenslab
