#include "render/pass_wavelength.h"

#include <cmath>

#include "render/photon_emission.h"

namespace lenslab {

namespace {

// Share of the draw spread uniformly over the visible range.
constexpr double kUniformShare = 0.2;

// Sum of the lights' spectra, each divided by its power, plus the uniform share: a density
// up to a constant, which Spectrum::sample_wavelength normalises.
class LightMixture final : public Spectrum {
public:
    explicit LightMixture(const Scene& scene) {
        const int lights = photon_light_count(scene);
        for (int l = 0; l < lights; ++l) {
            const Spectrum& s = emitted_spectrum(scene, l);
            double power = 0.0;
            for (double nm = kLambdaMinNm + 0.125; nm < kLambdaMaxNm; nm += 0.25)
                power += s.eval(nm) * 0.25;
            if (power > 0.0) m_parts.push_back({&s, 1.0 / power});
        }
        const double range = kLambdaMaxNm - kLambdaMinNm;
        m_uniform = m_parts.empty() ? 1.0 / range : kUniformShare / range;
        for (Part& p : m_parts)
            p.scale *= (1.0 - kUniformShare) / static_cast<double>(m_parts.size());
    }
    double eval(double nm) const override {
        if (nm < kLambdaMinNm || nm > kLambdaMaxNm) return 0.0;
        double v = m_uniform;
        for (const Part& p : m_parts) v += p.spectrum->eval(nm) * p.scale;
        return v;
    }

private:
    struct Part {
        const Spectrum* spectrum;  // owned by the scene, which outlives the integrator
        double scale;
    };
    std::vector<Part> m_parts;
    double m_uniform = 0;
};

}  // namespace

double radical_inverse_base2(uint32_t i) {
    i = (i << 16) | (i >> 16);
    i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
    i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
    i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
    i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
    return static_cast<double>(i) * 0x1p-32;
}

PassWavelength::PassWavelength(const Scene& scene)
    : m_mixture(std::make_shared<LightMixture>(scene)) {}

double PassWavelength::sample(int pass, double rotation, double& pdf) const {
    double u = radical_inverse_base2(static_cast<uint32_t>(pass)) + rotation;
    if (u >= 1.0) u -= 1.0;
    return draw(u, pdf);
}

double PassWavelength::draw(double u, double& pdf) const {
    double nm;
    pdf = m_mixture->sample_wavelength(u, nm);
    return nm;
}

}  // namespace lenslab
