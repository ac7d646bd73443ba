#pragma once
// The report's global illumination: Whitted ray tracing for what the camera sees through
// mirrors and glass, plus photon maps for the light that reaches diffuse surfaces.
//   - direct light: shadow rays (default), or the direct photon map (render.direct =
//     "photon_map", as the report did);
//   - caustics (light -> mirror/glass -> diffuse): the caustic photon map, gathered within
//     render.radius with the cone filter (render.filter_k) and at most
//     render.max_photons_per_estimate photons per estimate.

#include <memory>
#include <string_view>

#include "render/integrators/whitted.h"
#include "render/photon_map.h"
#include "render/photon_tracer.h"

namespace lenslab {

class PhotonMapIntegrator final : public WhittedIntegrator {
public:
    explicit PhotonMapIntegrator(const Scene& scene);

    // Traces the photons, builds the maps, then renders the pixels.
    bool render(const Scene& scene, const Camera& camera, Film& film,
                RenderControl& control) override;

    // The photons traced (none yet: zeros); summary "photons: N emitted (...) ...".
    RenderStats stats(double seconds) const override;
    // Uses maps traced elsewhere (benchmarks reuse one map across several renders).
    void set_photon_map(std::shared_ptr<const PhotonMap> map) { m_map = std::move(map); }

protected:
    // The photon-map estimate gathers at most max_photons_per_estimate times `share` photons
    // (at least kFewestPhotonsPerEstimate): the wavelengths of a split, each a few, gather
    // about as many as one unsplit path, and a faint reflection's estimate costs little.
    void add_diffuse_irradiance(LightSum& e, const Vec3& p, const Vec3& n, double share,
                                Rng& rng) const override;

private:
    GatherSettings m_gather;
    std::shared_ptr<const PhotonMap> m_map;
    PhotonTracingStats m_stats;
};

// The fewest photons an estimate gathers, however small its share of a pixel (see
// PhotonMapIntegrator::add_diffuse_irradiance).
inline constexpr size_t kFewestPhotonsPerEstimate = 8;

// Gather radius when the scene gives none: 0.5% of the diagonal of the scene's bounds
// (0.046 for the default scene, inside the report's range 0.025 to 0.1).
double default_gather_radius(const Scene& scene);

// The gather settings a scene's render block asks for (auto radius resolved).
GatherSettings gather_settings(const Scene& scene);
// The photons a scene's render block asks for: `photons` emitted, `caustic_photons` aimed.
PhotonTracingSettings photon_tracing_settings(const Scene& scene);

}  // namespace lenslab
