#pragma once
// One photon pass of stochastic progressive photon mapping. Photons leave every light (as it
// emits, and aimed at the glass and mirrors: render/photon_emission.h), go
// through glass and off mirrors, bounce diffusely (Russian roulette on the albedo), and leave
// a hit at every diffuse surface they reach after at least one scattering event: the light
// that comes straight from a light source is found by shadow rays instead (sharp shadows at
// once), so only caustics and indirect light come from photons.
//
// Spectra: a photon's flux is its light's spectrum times the albedos of the diffuse
// surfaces it bounced off, times a number. Keeping that as a function of wavelength (the
// list of bounces is stored, not evaluated) lets each visible point evaluate it at its own
// four wavelengths, so colour is exact and has no noise from wavelength sampling. Only a
// dispersive refraction makes the path depend on wavelength: there the photon picks one
// wavelength and becomes a number at it. A share of the dispersed photons take the pass's
// wavelength (PassWavelength: the one a camera path through dispersive glass follows in
// this pass, so the two can meet) and light only such camera paths; the others draw their
// own from the same density and light the rest, so a spectrum seen directly is smooth after
// a few passes, not one band per pass. `power` is divided by the wavelength's density and by
// the probability of the photon's share.
//
// In a participating medium (fog, smoke) a photon leaves a volume photon where it scatters:
// the same record, its `normal` holding its direction of travel before scattering, its power
// what arrived there (absorption on the way taken off). Camera rays through the medium
// gather them with the beam radiance estimate (integrators/sppm.h). The first scattering of
// light coming straight from a point, spot or beam is left out: camera rays compute it
// exactly (render/medium_transport.h), as surfaces compute the direct light.

#include <cstdint>
#include <vector>

#include "math/aabb.h"
#include "render/render_control.h"
#include "scene/scene.h"

namespace lenslab {

enum class PhotonWavelength : uint8_t {
    All,   // not dispersed: a function of wavelength
    Own,   // dispersed, at a wavelength of its own
    Pass,  // dispersed, at the pass's wavelength
};

struct PhotonHit {
    float position[3];
    uint16_t normal[2];  // octahedral: the surface normal on the side the photon arrived on
    float power;         // flux factor; dispersed: flux at its wavelength / that one's density
    union {
        uint32_t chain;   // not dispersed: first of its diffuse bounces in PhotonPass::chains
        float lambda_nm;  // dispersed: its wavelength
    };
    uint16_t chain_length;  // 0 when dispersed (the bounces are folded into `power`)
    uint16_t light;         // index as in emitted_spectrum()
    PhotonWavelength wavelength;
    uint8_t unused[3];

    Vec3 pos() const { return {position[0], position[1], position[2]}; }
};

static_assert(sizeof(PhotonHit) == 32, "a photon hit takes 32 bytes");

struct PhotonPass {
    std::vector<PhotonHit> hits;
    std::vector<PhotonHit> volume;  // scattering events in media
    // Material indices of the diffuse surfaces each photon bounced off, in order: the flux
    // of a hit is power * spectrum_light(l) * prod albedo(chains[chain .. chain + length)).
    std::vector<uint32_t> chains;
    int64_t emitted = 0;  // both streams
    int64_t aimed = 0;
};

struct PhotonPassSettings {
    int64_t photons_per_light = 100000;  // emitted as the lights emit, per light on average
    int max_depth = 8;                   // surfaces a photon meets before it is dropped
    uint64_t seed = 1;                   // this pass's seed
    double lambda_nm = 550;              // the pass wavelength
    double lambda_pdf = 1;               // its density
    double pass_share = 0;  // probability that a dispersed photon takes the pass wavelength
    const class PassWavelength* wavelengths = nullptr;  // where dispersed photons draw their own
    int64_t caustic_photons_per_light = 0;              // aimed at the photon targets, per light
    bool aim = true;
    // Volume photons are kept inside this box only (the camera's view of the scene): in an
    // atmosphere without bounds photons scatter on far from everything (empty: everywhere).
    Aabb volume_bounds;
};

// Deterministic for a given seed at any thread count (one random stream per photon, hits
// gathered in photon order). Returns an empty pass when `control` was cancelled.
PhotonPass trace_photon_pass(const Scene& scene, const PhotonPassSettings& settings,
                             RenderControl& control);

// Bytes one pass may need at most for its hits, to refuse a count that cannot fit.
uint64_t photon_pass_bytes(const Scene& scene, const PhotonPassSettings& settings);

}  // namespace lenslab
