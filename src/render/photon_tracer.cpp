#include "render/photon_tracer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "cluster/dealt_parts.h"
#include "render/chunk_collector.h"
#include "render/photon_walk.h"

namespace lenslab {

namespace {

// The lists of a chunk's deposits (ChunkCollector).
constexpr size_t kDirectList = 0, kCausticList = 1;

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

// The photon map's deposit policy (render/photon_walk.h). An emitted photon is stored where
// Russian roulette picks the diffuse event (power / p_diffuse keeps the estimate unbiased)
// and ends there; an aimed one splits and leaves its whole arriving power at every diffuse
// surface (as roulette stores on average). Photons go to the direct list (first surface) or
// the caustic one, none when they are null; `on_arrival`, if given, sees the photon at every
// surface before the material acts (a detector).
//
// A photon carries its light's whole spectrum (its power is the exact colour of its share)
// until it meets a dispersive refraction; only there does it draw one wavelength from the
// light's spectrum and become that wavelength's colour. Scenes without dispersion thus get
// no colour noise from wavelength sampling.
struct MapDeposit {
    static constexpr bool kSplitAimed = true;

    Rgb power;
    const Spectrum* spectrum;  // spectral flux shape of its light
    double scale;              // this photon's share of it
    double radiant_power;      // what it carries: scale x the spectrum's radiant power
    int light;
    bool aimed;
    const PhotonArrivalFn* on_arrival;
    std::vector<Photon>* direct;  // where photons go, or nullptr (a detector's walk)
    std::vector<Photon>* caustic;
    double lambda_nm = 0;  // 0 until a dispersive refraction picks one
    double wavelength_u;   // where in the spectrum it picks it, or < 0: at random

    MapDeposit(const PhotonPlan::Photon& p, const LightSpectrum& ls, const PhotonArrivalFn* arrival,
               std::vector<Photon>* direct_list = nullptr,
               std::vector<Photon>* caustic_list = nullptr)
        : power(ls.colour * p.start.scale),
          spectrum(p.start.spectrum),
          scale(p.start.scale),
          radiant_power(ls.radiant_power * p.start.scale),
          light(p.light),
          aimed(p.aimed),
          on_arrival(arrival),
          direct(direct_list),
          caustic(caustic_list),
          wavelength_u(p.wavelength_u) {}

    void arrive(const Interaction& it, const Vec3& direction, int depth) const {
        if (on_arrival) {
            (*on_arrival)(
                PhotonArrival{&it, direction, light, aimed, depth, spectrum, scale, lambda_nm});
        }
    }

    // The wavelength follows the spectrum's 1 nm histogram; the photon keeps its whole radiant
    // power, so on average it has the spectrum's colour and it never gains power. (Weighting
    // by the spectrum's value at the drawn wavelength over the histogram's density instead
    // made photons of a line narrower than a bin up to 15 times brighter than their light.)
    void disperse(Rng& rng) {
        (void)spectrum->sample_wavelength(wavelength_u >= 0 ? wavelength_u : rng.uniform(),
                                          lambda_nm);
        power = sample_to_rgb(radiant_power, lambda_nm, 1.0);
    }

    void hit(const Interaction& it, const Vec3& direction, int depth) {
        if (aimed && diffuse_probability(it) > 0.0) store(it, power, direction, depth);
    }

    double diffuse_probability(const Interaction& it) const {
        return it.material->color.is_black() ? 0.0 : it.scattering.diffuse;
    }

    bool diffuse(const Interaction& it, Ray& ray, double p_diffuse, int depth, Rng&) {
        store(it, power * (1.0 / p_diffuse), ray.direction, depth);
        return false;
    }

    void attenuate(double t) { carry(t); }

    // The photon map holds surface photons only (the photon_map integrator refuses media); a
    // detector measures what reaches it, wherever the photon scattered on the way.
    void scatter(const Vec3&, const Vec3&, int) const {}

    void carry(double w) {
        power = power * w;
        scale *= w;
        radiant_power *= w;
    }

    void store(const Interaction& it, const Rgb& p, const Vec3& direction, int depth) {
        std::vector<Photon>* map = depth == 0 ? direct : caustic;
        if (map) {
            map->push_back(make_photon(it.point(), p, -direction,
                                       depth == 0 ? PhotonKind::Direct : PhotonKind::Caustic));
        }
    }
};
// In a job of several ranks: the chunks the others traced, into `found`, so every rank builds
// the whole maps with the photons in the order one process stores them.
void share_map_chunks(Communicator& comm, ChunkCollector<Photon>& found, size_t chunks) {
    if (comm.alone()) return;
    std::vector<std::vector<Photon>> direct(chunks), caustic(chunks);
    for (size_t c = 0; c < chunks; ++c) {
        if (!dealt_to(static_cast<int64_t>(c), comm)) continue;
        direct[c] = found.items(c, kDirectList);
        caustic[c] = found.items(c, kCausticList);
    }
    share_dealt_parts(comm, direct);
    share_dealt_parts(comm, caustic);
    for (size_t c = 0; c < chunks; ++c) {
        if (dealt_to(static_cast<int64_t>(c), comm)) continue;
        ChunkCollector<Photon>::Lists lists;
        lists[kDirectList] = std::move(direct[c]);
        lists[kCausticList] = std::move(caustic[c]);
        found.put(c, lists);
    }
}

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
    const size_t chunks = static_cast<size_t>(photon_chunks(plan.total()));
    // The direct photons and the caustic ones in two lists: the maps are then two runs.
    ChunkCollector<Photon> found(chunks, need / sizeof(Photon));
    for_each_photon_chunk(plan.total(), control, [&](int64_t chunk, int64_t first, int64_t last) {
        ChunkCollector<Photon>::Lists& lists = found.scratch();
        PhotonWalker<MapDeposit> walker(scene, plan, settings.max_depth);
        trace_photon_range(first, last, control, [&](int64_t i) {
            walker.trace(i, settings.seed, [&](const PhotonPlan::Photon& p) {
                return MapDeposit(p, spectra[static_cast<size_t>(p.light)], nullptr,
                                  &lists[kDirectList], &lists[kCausticList]);
            });
        });
        found.put(static_cast<size_t>(chunk), lists);
    });
    share_map_chunks(control.cluster(), found, chunks);
    // Cancelled: the render throws the photons away, so do not build a tree over them.
    if (control.cancelled() || !found.complete()) return {};
    size_t direct = 0, caustic = 0;
    std::unique_ptr<Photon[]> direct_photons = found.take(kDirectList, direct);
    std::unique_ptr<Photon[]> caustic_photons = found.take(kCausticList, caustic);
    const auto t1 = std::chrono::steady_clock::now();
    PhotonMap map(std::move(direct_photons), direct, std::move(caustic_photons), caustic);
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
    PhotonWalker<MapDeposit>(scene, plan, settings.max_depth)
        .trace(index, settings.seed, [&](const PhotonPlan::Photon& p) {
            return MapDeposit(p, LightSpectrum{}, &on_arrival);
        });
}

}  // namespace lenslab
