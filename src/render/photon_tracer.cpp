#include "render/photon_tracer.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <unistd.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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
    Ray ray;
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

// The photon-map tracer's photon: the emitted start with its colour as RGB and its power.
EmittedPhoton emit(const Scene& scene, int light, const LightSpectrum& ls, int64_t n, Rng& rng) {
    const PhotonStart start = emit_photon(scene, light, n, rng);
    return EmittedPhoton{start.ray, ls.colour * start.scale, start.spectrum, start.scale,
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

// Follows one photon until it is stored, absorbed, escapes or exceeds the depth. Returns
// the stored photon (kind None if none). Russian roulette picks one event per hit with the
// material's weights: diffuse (store; power / p_diffuse keeps the estimate unbiased),
// one of the specular branches (power unchanged: its weight equals its probability), or
// absorption.
// `on_arrival`, if given, sees the photon at every surface before the material acts.
Photon trace_one(const Scene& scene, EmittedPhoton e, int max_depth, Rng& rng,
                 const PhotonArrivalFn* on_arrival = nullptr, int light = 0) {
    Ray ray = e.ray;
    for (int depth = 0; depth <= max_depth; ++depth) {
        Interaction it;
        if (!next_interaction(scene, ray, e.lambda_nm > 0 ? e.lambda_nm : kLineD, it)) break;
        if (on_arrival) {
            (*on_arrival)(PhotonArrival{&it, ray.direction, light, depth, e.spectrum, e.scale, e.lambda_nm});
        }
        if (e.lambda_nm == 0 && it.scattering.dispersive) {
            e.pick_wavelength(rng);
            it.scattering = scatter_at(it, ray.direction, e.lambda_nm);
        }
        const Scattering& s = it.scattering;
        double u = rng.uniform();
        const double p_diffuse = it.material->color.is_black() ? 0.0 : s.diffuse;
        if (u < p_diffuse) {
            const PhotonKind kind = depth == 0 ? PhotonKind::Direct : PhotonKind::Caustic;
            return make_photon(it.point(), e.power * (1.0 / p_diffuse), -ray.direction, kind);
        }
        u -= p_diffuse;
        const Branch* chosen = nullptr;
        for (int i = 0; i < s.count && !chosen; ++i) {
            if (u < s.branches[i].weight) chosen = &s.branches[i];
            u -= s.branches[i].weight;
        }
        if (!chosen) break;  // absorbed (or the diffuse share of a black surface)
        ray = {it.point(), chosen->direction};
    }
    return Photon{};
}

}  // namespace

uint64_t photon_storage_bytes(const Scene& scene, int64_t photons_per_light) {
    // One slot per emitted photon: a photon is stored at most once (at its first diffuse
    // surface), and the slots are compacted afterwards.
    const long double bytes = static_cast<long double>(photons_per_light) * photon_light_count(scene) * sizeof(Photon);
    return bytes > static_cast<long double>(std::numeric_limits<uint64_t>::max())
               ? std::numeric_limits<uint64_t>::max()
               : static_cast<uint64_t>(bytes);
}

uint64_t available_memory_bytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    uint64_t kib = 0;
    while (meminfo >> key >> kib) {
        if (key == "MemAvailable:") return kib * 1024;
        meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    }
    return static_cast<uint64_t>(sysconf(_SC_PHYS_PAGES)) * static_cast<uint64_t>(sysconf(_SC_PAGE_SIZE));
}

PhotonMap trace_photons(const Scene& scene, const PhotonTracingSettings& settings,
                        RenderControl& control, PhotonTracingStats* stats) {
    const auto t0 = std::chrono::steady_clock::now();
    const int lights = photon_light_count(scene);
    const int64_t n = settings.photons_per_light;
    const uint64_t need = photon_storage_bytes(scene, n);
    const uint64_t have = available_memory_bytes();
    // Leave room for the image, the scene and the system: use at most 80% of what is free.
    if (need > have / 10 * 8) {
        std::ostringstream msg;
        msg << "photons: " << n << " photons per light x " << lights << " light(s) need "
            << need / (1024 * 1024) << " MiB of photon storage, but only " << have / (1024 * 1024)
            << " MiB of memory is available; use fewer photons";
        throw ResourceError(msg.str());
    }

    std::vector<Photon> slots(static_cast<size_t>(n) * lights);
    std::vector<LightSpectrum> spectra;
    for (int l = 0; l < lights; ++l) {
        const Spectrum& s = emitted_spectrum(scene, l);
        spectra.push_back({spectrum_to_rgb(s), radiant_power(s)});
    }
    const int64_t chunks_per_light = (n + kChunk - 1) / kChunk;
    const int64_t chunks = chunks_per_light * lights;
    tbb::parallel_for(tbb::blocked_range<int64_t>(0, chunks, 1), [&](const tbb::blocked_range<int64_t>& r) {
        for (int64_t chunk = r.begin(); chunk != r.end(); ++chunk) {
            if (control.cancelled()) return;
            const int light = static_cast<int>(chunk / chunks_per_light);
            const int64_t first = (chunk % chunks_per_light) * kChunk;
            const int64_t last = std::min(n, first + kChunk);
            for (int64_t i = first; i < last; ++i) {
                const int64_t slot = light * n + i;
                Rng rng(settings.seed, kPhotonStreamBase + static_cast<uint64_t>(slot));
                slots[static_cast<size_t>(slot)] = trace_one(scene, emit(scene, light, spectra[light], n, rng), settings.max_depth, rng);
            }
        }
    });
    const auto t1 = std::chrono::steady_clock::now();
    PhotonMap map(std::move(slots));
    const auto t2 = std::chrono::steady_clock::now();
    if (stats) {
        stats->emitted = n * lights;
        stats->direct = map.direct().size();
        stats->caustic = map.caustic().size();
        stats->trace_seconds = std::chrono::duration<double>(t1 - t0).count();
        stats->build_seconds = std::chrono::duration<double>(t2 - t1).count();
        stats->memory_bytes = map.memory_bytes();
    }
    return map;
}

void trace_photon_path(const Scene& scene, const PhotonTracingSettings& settings, int light, int64_t index,
                       const PhotonArrivalFn& on_arrival) {
    // The stream and the draws of trace_photons' slot for this photon; the colour only
    // feeds the stored RGB power, which nothing reads here.
    const int64_t slot = light * settings.photons_per_light + index;
    Rng rng(settings.seed, kPhotonStreamBase + static_cast<uint64_t>(slot));
    const EmittedPhoton e = emit(scene, light, LightSpectrum{}, settings.photons_per_light, rng);
    (void)trace_one(scene, e, settings.max_depth, rng, &on_arrival, light);
}

}  // namespace lenslab
