#include "render/dispersion_split.h"

#include <algorithm>
#include <cmath>

#include "math/rng.h"
#include "optics/spectrum.h"
#include "render/pass_wavelength.h"
#include "scene/scene.h"

namespace lenslab {

namespace {

constexpr double kPeakNm = 538.0, kSharpness = 0.0072;

double shape_cdf(double nm) { return std::tanh(kSharpness * (nm - kPeakNm)); }

}  // namespace

double visible_wavelength(double u) {
    const double lo = shape_cdf(kLambdaMinNm), hi = shape_cdf(kLambdaMaxNm);
    return kPeakNm + std::atanh(lo + u * (hi - lo)) / kSharpness;
}

double visible_wavelength_pdf(double nm) {
    const double c = std::cosh(kSharpness * (nm - kPeakNm));
    return kSharpness / ((shape_cdf(kLambdaMaxNm) - shape_cdf(kLambdaMinNm)) * c * c);
}

DispersionSplit::DispersionSplit(int count, double offset) {
    for (int k = 0; k < count; ++k) {
        const double nm = visible_wavelength((k + offset) / count);
        m_wavelengths.push_back(
            {nm, cie_xyz_bar(nm) * (1.0 / (count * visible_wavelength_pdf(nm)))});
    }
    // The set integrates D65 exactly: white light, and the RGB colours made from D65
    // (reflectance_from_rgb, the photon estimates), keep their colour whatever the offset.
    static const Vec3 exact = spectrum_xyz(*d65_spectrum());
    const SpectrumPtr d65 = d65_spectrum();
    Vec3 estimate;
    for (const SplitWavelength& s : m_wavelengths) estimate += s.xyz_weight * d65->eval(s.nm);
    for (SplitWavelength& s : m_wavelengths) {
        for (int c = 0; c < 3; ++c) {
            if (estimate[c] > 0) s.xyz_weight[c] *= exact[c] / estimate[c];
        }
    }
}

std::vector<DispersionSplit> dispersion_splits(int count, int spp, uint64_t seed) {
    std::vector<DispersionSplit> out;
    if (count <= 1) return out;
    // The rotation's own stream: no pixel's stream (x + y * width) reaches this far.
    Rng rng(seed, ~uint64_t{0});
    const double rotation = rng.uniform();
    const int distinct = std::min(spp, kDistinctSplits);
    out.reserve(static_cast<size_t>(distinct));
    for (int s = 0; s < distinct; ++s) {
        const double u = radical_inverse_base2(static_cast<uint32_t>(s)) + rotation;
        out.emplace_back(count, u >= 1.0 ? u - 1.0 : u);
    }
    return out;
}

int dispersion_samples(const Scene& scene) {
    if (scene.render.dispersion_samples > 0) return scene.render.dispersion_samples;
    for (const Material& m : scene.materials) {
        if (m.transparency > 0 && m.index && m.index->dispersive()) return 7;
    }
    return 1;
}

}  // namespace lenslab
