#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "optics/rgb.h"

namespace lenslab {

// Smallest `min_weight` accepted: the specular branches of one ray that each carry at least
// w number at most about 1/w, so this bounds the work per camera ray.
inline constexpr double kMinBranchWeight = 1e-6;

// The names the scene file and the command line accept, declared once for both. The
// integrators are a registry (render/integrator_registry.h), open to more; the other choices
// are closed, each an enum whose names are listed in its order.
inline const std::vector<std::string> kIntegratorNames{"whitted", "photon_map", "sppm", "path"};

// Weighting of the photons inside the gather disc (Jensen 2001, section 7.2.2).
enum class PhotonFilter { Cone, Gaussian, Box };
inline const std::vector<std::string> kPhotonFilterNames{"cone", "gaussian", "box"};
// Where photon_map's direct light comes from.
enum class DirectLight { ShadowRays, PhotonMap };
inline const std::vector<std::string> kDirectLightNames{"shadow_rays", "photon_map"};
// How light brighter than white is shown (image/tone_map.h).
enum class ToneMapCurve { Clip, Log };
inline const std::vector<std::string> kToneMapNames{"clip", "log"};

// The value `name` stands for in `names` (the enum's names in its order); throws
// std::invalid_argument for a name not there (the readers check names first).
template <class Choice>
Choice choice_named(const std::vector<std::string>& names, const std::string& name) {
    for (size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name) return static_cast<Choice>(i);
    }
    throw std::invalid_argument("unknown choice '" + name + "'");
}

template <class Choice>
const std::string& choice_name(const std::vector<std::string>& names, Choice value) {
    return names.at(static_cast<size_t>(value));
}

// The scene file's `render` block; the command line may override any of it.
struct RenderSettings {
    int width = 640;
    int height = 480;
    int spp = 4;        // camera samples per pixel
    int max_depth = 8;  // longest chain of specular bounces followed
    uint64_t seed = 1;
    Rgb ambient{0, 0, 0};      // ambient radiance Ia lighting every diffuse surface
    Rgb background{0, 0, 0};   // radiance of rays that leave the scene
    int light_samples = 1;     // shadow rays per area light per camera sample
    double min_weight = 1e-4;  // specular branches carrying less are not followed
    // The wavelengths of a split whose branch carries less than this share of the camera
    // sample follow one path together (whitted, photon_map; render/path_colour.h). About
    // 1/255: one 8-bit level of the pixel, where POV-Ray stops tracing rays (adc_bailout).
    double merge_weight = 0.004;
    // Local error of a step through a GRIN medium, relative to the solid's size: far below a
    // pixel (the bench traces at 1e-9, scene/grin_ray.h).
    double grin_tolerance = 1e-7;
    std::string integrator = "whitted";  // whitted | photon_map | sppm | path
    // Wavelengths a camera path splits into at dispersive glass (whitted, photon_map;
    // render/dispersion_split.h); 0 = auto: 7 when a material disperses.
    int dispersion_samples = 0;

    // Photon mapping (integrator photon_map).
    int64_t photons = 200000;  // photons emitted per light
    double radius = 0;         // gather radius; 0 = auto (0.5% of the scene's diagonal)
    PhotonFilter filter = PhotonFilter::Cone;
    double filter_k = 1.1;               // cone filter constant k >= 1
    int max_photons_per_estimate = 500;  // cap on the photons one estimate gathers
    DirectLight direct = DirectLight::ShadowRays;
    // Photons aimed at the photon targets (the glass and mirrors), per light: the caustic
    // budget, apart from `photons` (photon_map) or `pass_photons` (sppm, per pass);
    // 0 = auto, as many as those.
    int64_t caustic_photons = 0;
    bool aim_photons = true;  // false: every photon leaves as the light emits (uniformly)

    // Stochastic progressive photon mapping (integrator sppm). The render stops after
    // `passes` passes or `time` seconds, whichever comes first (0: no limit of that kind).
    int passes = 64;
    double time = 0;           // seconds
    int64_t pass_photons = 0;  // photons emitted per light in each pass; 0 = auto (pixels / lights)
    double initial_radius = 0;  // 0 = auto, from the pixel footprint and the scene's size
    double alpha = 2.0 / 3.0;   // share of each pass's photons kept as the radius shrinks
    // In fog: 0, every volume photon's disc a few pixel footprints (sharp, fastest); N, a
    // sparse photon's disc grows until about N neighbours share it (render/volume_photon_radii.h).
    int volume_neighbours = 0;

    ToneMapCurve tone_map = ToneMapCurve::Clip;
    double highlight_stops = 8;  // log: stops above the knee that reach white
};

}  // namespace lenslab
