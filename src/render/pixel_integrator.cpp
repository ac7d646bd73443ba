#include <atomic>
#include <cmath>

#include "cluster/dealt_parts.h"
#include "cluster/rank_order_sum.h"
#include "math/rng.h"
#include "render/dispersion_split.h"
#include "render/integrator.h"
#include "util/parallel_in_order.h"

namespace lenslab {

namespace {

constexpr int kTileSize = 16;

// Stream index for a pixel: distinct per pixel, independent of which thread runs it.
uint64_t pixel_stream(int x, int y, int width) {
    return static_cast<uint64_t>(y) * static_cast<uint64_t>(width) + static_cast<uint64_t>(x);
}

// Tile `tile`'s pixels, row by row, out of or into `film`.
template <class Visit>
void for_each_tile_pixel(const Film& film, int tile, const Visit& visit) {
    const int tiles_x = (film.width() + kTileSize - 1) / kTileSize;
    const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
    for (int y = y0; y < std::min(y0 + kTileSize, film.height()); ++y)
        for (int x = x0; x < std::min(x0 + kTileSize, film.width()); ++x) visit(x, y);
}

// Rank 0 receives the tiles the other ranks rendered. Each pixel's samples come from its own
// random stream (pixel_stream), so a tile is the same whichever rank renders it.
void gather_tiles_to_root(Communicator& comm, Film& film, int tiles) {
    std::vector<std::vector<PixelRgb>> parts(static_cast<size_t>(tiles));
    for (int tile = comm.rank(); tile < tiles; tile += comm.size()) {
        for_each_tile_pixel(film, tile, [&](int x, int y) {
            parts[static_cast<size_t>(tile)].push_back(film.at(x, y));
        });
    }
    gather_dealt_parts_to_root(comm, parts);
    if (!comm.is_root()) return;
    for (int tile = 0; tile < tiles; ++tile) {
        if (dealt_to(tile, comm)) continue;
        const std::vector<PixelRgb>& part = parts[static_cast<size_t>(tile)];
        size_t i = 0;
        for_each_tile_pixel(film, tile, [&](int x, int y) {
            if (i < part.size()) film.at(x, y) = part[i++];
        });
    }
}

}  // namespace

bool PixelIntegrator::render(const Scene& scene, const Camera& camera, Film& film,
                             RenderControl& control) {
    return render_window(scene, camera, film, control, {0, 0, film.width(), film.height()});
}

bool PixelIntegrator::render_window(const Scene& scene, const Camera& camera, Film& film,
                                    RenderControl& control, const PixelWindow& window) {
    const int w = film.width(), h = film.height();
    const int tiles_x = (w + kTileSize - 1) / kTileSize;
    const int tiles_y = (h + kTileSize - 1) / kTileSize;
    const int tiles = tiles_x * tiles_y;
    const int spp = scene.render.spp;
    // Stratify the pixel samples on a sqrt(spp) grid when spp is square, else jitter.
    const int strata = static_cast<int>(std::lround(std::sqrt(spp)));
    const bool stratified = strata * strata == spp;
    const std::vector<DispersionSplit> splits =
        splits_at_dispersion()
            ? dispersion_splits(dispersion_samples(scene), spp, scene.render.seed)
            : std::vector<DispersionSplit>{};
    std::atomic<int> done{0};
    // In a job of several ranks each renders the tiles dealt to it.
    Communicator& comm = control.cluster();
    auto in_window = [&](int tile) {
        const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
        return x0 < window.x1 && x0 + kTileSize > window.x0 && y0 < window.y1 &&
               y0 + kTileSize > window.y0;
    };
    int mine = 0;
    for (int tile = 0; tile < tiles; ++tile) mine += dealt_to(tile, comm) && in_window(tile);

    // Tiles begun in order, one at a time: a thread never holds a run of slow ones.
    parallel_for_in_order(tiles, [&](int64_t index) {
        const int tile = static_cast<int>(index);
        if (!dealt_to(tile, comm) || !in_window(tile)) return;
        if (control.cancelled()) return;
        const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
        for (int y = y0; y < std::min(y0 + kTileSize, h); ++y) {
            for (int x = x0; x < std::min(x0 + kTileSize, w); ++x) {
                if (!window.contains(x, y)) continue;
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
                    const DispersionSplit* split =
                        splits.empty() ? nullptr : &splits[s % splits.size()];
                    const Rgb l =
                        radiance(camera.generate_ray(x + jx, y + jy), lambdas, split, rng);
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
        control.report(static_cast<double>(++done) / mine);
    });
    if (comm.alone()) return done == mine;
    gather_tiles_to_root(comm, film, tiles);
    uint64_t unfinished[1] = {done == mine ? 0u : 1u};
    sum_in_rank_order(comm, unfinished);
    return unfinished[0] == 0;
}

}  // namespace lenslab
