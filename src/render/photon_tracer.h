#pragma once
// Photon tracing (Jensen 2001, chapter 5): photons leave every light, bounce off mirrors and
// through glass chosen by Russian roulette on the Fresnel weights, and are stored where they
// meet a diffuse surface. Each light emits the same number of photons; a photon carries the
// light's power divided by that number, so the estimate does not change with the count.

#include <cstdint>
#include <functional>
#include <stdexcept>

#include "render/photon_emission.h"
#include "render/photon_map.h"
#include "render/render_control.h"
#include "scene/interaction.h"
#include "scene/scene.h"

namespace lenslab {

struct PhotonTracingSettings {
    int64_t photons_per_light = 200000;
    int max_depth = 8;   // specular bounces followed before a photon is dropped
    uint64_t seed = 1;
};

struct PhotonTracingStats {
    int64_t emitted = 0;
    size_t direct = 0, caustic = 0;
    double trace_seconds = 0, build_seconds = 0;
    size_t memory_bytes = 0;
};

// Thrown before any work when the photons asked for cannot fit in memory.
class ResourceError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Bytes of photon storage the settings need at most, and the memory available for it.
uint64_t photon_storage_bytes(const Scene& scene, int64_t photons_per_light);
uint64_t available_memory_bytes();

// Traces the photons and builds the maps. Deterministic for a given seed at any thread
// count (one random stream per photon). Throws ResourceError if storage would not fit.
PhotonMap trace_photons(const Scene& scene, const PhotonTracingSettings& settings,
                        RenderControl& control, PhotonTracingStats* stats = nullptr);

// A photon reaching a surface, as a measurement (a detector) sees it: before the surface's
// material decides what happens to it.
struct PhotonArrival {
    const Interaction* interaction;  // the surface, the point, its outward normal
    Vec3 direction;                  // of travel, unit
    int light;                       // which light sent it (in photon_light_count's order)
    int depth;                       // surfaces met before this one
    // What it carries: `scale` times its light's spectral power `*spectrum` at every
    // wavelength while `lambda_nm` is 0; once a dispersive refraction picked one wavelength,
    // `lambda_nm` > 0 and the photon carries the same radiant power, `scale` times that of
    // `*spectrum`, all at that wavelength (a photon never gains power when it disperses).
    const Spectrum* spectrum;
    double scale;
    double lambda_nm;
};
using PhotonArrivalFn = std::function<void(const PhotonArrival&)>;

// Follows photon `index` (0 <= index < photons_per_light) of light `light` along the path
// trace_photons gives it (the same random stream and choices) and calls `on_arrival` at
// every surface it reaches; stores nothing. Deterministic per (seed, light, index).
void trace_photon_path(const Scene& scene, const PhotonTracingSettings& settings, int light, int64_t index,
                       const PhotonArrivalFn& on_arrival);

}  // namespace lenslab
