#include "render/integrators/photon_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/direct_light.h"

namespace lenslab {

double default_gather_radius(const Scene& scene) {
    const Aabb b = scene.bounds();
    if (b.empty()) return 0.05;
    return 0.005 * length(b.extent());
}

GatherSettings gather_settings(const Scene& scene) {
    const RenderSettings& r = scene.render;
    GatherSettings g;
    g.radius = r.radius > 0 ? r.radius : default_gather_radius(scene);
    g.max_photons = static_cast<size_t>(r.max_photons_per_estimate);
    g.filter = r.filter;
    g.cone_k = r.filter_k;
    return g;
}

PhotonTracingSettings photon_tracing_settings(const Scene& scene) {
    const RenderSettings& r = scene.render;
    PhotonTracingSettings s{r.photons, r.max_depth, r.seed,
                            r.caustic_photons > 0 ? r.caustic_photons : r.photons, r.aim_photons};
    // With shadow rays for direct light, the emitted photons serve only the caustics of glass
    // and mirrors that are not aimed at: when every light aims at every such object they
    // would be traced for nothing.
    const auto aims = [&](const LightPtr& l) { return l->worth_aiming(scene.photon_targets()); };
    const bool all_aimed = s.aim && !scene.photon_targets().empty() &&
                           !scene.has_specular_non_target() &&
                           std::all_of(scene.lights().begin(), scene.lights().end(), aims);
    if (r.direct == DirectLight::ShadowRays && all_aimed) s.photons_per_light = 0;
    return s;
}

PhotonMapIntegrator::PhotonMapIntegrator(const Scene& scene)
    : WhittedIntegrator(scene), m_gather(gather_settings(scene)) {}

bool PhotonMapIntegrator::render(const Scene& scene, const Camera& camera, Film& film,
                                 RenderControl& control) {
    if (!m_map) {
        auto map = std::make_shared<const PhotonMap>(
            trace_photons(scene, photon_tracing_settings(scene), control, &m_stats));
        // A cancelled trace leaves a partial map: not kept for a later render to reuse.
        if (control.cancelled()) return false;
        m_map = std::move(map);
    }
    if (control.cancelled()) return false;
    return WhittedIntegrator::render(scene, camera, film, control);
}

RenderStats PhotonMapIntegrator::stats(double /*seconds*/) const {
    const PhotonTracingStats& p = m_stats;
    RenderStats out;
    out.photons = static_cast<int64_t>(p.direct + p.caustic);
    out.values = {{"photons_emitted", double(p.emitted)},  {"photons_aimed", double(p.aimed)},
                  {"direct_photons", double(p.direct)},    {"caustic_photons", double(p.caustic)},
                  {"trace_seconds", p.trace_seconds},      {"build_seconds", p.build_seconds},
                  {"memory_bytes", double(p.memory_bytes)}};
    // Tools parse this line (`lenslab bench povray`): keep its wording.
    char line[512];
    std::snprintf(line, sizeof line,
                  "photons: %lld emitted (%lld aimed at the glass and mirrors), %zu direct + %zu "
                  "caustic stored (%.1f MiB), traced in %.3f s, maps built in %.3f s",
                  static_cast<long long>(p.emitted), static_cast<long long>(p.aimed), p.direct,
                  p.caustic, p.memory_bytes / (1024.0 * 1024.0), p.trace_seconds, p.build_seconds);
    out.summary = line;
    return out;
}

void PhotonMapIntegrator::add_diffuse_irradiance(LightSum& e, const Vec3& p, const Vec3& n,
                                                 double share, Rng& rng) const {
    thread_local std::vector<PhotonNeighbour> scratch;
    GatherSettings g = m_gather;
    const double wanted = std::ceil(static_cast<double>(g.max_photons) * share);
    if (wanted < static_cast<double>(g.max_photons))
        g.max_photons = std::max(kFewestPhotonsPerEstimate, static_cast<size_t>(wanted));
    // Photons store colours; the estimate is lit as an RGB illuminant (D65 times bands), whose
    // band colours are exact.
    Rgb from_maps = PhotonMap::irradiance(m_map->caustic(), p, n, g, scratch);
    if (m_scene.render.direct == DirectLight::PhotonMap) {
        from_maps += PhotonMap::irradiance(m_map->direct(), p, n, g, scratch);
    } else {
        WhittedIntegrator::add_diffuse_irradiance(e, p, n, share, rng);
    }
    e.add_illuminant(from_maps);
}

}  // namespace lenslab
