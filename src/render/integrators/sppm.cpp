#include "render/integrators/sppm.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "accel/hash_grid.h"
#include "accel/photon.h"
#include "accel/point_bvh.h"
#include "cluster/dealt_parts.h"
#include "cluster/rank_order_sum.h"
#include "math/constants.h"
#include "math/rng.h"
#include "optics/glass.h"
#include "optics/phase_function.h"
#include "render/camera.h"
#include "render/density_tracking.h"
#include "render/direct_light.h"
#include "render/medium_transport.h"
#include "render/memory_budget.h"
#include "render/path_colour.h"
#include "render/photon_emission.h"
#include "render/photon_tracer.h"
#include "render/sppm_photons.h"
#include "render/volume_photon_radii.h"
#include "scene/interaction.h"
#include "scene/segment_medium.h"

namespace lenslab {

namespace {

// The pass wavelengths' rotation uses the stream just below this one, apart from the camera
// paths' (pixel index) and the photons' (2^62 + photon index). (Streams from here up once
// rotated the visible points' wavelengths, before their colour became exact.)
constexpr uint64_t kSppmRotationStream = uint64_t{1} << 61;
// The volume gather's transmittance walks through heterogeneous media: from here up, one
// stream per pixel segment, above the photons'.
constexpr uint64_t kGatherStreams = uint64_t{3} << 62;
// Automatic initial radius: this many pixel footprints, at most this share of the scene's
// diagonal (the photon_map integrator's default radius).
constexpr double kFootprints = 2.0;
constexpr double kSceneShare = 0.005;
// A photon counts at a visible point only if their surfaces face the same way: the photon
// arrived on the side the camera sees (no light through thin objects) and on a surface
// turned less than 60 degrees from the point's (not the wall round a corner).
constexpr double kSameSurfaceCos = 0.5;
// Segments through media a camera path keeps for the volume gather (a ray through a fog box,
// a lens in it, and out again is three).
constexpr int kMaxSegments = 4;
// A volume photon's radius: this many pixel footprints at its distance from the camera, at
// most the volume radius. A fixed radius in the scene would make a photon near the camera a
// disc across half the image.
constexpr double kVolumeFootprints = 3.0;

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
    bool in_medium = false;      // it crossed a medium (its segments gather volume photons)
    Rgb direct;
};

struct SppmIntegrator::MediumSegment {
    Ray ray;
    double t_max = 0;  // where it meets the next surface (INFINITY: none)
    double beta = 0;   // the camera path's throughput at the ray's origin; 0: no segment
    const Medium* medium = nullptr;
    bool dispersed = false;  // the path follows the pass wavelength alone
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
    if (scene.has_media()) {
        m_segments.resize(m_pixels.size() * kMaxSegments);
        // Where volume photons are kept: the objects, the camera and the lights, and a quarter
        // of their diagonal around them. Its size, not the objects' alone, sets the volume
        // radius: fog fills the space between the camera and a small lamp too.
        Aabb box = b;
        box.expand(scene.camera.position);
        for (const PointLight& l : scene.point_lights) box.expand(l.position);
        for (const BeamLight& l : scene.beams) box.expand(l.origin);
        for (const SpotLight& l : scene.spots) box.expand(l.position);
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

void SppmIntegrator::trace_camera_path(int x, int y, const PassState& pass, VisiblePoint& vp,
                                       MediumSegment* segments) const {
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
    int segment_count = 0;
    if (segments) std::fill(segments, segments + kMaxSegments, MediumSegment{});
    // The colour of light found along the path (medium_transport's sums) at beta = 1.
    auto path_colour = [&] {
        PathColour c(pass.lambda_nm, pass.lambda_pdf);
        if (vp.dispersed) c.disperse();
        return c;
    };
    for (int depth = 0; depth <= scene.render.max_depth; ++depth) {
        Interaction it;
        const bool hit = next_interaction(scene, ray, vp.dispersed ? pass.lambda_nm : kLineD, it);
        const Medium* medium = segments ? segment_medium(scene, ray, hit ? &it : nullptr) : nullptr;
        if (medium) {
            // A coloured medium, like absorbing glass, leaves the pass wavelength alone.
            if (!vp.dispersed && !medium->is_grey()) {
                vp.dispersed = true;
                if (hit) it.scattering = scatter_at(it, it.direction, pass.lambda_nm);
            }
            const double t_max = hit ? it.hit.surface.t : INFINITY;
            const PathColour colour = path_colour();
            LightSum e(colour);
            add_light_in_scattering(scene, *medium, ray, t_max, scene.render.light_samples, rng, e);
            found += colour.of(e) * beta;
            if (segment_count < kMaxSegments)
                segments[segment_count++] = {ray, t_max, beta, medium, vp.dispersed};
            vp.in_medium = true;
            const int band = vp.dispersed ? band_of(pass.lambda_nm) : 0;
            beta *= medium->is_heterogeneous()
                        ? ratio_track(*medium->density, medium->extinction()[size_t(band)], ray,
                                      t_max, rng)
                        : medium->transmittance(t_max)[band];
            if (!(beta > 0.0)) break;
        }
        if (!hit) {
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
        if (it.material->surfaceless) {  // a medium's edge: no event, no bounce
            ray = {it.point(), ray.direction};
            --depth;
            continue;
        }
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
            if (segments) {
                // Through media: the direct light dimmed on its way.
                PathColour colour = path_colour();
                LightSum e(colour);
                add_direct_light(
                    scene, p, samples, rng, [&](const Vec3& wi) { return dot(facing, wi); }, e);
                if (m_ambient) e.add(*m_ambient, kPi);
                colour *= m.albedo_bands;
                found += colour.of(e) * (beta / kPi);
            } else if (vp.dispersed) {
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
    photon_settings.volume_bounds = m_volume_box;  // empty (all kept) without media
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
    tbb::parallel_for(
        tbb::blocked_range<int>(0, m_height, 1), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y != rows.end(); ++y) {
                if (!dealt_to(y, comm)) continue;
                if (control.cancelled()) return;
                for (int x = 0; x < m_width; ++x) {
                    const size_t i = size_t(y) * m_width + x;
                    trace_camera_path(x, y, pass, points[i],
                                      m_segments.empty() ? nullptr : &m_segments[i * kMaxSegments]);
                }
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
        const bool gathers = vp.valid || vp.in_medium;
        valid_points += gathers;
        dispersed_points += gathers && vp.dispersed;
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
    const PhotonColours colours(scene, photons, pass);
    const double alpha = r.alpha;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, m_pixels.size(), 256),
                      [&](const tbb::blocked_range<size_t>& range) {
                          for (size_t i = range.begin(); i != range.end(); ++i) {
                              if (!dealt_to(static_cast<int64_t>(i) / m_width, comm)) continue;
                              const VisiblePoint& vp = points[i];
                              Pixel& px = m_pixels[i];
                              px.direct += vp.direct;
                              if (!vp.valid) continue;
                              const double radius2 = px.radius * px.radius;
                              const PhotonColours::Receiver at_point{vp.dispersed, vp.beta / kPi,
                                                                     vp.albedo, vp.albedo_bands};
                              PhotonColours::Sum sum;
                              int64_t found = 0;
                              grid.for_each_near(vp.p, px.radius, [&](size_t h) {
                                  const PhotonHit& ph = hits[h];
                                  if (length_squared(ph.pos() - vp.p) > radius2) return;
                                  if (dot(decode_octahedral(ph.normal), vp.n) < kSameSurfaceCos)
                                      return;
                                  ++found;
                                  colours.add(sum, ph, at_point, 1.0);
                              });
                              if (found == 0) continue;
                              const Rgb phi = colours.colour(sum, at_point);
                              // Hachisuka & Jensen 2009, eqs. 6 and 7 (and tau scaled with the
                              // disc's area).
                              const double n_new = px.n + alpha * static_cast<double>(found);
                              const double ratio = n_new / (px.n + static_cast<double>(found));
                              px.tau = (px.tau + phi) * ratio;
                              px.radius *= std::sqrt(ratio);
                              px.n = n_new;
                          }
                      });

    gather_volume(pass, photons, colours);

    ++m_stats.passes;
    m_stats.volume_photons = photons.volume.size();
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

void SppmIntegrator::gather_volume(const PassState& pass, const PhotonPass& photons,
                                   const PhotonColours& colours) {
    if (m_segments.empty()) return;
    const double radius = m_volume_radius;
    const double footprint = kVolumeFootprints * m_pixel_angle * radius / m_volume_radius_start;
    const auto position = [&](size_t i) { return photons.volume[i].pos(); };
    const std::vector<double> radii = volume_photon_radii(
        photons.volume.size(), position,
        {radius, footprint, m_scene.camera.position, m_scene.render.volume_neighbours});
    const PointBvh photon_discs(photons.volume.size(), position,
                                [&](size_t i) { return radii[i]; });
    const Communicator& comm = *m_cluster;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, m_pixels.size(), 256), [&](const tbb::
                                                                                   blocked_range<
                                                                                       size_t>&
                                                                                       range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            if (!dealt_to(static_cast<int64_t>(i) / m_width, comm)) continue;
            for (int k = 0; k < kMaxSegments; ++k) {
                const MediumSegment& seg = m_segments[i * kMaxSegments + size_t(k)];
                if (!(seg.beta > 0.0)) break;
                const HenyeyGreenstein phase(seg.medium->g);
                const int band = seg.dispersed ? band_of(pass.lambda_nm) : 0;
                const double sigma_t = seg.medium->extinction()[size_t(band)];
                // A heterogeneous medium's T(t): one ratio-tracking walk along the segment,
                // unbiased at every t (density_tracking.h), in its own random stream.
                std::optional<TransmittanceWalk> walk;
                if (seg.medium->is_heterogeneous()) {
                    Rng rng(pass.seed, kGatherStreams + i * kMaxSegments + size_t(k));
                    walk.emplace(*seg.medium, band, seg.ray, seg.t_max, rng);
                }
                const auto transmittance = [&](double t) {
                    return walk ? walk->at(t) : std::exp(-sigma_t * t);
                };
                const PhotonColours::Receiver to{seg.dispersed, seg.beta / kPi, nullptr, {1, 1, 1}};
                PhotonColours::Sum sum;
                photon_discs.for_each_near(seg.ray, seg.t_max, [&](size_t p, double t, double r2) {
                    const PhotonHit& ph = photons.volume[p];
                    const Vec3 travel = decode_octahedral(ph.normal);
                    const double w =
                        phase.eval(-dot(travel, seg.ray.direction)) * transmittance(t) / r2;
                    colours.add(sum, ph, to, w);
                });
                m_pixels[i].direct += colours.colour(sum, to);
            }
        }
    });
    m_stats.volume_radius = radius;
    // Knaus and Zwicker 2011: r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1), i the pass (from 1).
    const double i = m_stats.passes + 1;
    m_volume_radius *= std::sqrt((i + m_scene.render.alpha) / (i + 1.0));
}

void SppmIntegrator::share_visible_points(Communicator& comm) {
    if (comm.alone()) return;
    // Per row: each pixel's radius, and whether its visible point is valid (1) and dispersed
    // (2), and its path crossed a medium (4). Every rank then picks the same grid cell and the same
    // share of dispersed photons.
    const size_t rows = static_cast<size_t>(m_height), width = static_cast<size_t>(m_width);
    std::vector<std::vector<double>> radius(rows);
    std::vector<std::vector<uint8_t>> flags(rows);
    for (size_t y = static_cast<size_t>(comm.rank()); y < rows; y += size_t(comm.size())) {
        for (size_t i = y * width; i < (y + 1) * width; ++i) {
            radius[y].push_back(m_pixels[i].radius);
            flags[y].push_back(uint8_t(m_points[i].valid) | uint8_t(m_points[i].dispersed << 1) |
                               uint8_t(m_points[i].in_medium << 2));
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
            m_points[y * width + x].in_medium = flags[y][x] & 4;
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
