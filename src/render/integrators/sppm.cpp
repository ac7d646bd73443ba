#include "render/integrators/sppm.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "accel/hash_grid.h"
#include "accel/photon.h"
#include "cluster/dealt_parts.h"
#include "cluster/rank_order_sum.h"
#include "math/constants.h"
#include "math/rng.h"
#include "optics/glass.h"
#include "render/camera.h"
#include "render/direct_light.h"
#include "render/memory_budget.h"
#include "render/photon_emission.h"
#include "render/photon_tracer.h"
#include "render/sppm_photons.h"
#include "scene/interaction.h"

namespace lenslab {

namespace {

// The pass wavelengths' rotation uses the stream just below this one, apart from the camera
// paths' (pixel index) and the photons' (2^62 + photon index). (Streams from here up once
// rotated the visible points' wavelengths, before their colour became exact.)
constexpr uint64_t kSppmRotationStream = uint64_t{1} << 61;
// Automatic initial radius: this many pixel footprints, at most this share of the scene's
// diagonal (the photon_map integrator's default radius).
constexpr double kFootprints = 2.0;
constexpr double kSceneShare = 0.005;
// A photon counts at a visible point only if their surfaces face the same way: the photon
// arrived on the side the camera sees (no light through thin objects) and on a surface
// turned less than 60 degrees from the point's (not the wall round a corner).
constexpr double kSameSurfaceCos = 0.5;

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

struct SppmIntegrator::Pixel {
    double radius = 0;  // 0 until the pixel's first visible point
    double n = 0;       // photons kept so far (N)
    Rgb tau;            // their flux times the reflectance, scaled as the radius shrank
    Rgb direct;         // radiance found by tracing, summed over passes
};

struct SppmIntegrator::VisiblePoint {
    Vec3 p, n;        // n: the normal on the side the camera sees
    double beta = 0;  // path throughput to the point
    const Spectrum* albedo = nullptr;
    BandWeights albedo_bands{};  // the same albedo, per band
    double path_length = 0;      // camera to point, through mirrors and glass
    bool valid = false;          // the path reached a diffuse surface
    bool dispersed = false;      // it went through dispersive glass: pass wavelength only
    Rgb direct;
};

struct SppmIntegrator::PassState {
    int index = 0;
    uint64_t seed = 0;
    double lambda_nm = 550, lambda_pdf = 1;
    Camera camera;
};

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

void SppmIntegrator::trace_camera_path(int x, int y, const PassState& pass,
                                       VisiblePoint& vp) const {
    const Scene& scene = m_scene;
    const uint64_t pixel = uint64_t(y) * uint64_t(m_width) + uint64_t(x);
    Rng rng(pass.seed, pixel);
    vp = VisiblePoint{};
    const double jx = rng.uniform(), jy = rng.uniform();
    Ray ray = pass.camera.generate_ray(x + jx, y + jy);

    double beta = 1.0;
    // Until a dispersive refraction the path carries the whole spectrum and its colour is
    // exact (render/path_colour.h); after one, the pass wavelength alone.
    Rgb found;
    double found_pass = 0;  // at the pass wavelength
    auto add = [&](const Spectrum& s) {
        if (vp.dispersed) {
            found_pass += beta * s.eval(pass.lambda_nm);
        } else {
            found += s.band_colour().total() * beta;
        }
    };
    for (int depth = 0; depth <= scene.render.max_depth; ++depth) {
        Interaction it;
        if (!next_interaction(scene, ray, vp.dispersed ? pass.lambda_nm : kLineD, it)) {
            if (m_background) add(*m_background);
            break;
        }
        // Beer-Lambert inside absorbing glass depends on wavelength, like a dispersive
        // refraction: either leaves the pass wavelength alone on the path.
        const bool absorbed_on_the_way = absorption_before(it, ray.direction) != nullptr;
        if (!vp.dispersed && (it.scattering.dispersive || absorbed_on_the_way)) {
            vp.dispersed = true;
            it.scattering = scatter_at(it, it.direction, pass.lambda_nm);
        }
        if (absorbed_on_the_way) beta *= segment_transmittance(it, ray.direction, pass.lambda_nm);
        vp.path_length += it.hit.surface.t;
        const Material& m = *it.material;
        const Vec3& p = it.point();
        const bool front_side = dot(ray.direction, it.normal()) < 0.0;
        const Vec3 facing = front_side ? it.normal() : -it.normal();
        if (front_side && m.is_emitter()) add(*m.emission);

        // One event, chosen with the material's weights (absorption excluded, so the path
        // carries their sum).
        const Scattering& s = it.scattering;
        const double diffuse = s.diffuse > 0.0 && !m.color.is_black() ? s.diffuse : 0.0;
        double total = diffuse;
        for (int i = 0; i < s.count; ++i) total += s.branches[i].weight;
        if (!(total > 0.0)) break;
        const EventPick event = pick_event(s, diffuse, rng.uniform() * total);
        beta *= total;
        if (event.diffuse) {
            vp.valid = true;
            vp.p = p;
            vp.n = facing;
            vp.beta = beta;
            vp.albedo = m.albedo.get();
            vp.albedo_bands = m.albedo_bands;
            const int samples = scene.render.light_samples;
            if (vp.dispersed) {
                const SampledWavelengths at_pass = SampledWavelengths::single(pass.lambda_nm);
                double e = direct_irradiance(scene, p, facing, samples, at_pass, rng).v[0];
                if (m_ambient) e += kPi * m_ambient->eval(pass.lambda_nm);
                found_pass += beta * m.albedo->eval(pass.lambda_nm) / kPi * e;
            } else {
                for_each_direct_light(
                    scene, p, facing, samples, rng, [&](const Spectrum& light, double f) {
                        found += light.band_colour().through(m.albedo_bands) * (f * beta / kPi);
                    });
                if (m_ambient) found += m_ambient->band_colour().through(m.albedo_bands) * beta;
            }
            break;
        }
        // Rounding can leave the pick just past the last branch: that one is meant.
        ray = {p, (event.branch ? event.branch : &s.branches[s.count - 1])->direction};
    }
    vp.direct = found;
    if (found_pass != 0.0) vp.direct += sample_to_rgb(found_pass, pass.lambda_nm, pass.lambda_pdf);
}

bool SppmIntegrator::add_pass(RenderControl& control) {
    const Scene& scene = m_scene;
    const RenderSettings& r = scene.render;
    PhotonPassSettings photon_settings;
    photon_settings.photons_per_light = pass_photons();
    photon_settings.max_depth = r.max_depth;
    // Auto: a quarter of the pass's photons aimed. They serve the caustics only, where the
    // light's own photons rarely go; the rest of the image needs the emitted ones.
    photon_settings.caustic_photons_per_light =
        r.caustic_photons > 0 ? r.caustic_photons : std::max<int64_t>(1, pass_photons() / 4);
    photon_settings.aim = r.aim_photons;
    photon_settings.wavelengths = &m_pass_wavelength;
    if (m_stats.passes == 0) {
        const uint64_t need = photon_pass_bytes(scene, photon_settings);
        check_memory_budget(
            need,
            "pass_photons: " + std::to_string(pass_photons()) + " photons per light need up to",
            " per pass", "use fewer");
    }
    PassState pass{m_stats.passes,
                   splitmix64(r.seed ^ splitmix64(static_cast<uint64_t>(m_stats.passes))), 550, 1,
                   Camera(scene.camera, m_width, m_height)};
    pass.lambda_nm = m_pass_wavelength.sample(
        pass.index, Rng(r.seed, kSppmRotationStream - 1).uniform(), pass.lambda_pdf);

    // In a job of several ranks each traces the camera paths and gathers the photons of the
    // image rows dealt to it, and traces the photon chunks dealt to it (docs/cluster.md).
    Communicator& comm = control.cluster();
    m_cluster = &comm;

    // 1. Camera paths to this pass's visible points.
    auto t0 = std::chrono::steady_clock::now();
    std::vector<VisiblePoint>& points = m_points;
    points.resize(m_pixels.size());
    tbb::parallel_for(tbb::blocked_range<int>(0, m_height, 1),
                      [&](const tbb::blocked_range<int>& rows) {
                          for (int y = rows.begin(); y != rows.end(); ++y) {
                              if (!dealt_to(y, comm)) continue;
                              if (control.cancelled()) return;
                              for (int x = 0; x < m_width; ++x)
                                  trace_camera_path(x, y, pass, points[size_t(y) * m_width + x]);
                          }
                      });
    if (control.cancelled()) return false;
    // A pixel's radius starts at its first visible point.
    for (size_t i = 0; i < points.size(); ++i) {
        if (!points[i].valid || m_pixels[i].radius != 0.0) continue;
        if (!dealt_to(static_cast<int64_t>(i) / m_width, comm)) continue;
        m_pixels[i].radius =
            r.initial_radius > 0 ? r.initial_radius : auto_radius(points[i].path_length);
    }
    share_visible_points(comm);
    const double camera_seconds = seconds_since(t0);

    // 2. Photons. Dispersed photons take the pass wavelength in proportion to the camera
    // paths that went through dispersive glass (at least 10%, at most half, none if none).
    size_t dispersed_points = 0, valid_points = 0;
    for (const VisiblePoint& vp : points) {
        valid_points += vp.valid;
        dispersed_points += vp.valid && vp.dispersed;
    }
    const double pass_share =
        dispersed_points == 0
            ? 0.0
            : std::clamp(double(dispersed_points) / double(valid_points), 0.1, 0.5);
    t0 = std::chrono::steady_clock::now();
    photon_settings.seed = pass.seed;
    photon_settings.lambda_nm = pass.lambda_nm;
    photon_settings.lambda_pdf = pass.lambda_pdf;
    photon_settings.pass_share = pass_share;
    const PhotonPass photons = trace_photon_pass(scene, photon_settings, control);
    if (control.cancelled()) return false;
    const double photon_seconds = seconds_since(t0);

    // 3. Gather and update; not cancelled part-way, so the statistics stay whole.
    t0 = std::chrono::steady_clock::now();
    std::vector<double> radii;
    radii.reserve(points.size());
    for (size_t i = 0; i < points.size(); ++i)
        if (points[i].valid) radii.push_back(m_pixels[i].radius);
    double cell = m_radius_cap;
    if (!radii.empty()) {
        // Cells twice the median radius: most queries look at 8 cells or fewer. At least an
        // eighth of the largest radius, so that no query looks at more than 17^3 cells (a
        // camera close to one surface and far from another gives radii far apart).
        auto mid = radii.begin() + static_cast<ptrdiff_t>(radii.size() / 2);
        std::nth_element(radii.begin(), mid, radii.end());
        cell = std::max(2.0 * *mid, *std::max_element(mid, radii.end()) / 8.0);
    }
    const HashGrid grid(
        photons.hits.size(), [&](size_t i) { return photons.hits[i].pos(); }, cell);
    const std::vector<PhotonHit> hits = grid.reorder(photons.hits);
    const int lights = photon_light_count(scene);
    std::vector<double> light_at_pass(lights), albedo_at_pass(scene.materials.size());
    std::vector<BandColour> light_bands(lights);
    for (int l = 0; l < lights; ++l) {
        light_at_pass[l] = emitted_spectrum(scene, l).eval(pass.lambda_nm);
        light_bands[l] = emitted_spectrum(scene, l).band_colour();
    }
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        albedo_at_pass[m] =
            scene.materials[m].albedo ? scene.materials[m].albedo->eval(pass.lambda_nm) : 0.0;
    }
    const double alpha = r.alpha;
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, m_pixels.size(), 256),
        [&](const tbb::blocked_range<size_t>& range) {
            for (size_t i = range.begin(); i != range.end(); ++i) {
                if (!dealt_to(static_cast<int64_t>(i) / m_width, comm)) continue;
                const VisiblePoint& vp = points[i];
                Pixel& px = m_pixels[i];
                px.direct += vp.direct;
                if (!vp.valid) continue;
                const double radius2 = px.radius * px.radius;
                Rgb flux;                // photons not dispersed, reflected: exact colour
                double flux_pass = 0.0;  // at the pass wavelength
                Rgb dispersed;           // photons at wavelengths of their own
                int64_t found = 0;
                grid.for_each_near(vp.p, px.radius, [&](size_t h) {
                    const PhotonHit& ph = hits[h];
                    if (length_squared(ph.pos() - vp.p) > radius2) return;
                    if (dot(decode_octahedral(ph.normal), vp.n) < kSameSurfaceCos) return;
                    ++found;
                    if (ph.wavelength == PhotonWavelength::Pass) {
                        // Dispersed photons at the pass wavelength light only camera paths
                        // dispersed at it; the others only the rest (sppm_photons.h).
                        if (vp.dispersed) flux_pass += ph.power * pass.lambda_pdf;
                    } else if (ph.wavelength == PhotonWavelength::Own) {
                        if (!vp.dispersed) {
                            const double nm = ph.lambda_nm;
                            dispersed += sample_to_rgb(
                                vp.beta * vp.albedo->eval(nm) / kPi * ph.power, nm, 1.0);
                        }
                    } else if (vp.dispersed) {
                        double f = ph.power * light_at_pass[ph.light];
                        for (uint32_t k = 0; k < ph.chain_length; ++k)
                            f *= albedo_at_pass[photons.chains[ph.chain + k]];
                        flux_pass += f;
                    } else {
                        // power x the albedos it met (band-constant) x its light's spectrum,
                        // reflected by the visible point's albedo: exact per band.
                        BandWeights f = vp.albedo_bands;
                        for (double& b : f) b *= ph.power;
                        for (uint32_t k = 0; k < ph.chain_length; ++k) {
                            const BandWeights& a =
                                scene.materials[photons.chains[ph.chain + k]].albedo_bands;
                            for (int b = 0; b < 3; ++b) f[b] *= a[b];
                        }
                        flux += light_bands[ph.light].through(f);
                    }
                });
                if (found == 0) continue;
                Rgb phi = dispersed;
                if (!vp.dispersed) phi += flux * (vp.beta / kPi);
                if (flux_pass != 0.0) {
                    const double weight_pass = vp.beta * vp.albedo->eval(pass.lambda_nm) / kPi;
                    phi += sample_to_rgb(weight_pass * flux_pass, pass.lambda_nm, pass.lambda_pdf);
                }
                // Hachisuka & Jensen 2009, eqs. 6 and 7 (and tau scaled with the disc's area).
                const double n_new = px.n + alpha * static_cast<double>(found);
                const double ratio = n_new / (px.n + static_cast<double>(found));
                px.tau = (px.tau + phi) * ratio;
                px.radius *= std::sqrt(ratio);
                px.n = n_new;
            }
        });

    ++m_stats.passes;
    m_stats.photons_emitted += photons.emitted;
    m_stats.photons_aimed += photons.aimed;
    m_stats.photon_hits = hits.size();
    m_stats.camera_seconds += camera_seconds;
    m_stats.photon_seconds += photon_seconds;
    m_stats.gather_seconds += seconds_since(t0);
    double sum[2] = {0, 0};  // of the radii, and their count
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        if (m_pixels[i].radius > 0 && dealt_to(static_cast<int64_t>(i) / m_width, comm)) {
            sum[0] += m_pixels[i].radius;
            sum[1] += 1;
        }
    }
    sum_in_rank_order(comm, sum);
    m_stats.mean_radius = sum[1] > 0 ? sum[0] / sum[1] : 0.0;
    return true;
}

void SppmIntegrator::share_visible_points(Communicator& comm) {
    if (comm.alone()) return;
    // Per row: each pixel's radius, and whether its visible point is valid (1) and dispersed
    // (2). Every rank then picks the same grid cell and the same share of dispersed photons.
    const size_t rows = static_cast<size_t>(m_height), width = static_cast<size_t>(m_width);
    std::vector<std::vector<double>> radius(rows);
    std::vector<std::vector<uint8_t>> flags(rows);
    for (size_t y = static_cast<size_t>(comm.rank()); y < rows; y += size_t(comm.size())) {
        for (size_t i = y * width; i < (y + 1) * width; ++i) {
            radius[y].push_back(m_pixels[i].radius);
            flags[y].push_back(uint8_t(m_points[i].valid) | uint8_t(m_points[i].dispersed << 1));
        }
    }
    share_dealt_parts(comm, radius);
    share_dealt_parts(comm, flags);
    for (size_t y = 0; y < rows; ++y) {
        if (dealt_to(static_cast<int64_t>(y), comm)) continue;
        for (size_t x = 0; x < width; ++x) {
            m_pixels[y * width + x].radius = radius[y][x];
            m_points[y * width + x].valid = flags[y][x] & 1;
            m_points[y * width + x].dispersed = flags[y][x] & 2;
        }
    }
}

void SppmIntegrator::develop(Film& film) const {
    if (m_stats.passes == 0) return;
    // In a job of several ranks, rank 0 receives the statistics of the rows it did not
    // gather (collective: every rank calls develop).
    Communicator& comm = *m_cluster;
    std::vector<std::vector<Pixel>> rows(static_cast<size_t>(m_height));
    if (!comm.alone()) {
        for (int y = comm.rank(); y < m_height; y += comm.size()) {
            const auto row = m_pixels.begin() + static_cast<ptrdiff_t>(y) * m_width;
            rows[static_cast<size_t>(y)].assign(row, row + m_width);
        }
        gather_dealt_parts_to_root(comm, rows);
    }
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

}  // namespace lenslab

namespace lenslab {

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
                  {"mean_radius", p.mean_radius}};
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
