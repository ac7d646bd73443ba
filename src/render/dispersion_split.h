#pragma once
// Glass without confetti (issue 39). A camera path that meets a dispersive refraction can
// follow only one wavelength from there on; with one random wavelength per pixel sample,
// every pixel behind dispersive glass is one random colour at 1 sample per pixel. Instead the
// path splits there into several wavelengths stratified across the visible band (POV-Ray's
// `dispersion_samples`, 7 by default), each refracted and traced on with its own index.
//
// The split's wavelengths are the same in every pixel for a given pixel-sample index (their
// offset is drawn once per sample index from the render's seed), so neighbouring pixels
// agree and no per-pixel colour noise is left; over samples, and over seeds, the offsets are
// stratified and the estimate converges. The wavelengths' XYZ weights are normalised so the
// set integrates D65 exactly: white light through clear glass stays white whatever the
// offset. This ratio estimator is biased for other spectra, far less than the noise it
// removes: averaged over offsets, blackbodies from 1900 K to 10000 K and equal energy within
// 0.3% of their colour (tests/render/test_dispersion_split.cpp).

#include <cstdint>
#include <vector>

#include "math/vec3.h"

namespace lenslab {

class Scene;

// Density (per nm) over [kLambdaMinNm, kLambdaMaxNm] that follows the eye's sensitivity:
// proportional to 1 / cosh^2(0.0072 (nm - 538)), the shape pbrt-v4 samples visible
// wavelengths with, so strata are narrow where colour changes fast. Its inverse CDF at u.
double visible_wavelength(double u);
double visible_wavelength_pdf(double nm);

struct SplitWavelength {
    double nm;
    Vec3 xyz_weight;  // the XYZ a unit of light at nm adds to the pixel (xyz_sample_to_rgb)
};

class DispersionSplit {
public:
    // `count` (>= 1) wavelengths, one in each stratum of visible_wavelength's density,
    // at the fraction `offset` in [0, 1) of its stratum.
    DispersionSplit(int count, double offset);
    const std::vector<SplitWavelength>& wavelengths() const { return m_wavelengths; }

private:
    std::vector<SplitWavelength> m_wavelengths;
};

// The splits of a render, one per pixel-sample index up to kDistinctSplits (later indices
// reuse them: that many offsets times `count` strata are thousands of wavelengths), offsets
// stratified over the indices (van der Corput, rotated by the seed). `count` 1: empty.
inline constexpr int kDistinctSplits = 1024;
std::vector<DispersionSplit> dispersion_splits(int count, int spp, uint64_t seed);

// The render's dispersion_samples, `auto` (0) resolved: 7 as POV-Ray, and 1 (no split)
// when nothing in the scene disperses.
int dispersion_samples(const Scene& scene);

}  // namespace lenslab
