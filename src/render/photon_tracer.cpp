#include "render/photon_tracer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "math/rng.h"
#include "render/photon_emission.h"
#include "scene/interaction.h"

namespace lenslab {

namespace {

// Random streams for photons are offset from the per-pixel camera streams.
constexpr uint64_t kPhotonStreamBase = uint64_t{1} << 62;
constexpr int64_t kChunk = 4096;

// A photon carries its light's whole spectrum (its power is the exact colour of its share)
// until it meets a dispersive refraction; only there does it draw one wavelength from the
// light's spectrum and become that wavelength's colour. Scenes without dispersion thus get
// no colour noise from wavelength sampling.
struct EmittedPhoton {
    Rgb power;
    const Spectrum* spectrum;  // spectral flux shape of its light
    double scale;              // this photon's share of it
    double radiant_power;      // what it carries: scale x the spectrum's radiant power
    double lambda_nm = 0;      // 0 until a dispersive refraction picks one

    // The wavelength follows the spectrum's 1 nm histogram; the photon keeps its whole radiant
    // power, so on average it has the spectrum's colour and it never gains power. (Weighting
    // by the spectrum's value at the drawn wavelength over the histogram's density instead
    // made photons of a line narrower than a bin up to 15 times brighter than their light.)
    void pick_wavelength(Rng& rng) {
        double nm;
        (void)spectrum->sample_wavelength(rng.uniform(), nm);
        power = sample_to_rgb(radiant_power, nm, 1.0);
        lambda_nm = nm;
    }
};

// The colour and the radiant power of a light's spectrum, computed once per light.
struct LightSpectrum {
    Rgb colour;
    double radiant_power;
};

std::vector<LightSpectrum> light_spectra(const Scene& scene) {
    std::vector<LightSpectrum> out;
    for (const LightPtr& l : scene.lights())
        out.push_back({spectrum_to_rgb(l->spectrum()), radiant_power(l->spectrum())});
    return out;
}

EmittedPhoton emitted(const PhotonStart& start, const LightSpectrum& ls) {
    return EmittedPhoton{ls.colour * start.scale, start.spectrum, start.scale,
                         ls.radiant_power * start.scale};
}

Photon make_photon(const Vec3& p, const Rgb& power, const Vec3& towards, PhotonKind kind) {
    Photon ph{};
    ph.position[0] = static_cast<float>(p.x);
    ph.position[1] = static_cast<float>(p.y);
    ph.position[2] = static_cast<float>(p.z);
    ph.power[0] = static_cast<float>(power.r);
    ph.power[1] = static_cast<float>(power.g);
    ph.power[2] = static_cast<float>(power.b);
    encode_octahedral(towards, ph.towards);
    ph.kind = kind;
    return ph;
}

// One photon through the scene. The photons it leaves on diffuse surfaces go to the direct
// or the caustic list (none when they are null);
// `on_arrival`, if given, sees it at every surface before the material acts.
class PhotonWalk {
public:
    PhotonWalk(const Scene& scene, const PhotonPlan& plan, int max_depth,
               const PhotonArrivalFn* on_arrival, std::vector<Photon>* direct = nullptr,
               std::vector<Photon>* caustic = nullptr)
        : m_scene(scene),
          m_plan(plan),
          m_max_depth(max_depth),
          m_on_arrival(on_arrival),
          m_direct(direct),
          m_caustic(caustic) {}

    // Traces photon `p` with its own random stream `rng`.
    void run(const PhotonPlan::Photon& p, const LightSpectrum& ls, Rng& rng) {
        m_rng = &rng;
        m_light = p.light;
        m_aimed = p.aimed;
        m_initial_scale = p.start.scale;
        if (p.start.scale == 0.0) return;  // sampled where the light sends nothing
        if (p.aimed) {
            split(emitted(p.start, ls), p.start.ray);
        } else {
            roulette(emitted(p.start, ls), p.start.ray);
        }
    }

private:
    // The next surface, or false; the first surface must be in this stream's part of the
    // light's emission (photon_emission.h).
    bool arrive(const Ray& ray, EmittedPhoton& e, int depth, Interaction& it) {
        if (!next_interaction(m_scene, ray, e.lambda_nm > 0 ? e.lambda_nm : kLineD, it))
            return false;
        if (depth == 0 && !m_plan.counts(m_scene, m_light, m_aimed, it.hit.object)) return false;
        if (m_on_arrival) {
            (*m_on_arrival)(PhotonArrival{&it, ray.direction, m_light, m_aimed, depth, e.spectrum,
                                          e.scale, e.lambda_nm});
        }
        if (e.lambda_nm == 0 && it.scattering.dispersive) {
            e.pick_wavelength(*m_rng);
            it.scattering = scatter_at(it, ray.direction, e.lambda_nm);
        }
        return true;
    }

    double diffuse_share(const Interaction& it) const {
        return it.material->color.is_black() ? 0.0 : it.scattering.diffuse;
    }

    void store(const Interaction& it, const Rgb& power, const Vec3& direction, int depth) {
        std::vector<Photon>* map = depth == 0 ? m_direct : m_caustic;
        if (map) {
            map->push_back(make_photon(it.point(), power, -direction,
                                       depth == 0 ? PhotonKind::Direct : PhotonKind::Caustic));
        }
    }

    // Russian roulette picks one event per hit with the material's weights: diffuse (store;
    // power / p_diffuse keeps the estimate unbiased), one of the specular branches (power
    // unchanged: its weight equals its probability), or absorption.
    void roulette(EmittedPhoton e, Ray ray) {
        for (int depth = 0; depth <= m_max_depth; ++depth) {
            Interaction it;
            if (!arrive(ray, e, depth, it)) return;
            const Scattering& s = it.scattering;
            const double p_diffuse = diffuse_share(it);
            const EventPick event = pick_event(s, p_diffuse, m_rng->uniform());
            if (event.diffuse) {
                store(it, e.power * (1.0 / p_diffuse), ray.direction, depth);
                return;
            }
            if (!event.branch) return;  // absorbed (or the diffuse share of a black surface)
            ray = {it.point(), event.branch->direction};
        }
    }

    // Every event at once: the diffuse share is stored (the photon's whole arriving power,
    // as roulette stores on average) and each specular branch goes on with its weight.
    // Branches wait on a list, not the call stack: a mirror corridor is a thousand deep.
    void split(const EmittedPhoton& e, const Ray& ray) {
        m_pending.clear();
        m_pending.push_back({e, ray, 0});
        while (!m_pending.empty()) {
            Pending p = m_pending.back();
            m_pending.pop_back();
            Interaction it;
            if (p.depth > m_max_depth || !arrive(p.ray, p.photon, p.depth, it)) continue;
            if (diffuse_share(it) > 0.0) store(it, p.photon.power, p.ray.direction, p.depth);
            const Scattering& s = it.scattering;
            for (int i = 0; i < s.count; ++i) {
                double w = s.branches[i].weight;
                const double share = w * p.photon.scale / m_initial_scale;
                if (share < kSplitFloor) {
                    // Survives with probability share / floor, carrying the floor.
                    if (m_rng->uniform() * kSplitFloor >= share) continue;
                    w *= kSplitFloor / share;
                }
                EmittedPhoton branch = p.photon;
                branch.power = branch.power * w;
                branch.scale *= w;
                branch.radiant_power *= w;
                m_pending.push_back({branch, {it.point(), s.branches[i].direction}, p.depth + 1});
            }
        }
    }

    struct Pending {
        EmittedPhoton photon;
        Ray ray;
        int depth;
    };

    const Scene& m_scene;
    const PhotonPlan& m_plan;
    int m_max_depth;
    Rng* m_rng = nullptr;
    const PhotonArrivalFn* m_on_arrival;
    std::vector<Photon>* m_direct;  // where photons go, or nullptr (a detector's walk)
    std::vector<Photon>* m_caustic;
    int m_light = 0;
    bool m_aimed = false;
    double m_initial_scale = 1.0;  // the photon's share as it left the light
    std::vector<Pending> m_pending;
};
}  // namespace

PhotonPlan photon_plan(const Scene& scene, const PhotonTracingSettings& settings) {
    return PhotonPlan(scene, settings.photons_per_light, settings.caustic_photons_per_light,
                      settings.aim, settings.seed);
}

uint64_t photon_storage_bytes(const Scene& scene, const PhotonTracingSettings& settings) {
    // An emitted photon is stored at most once (at its first diffuse surface); an aimed one
    // splits, and through glass leaves about one photon and a share of another (kSplitFloor
    // bounds the branches): two slots each.
    const PhotonPlan plan = photon_plan(scene, settings);
    const long double bytes = (static_cast<long double>(plan.emitted_total()) +
                               2.0L * static_cast<long double>(plan.aimed_total())) *
                              sizeof(Photon);
    return bytes > static_cast<long double>(std::numeric_limits<uint64_t>::max())
               ? std::numeric_limits<uint64_t>::max()
               : static_cast<uint64_t>(bytes);
}

PhotonMap trace_photons(const Scene& scene, const PhotonTracingSettings& settings,
                        RenderControl& control, PhotonTracingStats* stats) {
    const auto t0 = std::chrono::steady_clock::now();
    const PhotonPlan plan = photon_plan(scene, settings);
    const uint64_t need = photon_storage_bytes(scene, settings);
    check_memory_budget(need,
                        "photons: " + std::to_string(plan.total()) + " photons in all from " +
                            std::to_string(photon_light_count(scene)) + " light(s) need",
                        " of photon storage", "use fewer photons");

    const std::vector<LightSpectrum> spectra = light_spectra(scene);
    const int64_t chunks = (plan.total() + kChunk - 1) / kChunk;
    // Per chunk, the direct photons and the caustic ones apart: the maps are then two runs.
    std::vector<std::vector<Photon>> found(2 * static_cast<size_t>(chunks));
    tbb::parallel_for(
        tbb::blocked_range<int64_t>(0, chunks, 1), [&](const tbb::blocked_range<int64_t>& r) {
            for (int64_t chunk = r.begin(); chunk != r.end(); ++chunk) {
                if (control.cancelled()) return;
                std::vector<Photon>& direct = found[static_cast<size_t>(chunk)];
                std::vector<Photon>& caustic = found[static_cast<size_t>(chunks + chunk)];
                const int64_t first = chunk * kChunk, last = std::min(plan.total(), first + kChunk);
                // Room for the split photons too: growing a chunk would copy it.
                direct.reserve(static_cast<size_t>(last - first));
                caustic.reserve(static_cast<size_t>(2 * (last - first)));
                PhotonWalk walk(scene, plan, settings.max_depth, nullptr, &direct, &caustic);
                for (int64_t i = first; i < last; ++i) {
                    Rng rng(settings.seed, kPhotonStreamBase + static_cast<uint64_t>(i));
                    const PhotonPlan::Photon p = plan.start(scene, i, rng);
                    walk.run(p, spectra[static_cast<size_t>(p.light)], rng);
                }
            }
        });
    // Concatenated in photon order, direct then caustic (the same maps for any thread
    // count), chunks in parallel.
    std::vector<size_t> offset(found.size() + 1, 0);
    for (size_t c = 0; c < found.size(); ++c) offset[c + 1] = offset[c] + found[c].size();
    std::vector<Photon> photons(offset.back());
    tbb::parallel_for(size_t{0}, found.size(), [&](size_t c) {
        std::copy(found[c].begin(), found[c].end(),
                  photons.begin() + static_cast<ptrdiff_t>(offset[c]));
        std::vector<Photon>().swap(found[c]);
    });
    const auto t1 = std::chrono::steady_clock::now();
    PhotonMap map(std::move(photons), offset[static_cast<size_t>(chunks)]);
    const auto t2 = std::chrono::steady_clock::now();
    if (stats) {
        stats->emitted = plan.total();
        stats->aimed = plan.aimed_total();
        stats->direct = map.direct().size();
        stats->caustic = map.caustic().size();
        stats->trace_seconds = std::chrono::duration<double>(t1 - t0).count();
        stats->build_seconds = std::chrono::duration<double>(t2 - t1).count();
        stats->memory_bytes = map.memory_bytes();
    }
    return map;
}

void trace_photon_path(const Scene& scene, const PhotonTracingSettings& settings,
                       const PhotonPlan& plan, int64_t index, const PhotonArrivalFn& on_arrival) {
    // The stream and the draws of trace_photons' photon `index`; the colour only feeds the
    // stored RGB power, which nothing reads here.
    Rng rng(settings.seed, kPhotonStreamBase + static_cast<uint64_t>(index));
    const PhotonPlan::Photon p = plan.start(scene, index, rng);
    PhotonWalk(scene, plan, settings.max_depth, &on_arrival).run(p, LightSpectrum{}, rng);
}

}  // namespace lenslab
