#pragma once
// The spectral accumulator of the sppm gathers (sppm.h): what the photons near a receiver
// bring to it, summed in the photons' own forms and turned into a colour once. Private to the
// integrator; inline, as it runs once per photon found.

#include <vector>

#include "optics/spectrum.h"
#include "render/integrators/sppm_state.h"
#include "render/photon_emission.h"
#include "render/sppm_photons.h"
#include "scene/scene.h"

namespace lenslab {

// What the photons found near a receiver bring to it: a visible point (its surface reflects
// with its albedo) or a camera segment through a medium (albedo 1: its phase function and
// transmittance weigh each photon). Sums stay in the photons' forms (sppm_photons.h) until
// colour(): exact band colours for photons that never dispersed, the pass wavelength's
// density for those at it, and their own wavelength for the others.
class SppmIntegrator::PhotonColours {
public:
    struct Receiver {
        bool dispersed;          // the camera path follows the pass wavelength
        double scale;            // its throughput and factor (a surface's 1/pi)
        const Spectrum* albedo;  // nullptr: 1
        BandWeights albedo_bands;
    };
    struct Sum {
        Rgb flux;         // not dispersed: exact colour, the receiver's albedo in
        double pass = 0;  // at the pass wavelength, over its density's share
        Rgb own;          // at wavelengths of their own, scaled already
    };

    PhotonColours(const Scene& scene, const PhotonPass& photons, const PassState& pass)
        : m_scene(scene), m_photons(photons), m_pass(pass) {
        const int lights = photon_light_count(scene);
        m_light_at_pass.resize(size_t(lights));
        m_light_bands.resize(size_t(lights));
        for (int l = 0; l < lights; ++l) {
            m_light_at_pass[size_t(l)] = emitted_spectrum(scene, l).eval(pass.lambda_nm);
            m_light_bands[size_t(l)] = emitted_spectrum(scene, l).band_colour();
        }
        for (const Material& m : scene.materials)
            m_albedo_at_pass.push_back(m.albedo ? m.albedo->eval(pass.lambda_nm) : 0.0);
    }

    // Photon `ph` with the share `weight` of its power.
    void add(Sum& sum, const PhotonHit& ph, const Receiver& to, double weight) const {
        const double power = ph.power * weight;
        if (ph.wavelength == PhotonWavelength::Pass) {
            // Dispersed photons at the pass wavelength light only camera paths dispersed at
            // it; the others only the rest (sppm_photons.h).
            if (to.dispersed) sum.pass += power * m_pass.lambda_pdf;
        } else if (ph.wavelength == PhotonWavelength::Own) {
            if (!to.dispersed) {
                const double nm = ph.lambda_nm;
                const double albedo = to.albedo ? to.albedo->eval(nm) : 1.0;
                sum.own += sample_to_rgb(to.scale * albedo * power, nm, 1.0);
            }
        } else if (to.dispersed) {
            double f = power * m_light_at_pass[ph.light];
            for (uint32_t k = 0; k < ph.chain_length; ++k)
                f *= m_albedo_at_pass[m_photons.chains[ph.chain + k]];
            sum.pass += f;
        } else {
            // power x the albedos it met (band-constant) x its light's spectrum, reflected by
            // the receiver's albedo: exact per band.
            BandWeights f = to.albedo_bands;
            for (double& b : f) b *= power;
            for (uint32_t k = 0; k < ph.chain_length; ++k) {
                const BandWeights& a =
                    m_scene.materials[m_photons.chains[ph.chain + k]].albedo_bands;
                for (int b = 0; b < 3; ++b) f[b] *= a[b];
            }
            sum.flux += m_light_bands[ph.light].through(f);
        }
    }

    Rgb colour(const Sum& sum, const Receiver& to) const {
        Rgb phi = sum.own;
        if (!to.dispersed) phi += sum.flux * to.scale;
        if (sum.pass != 0.0) {
            const double albedo = to.albedo ? to.albedo->eval(m_pass.lambda_nm) : 1.0;
            phi += sample_to_rgb(to.scale * albedo * sum.pass, m_pass.lambda_nm, m_pass.lambda_pdf);
        }
        return phi;
    }

private:
    const Scene& m_scene;
    const PhotonPass& m_photons;
    const PassState& m_pass;
    std::vector<double> m_light_at_pass, m_albedo_at_pass;
    std::vector<BandColour> m_light_bands;
};

}  // namespace lenslab
