#include "scene/material.h"

#include "optics/smooth_spectrum.h"

namespace lenslab {

namespace {

class ScaledSpectrum final : public Spectrum {
public:
    ScaledSpectrum(SpectrumPtr s, double scale) : m_s(std::move(s)), m_scale(scale) {}
    double eval(double nm) const override { return m_s->eval(nm) * m_scale; }

private:
    SpectrumPtr m_s;
    double m_scale;
};

}  // namespace

void Material::finish() {
    albedo = reflectance_from_rgb(color);
    albedo_bands = reflectance_bands(color);
    const SpectrumPtr shape =
        emission_spectrum ? emission_spectrum : smooth_illuminant_from_rgb(emission_color);
    emission = emission_intensity > 0.0
                   ? std::make_shared<ScaledSpectrum>(shape, emission_intensity)
                   : nullptr;
}

SpectrumPtr scaled_spectrum(SpectrumPtr s, double scale) {
    return std::make_shared<ScaledSpectrum>(std::move(s), scale);
}

}  // namespace lenslab
