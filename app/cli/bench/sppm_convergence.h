#pragma once
// How fast sppm converges, measured against a long path-traced reference: the error of the
// sppm image after 1, 2, 4, ... passes, and of path-traced images of growing sample counts,
// each with the time it took, so the two can be compared at equal time.
// `lenslab bench sppm` runs it and writes the numbers and plots (docs/performance.md).

#include <functional>
#include <string>
#include <vector>

#include "image/film.h"
#include "scene/scene.h"

namespace lenslab {

struct ConvergenceSettings {
    int width = 128, height = 128;
    int reference_spp = 4096;
    // An earlier run's reference (its reference.exr) instead of a new one: a long reference
    // is rendered once and measured against many times. Must be width x height.
    std::string reference_file;
    std::vector<int> passes{1, 2, 4, 8, 16, 32, 64, 128, 256};  // sppm snapshots (cumulative)
    std::vector<int> path_spp{1, 4, 16, 64, 256, 1024};
    int threads = 0;  // 0: all cores
    // A rectangle of pixels [x0, x1) x [y0, y1) measured on its own too (a caustic, say);
    // empty (x1 <= x0) for none.
    int region[4] = {0, 0, 0, 0};
    // Samples per pixel of the region's own reference, rendered apart (a caustic needs far
    // more than the whole image can be given); 0: the region is measured on the reference.
    int region_spp = 0;
    bool has_region() const { return region[2] > region[0] && region[3] > region[1]; }
};

struct ConvergencePoint {
    std::string integrator;   // integrators::kSppm or kPath
    int amount = 0;           // passes or samples per pixel
    double seconds = 0;       // rendering time to this point
    double block_error = 0;   // mean over 8x8-pixel blocks of |block - reference| / reference
    double rms_error = 0;     // RMS over pixels of the luminance error, over the reference's mean
    double region_error = 0;  // rms_error over the region only
};

struct ConvergenceResult {
    Film reference;
    double reference_seconds = 0;
    Film region_reference;  // with region_spp: the region's pixels only, the rest black
    double region_reference_seconds = 0;
    std::vector<ConvergencePoint> points;
    Film sppm_last;  // the sppm image after the most passes
};

// Mean over blocks of `block` x `block` pixels of |mean(a) - mean(reference)| / mean(reference),
// in luminance; blocks the reference leaves black are skipped.
double block_relative_error(const Film& a, const Film& reference, int block = 8);
// Root mean square over pixels of the luminance difference, divided by the reference's mean.
double rms_relative_error(const Film& a, const Film& reference);
// rms_relative_error over the pixels [x0, x1) x [y0, y1) only (the reference's mean there).
double region_relative_error(const Film& a, const Film& reference, const int region[4]);

// Renders the reference (path, `reference_spp`, a seed of its own; the region apart at
// `region_spp`), then sppm pass by pass and path at each sample count. `log` receives one line per
// measurement.
ConvergenceResult run_convergence(const Scene& scene, const ConvergenceSettings& s,
                                  const std::function<void(const std::string&)>& log);

std::string convergence_csv(const ConvergenceResult& r);

}  // namespace lenslab
