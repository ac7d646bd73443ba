#pragma once
// Photon tracing (Jensen 2001, chapter 5): photons leave every light, bounce off mirrors and
// through glass, and are stored where they meet a diffuse surface. Two streams
// (render/photon_emission.h): emitted photons, sent as the lights emit, choose one event per
// surface by Russian roulette on the material's weights; aimed photons, sent only towards
// the glass and mirrors, split at each surface into its reflected and refracted branches
// (weighted; Russian roulette only below kSplitFloor of a photon's power), so a caustic
// photon rarely carries more than its share and the faint reflected caustics come at low
// noise. A photon's power is its light's divided by the photons that light sends in its
// stream, so the estimate does not change with the counts. The walk itself is the shared
// photon tracer's (render/photon_walk.h); this file is its photon-map deposit policy.

#include <cstdint>
#include <functional>

#include "render/memory_budget.h"
#include "render/photon_emission.h"
#include "render/photon_map.h"
#include "render/render_control.h"
#include "scene/interaction.h"
#include "scene/scene.h"
#include "util/error.h"

namespace lenslab {

struct PhotonTracingSettings {
    int64_t photons_per_light = 200000;  // emitted stream, per light on average
    int max_depth = 8;                   // specular bounces followed before a photon is dropped
    uint64_t seed = 1;
    int64_t caustic_photons_per_light = 0;  // aimed stream, per light on average (0: none)
    bool aim = true;                        // false: no aimed stream, whatever its count
};

struct PhotonTracingStats {
    int64_t emitted = 0;  // both streams
    int64_t aimed = 0;    // of which aimed at the photon targets
    size_t direct = 0, caustic = 0;
    double trace_seconds = 0, build_seconds = 0;
    size_t memory_bytes = 0;
};

// Bytes of photon storage the settings are expected to need.
uint64_t photon_storage_bytes(const Scene& scene, const PhotonTracingSettings& settings);

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
    bool aimed;                      // from the aimed stream
    int depth;                       // surfaces met before this one
    // What it carries (an aimed photon's branch: its share of the photon): `scale` times its
    // light's spectral power `*spectrum` at every
    // wavelength while `lambda_nm` is 0; once a dispersive refraction picked one wavelength,
    // `lambda_nm` > 0 and the photon carries the same radiant power, `scale` times that of
    // `*spectrum`, all at that wavelength (a photon never gains power when it disperses).
    const Spectrum* spectrum;
    double scale;
    double lambda_nm;
};
using PhotonArrivalFn = std::function<void(const PhotonArrival&)>;

// Follows photon `index` of `plan` (0 <= index < plan.total()) along the path trace_photons
// gives it (the same random stream and choices) and calls `on_arrival` at every surface it
// (or, aimed, each of its branches) reaches, where it counts; stores nothing.
// Deterministic per (seed, index).
void trace_photon_path(const Scene& scene, const PhotonTracingSettings& settings,
                       const PhotonPlan& plan, int64_t index, const PhotonArrivalFn& on_arrival);

// The photons `settings` ask for, in the streams photon_emission.h describes.
PhotonPlan photon_plan(const Scene& scene, const PhotonTracingSettings& settings);

}  // namespace lenslab
