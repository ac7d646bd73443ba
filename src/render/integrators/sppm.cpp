#include "render/integrators/sppm.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cluster/dealt_parts.h"
#include "math/constants.h"
#include "math/rng.h"
#include "render/integrators/sppm_photon_colours.h"
#include "render/memory_budget.h"
#include "render/photon_emission.h"
#include "render/sppm_photons.h"

namespace lenslab {

namespace {

// Automatic initial radius: this many pixel footprints, at most this share of the scene's
// diagonal (the photon_map integrator's default radius).
constexpr double kFootprints = 2.0;
constexpr double kSceneShare = 0.005;

uint64_t splitmix64(uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

SppmIntegrator::SppmIntegrator(const Scene& scene)
    : m_scene(scene),
      m_width(scene.render.width),
      m_height(scene.render.height),
      m_pass_wavelength(scene),
      m_pixels(size_t(scene.render.width) * scene.render.height) {
    m_pixel_angle = 2.0 * std::tan(0.5 * scene.camera.fov_deg * kPi / 180.0) / m_height;
    const Aabb b = scene.bounds();
    m_radius_cap = b.empty() ? 0.05 : kSceneShare * length(b.extent());
    if (!scene.render.ambient.is_black()) m_ambient = illuminant_from_rgb(scene.render.ambient);
    if (!scene.render.background.is_black())
        m_background = illuminant_from_rgb(scene.render.background);
    if (scene.has_media()) {
        m_segments.resize(m_pixels.size() * sppm::kMaxSegments);
        // Where volume photons are kept: the objects, the camera and the lights, and a quarter
        // of their diagonal around them. Its size, not the objects' alone, sets the volume
        // radius: fog fills the space between the camera and a small lamp too.
        Aabb box = b;
        box.expand(scene.camera.position);
        for (const LightPtr& l : scene.lights()) box.expand(l->bounds());
        const double diagonal = length(box.extent());
        const double margin = 0.25 * diagonal;
        m_volume_box = {box.lo - Vec3{margin, margin, margin},
                        box.hi + Vec3{margin, margin, margin}};
        m_volume_radius =
            scene.render.initial_radius > 0 ? scene.render.initial_radius : kSceneShare * diagonal;
        m_volume_radius_start = m_volume_radius;
    }
}

SppmIntegrator::~SppmIntegrator() = default;

int64_t SppmIntegrator::pass_photons() const {
    if (m_scene.render.pass_photons > 0) return m_scene.render.pass_photons;
    // As many photons as pixels (pbrt-v4's default): a pass then spends about as long on
    // photons as on camera paths.
    const int lights = std::max(1, photon_light_count(m_scene));
    return std::max<int64_t>(1, int64_t(m_width) * m_height / lights);
}

double SppmIntegrator::auto_radius(double path_length) const {
    const double r = std::min(kFootprints * path_length * m_pixel_angle, m_radius_cap);
    return std::max(r, 1e-6 * m_radius_cap);
}

PhotonPassSettings SppmIntegrator::photon_pass_settings() const {
    const RenderSettings& r = m_scene.render;
    PhotonPassSettings s;
    s.photons_per_light = pass_photons();
    s.max_depth = r.max_depth;
    // Auto: a quarter of the pass's photons aimed. They serve the caustics only, where the
    // light's own photons rarely go; the rest of the image needs the emitted ones.
    s.caustic_photons_per_light =
        r.caustic_photons > 0 ? r.caustic_photons : std::max<int64_t>(1, pass_photons() / 4);
    s.aim = r.aim_photons;
    s.wavelengths = &m_pass_wavelength;
    s.volume_bounds = m_volume_box;  // empty (all kept) without media
    return s;
}

SppmIntegrator::PassState SppmIntegrator::next_pass() const {
    const RenderSettings& r = m_scene.render;
    PassState pass{m_stats.passes,
                   splitmix64(r.seed ^ splitmix64(static_cast<uint64_t>(m_stats.passes))), 550, 1,
                   Camera(m_scene.camera, m_width, m_height)};
    pass.lambda_nm = m_pass_wavelength.sample(
        pass.index, Rng(r.seed, sppm::kRotationStream - 1).uniform(), pass.lambda_pdf);
    return pass;
}

double SppmIntegrator::dispersed_photon_share() const {
    // In proportion to the camera paths that went through dispersive glass (at least 10%, at
    // most half, none if none).
    size_t dispersed_points = 0, valid_points = 0;
    for (const VisiblePoint& vp : m_points) {
        const bool gathers = vp.valid || vp.in_medium;
        valid_points += gathers;
        dispersed_points += gathers && vp.dispersed;
    }
    return dispersed_points == 0
               ? 0.0
               : std::clamp(double(dispersed_points) / double(valid_points), 0.1, 0.5);
}

bool SppmIntegrator::add_pass(RenderControl& control) {
    PhotonPassSettings photon_settings = photon_pass_settings();
    if (m_stats.passes == 0) {
        check_memory_budget(
            photon_pass_bytes(m_scene, photon_settings),
            "pass_photons: " + std::to_string(pass_photons()) + " photons per light need up to",
            " per pass", "use fewer");
    }
    const PassState pass = next_pass();
    // In a job of several ranks each traces the camera paths and gathers the photons of the
    // image rows dealt to it, and traces the photon chunks dealt to it (docs/cluster.md).
    m_cluster = &control.cluster();

    // 1. Camera paths to this pass's visible points (sppm_camera_paths.cpp).
    auto t0 = std::chrono::steady_clock::now();
    if (!trace_camera_paths(pass, control)) return false;
    share_visible_points(*m_cluster);
    const double camera_seconds = seconds_since(t0);

    // 2. Photons (sppm_photons.h). Dispersed ones take the pass wavelength.
    photon_settings.seed = pass.seed;
    photon_settings.lambda_nm = pass.lambda_nm;
    photon_settings.lambda_pdf = pass.lambda_pdf;
    photon_settings.pass_share = dispersed_photon_share();
    t0 = std::chrono::steady_clock::now();
    const PhotonPass photons = trace_photon_pass(m_scene, photon_settings, control);
    if (control.cancelled()) return false;
    const double photon_seconds = seconds_since(t0);

    // 3. Gather and update (sppm_surface_gather.cpp, sppm_volume_gather.cpp); not cancelled
    // part-way, so the statistics stay whole.
    t0 = std::chrono::steady_clock::now();
    const PhotonColours colours(m_scene, photons, pass);
    const size_t hits = gather_surface(photons, colours);
    gather_volume(pass, photons, colours);

    ++m_stats.passes;
    m_stats.volume_photons = photons.volume.size();
    m_stats.photons_emitted += photons.emitted;
    m_stats.photons_aimed += photons.aimed;
    m_stats.photon_hits = hits;
    m_stats.camera_seconds += camera_seconds;
    m_stats.photon_seconds += photon_seconds;
    m_stats.gather_seconds += seconds_since(t0);
    m_stats.mean_radius = mean_radius();
    return true;
}

void SppmIntegrator::develop(Film& film) const {
    if (m_stats.passes == 0) return;
    // In a job of several ranks, rank 0 receives the statistics of the rows it did not
    // gather (collective: every rank calls develop).
    const Communicator& comm = *m_cluster;
    const std::vector<std::vector<Pixel>> rows = pixel_rows_at_root();
    const double inv_passes = 1.0 / m_stats.passes;
    for (int y = 0; y < m_height; ++y) {
        const bool here = dealt_to(y, comm) || !comm.is_root();
        for (int x = 0; x < m_width; ++x) {
            const Pixel& px = here ? m_pixels[size_t(y) * m_width + x]
                                   : rows[static_cast<size_t>(y)][static_cast<size_t>(x)];
            Rgb l = px.direct * inv_passes;
            if (px.radius > 0) l += px.tau * (inv_passes / (kPi * px.radius * px.radius));
            film.set(x, y, l.is_finite() ? l : Rgb{});
        }
    }
}

RenderStats SppmIntegrator::stats(double seconds) const {
    const SppmStats& p = m_stats;
    RenderStats out;
    out.passes = p.passes;
    out.photons = p.photons_emitted;
    out.values = {{"passes", double(p.passes)},
                  {"photons_emitted", double(p.photons_emitted)},
                  {"photons_aimed", double(p.photons_aimed)},
                  {"photon_hits", double(p.photon_hits)},
                  {"camera_seconds", p.camera_seconds},
                  {"photon_seconds", p.photon_seconds},
                  {"gather_seconds", p.gather_seconds},
                  {"mean_radius", p.mean_radius},
                  {"volume_photons", double(p.volume_photons)},
                  {"volume_radius", p.volume_radius}};
    const auto rate = [seconds](auto n) { return seconds > 0 ? double(n) / seconds : 0.0; };
    // Tools parse this line: keep its wording.
    char line[512];
    std::snprintf(line, sizeof line,
                  "sppm: %d passes, %lld photons (%lld aimed; %.3g passes/s, %.3g photons/s); "
                  "camera %.2f s, photons %.2f s, gather %.2f s; mean radius %.4g",
                  p.passes, static_cast<long long>(p.photons_emitted),
                  static_cast<long long>(p.photons_aimed), rate(p.passes), rate(p.photons_emitted),
                  p.camera_seconds, p.photon_seconds, p.gather_seconds, p.mean_radius);
    out.summary = line;
    return out;
}

}  // namespace lenslab
