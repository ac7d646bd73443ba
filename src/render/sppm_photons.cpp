#include "render/sppm_photons.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "accel/photon.h"
#include "cluster/dealt_parts.h"
#include "optics/glass.h"
#include "render/pass_wavelength.h"
#include "render/photon_walk.h"

namespace lenslab {

namespace {

// The pass's deposit policy (render/photon_walk.h): a hit at every diffuse surface after the
// first, and the diffuse event goes on (Russian roulette on the albedo's largest component).
struct PassDeposit {
    static constexpr bool kSplitAimed = false;

    const Scene& scene;
    const PhotonPassSettings& s;
    std::vector<PhotonHit>& hits;  // the chunk's
    std::vector<PhotonHit>& volume;
    std::vector<uint32_t>& chains;
    const Spectrum* spectrum;  // of its light
    int light;
    double power;
    uint32_t chain;  // its first diffuse bounce in `chains`
    uint16_t chain_length = 0;
    PhotonWavelength kind = PhotonWavelength::All;
    double lambda_nm = 0;  // 0 until dispersed

    void arrive(const Interaction&, const Vec3&, int) const {}

    void disperse(Rng& rng) {
        double pdf = s.lambda_pdf * s.pass_share;
        if (rng.uniform() < s.pass_share) {
            kind = PhotonWavelength::Pass;
            lambda_nm = s.lambda_nm;
        } else {
            kind = PhotonWavelength::Own;
            lambda_nm = s.wavelengths->draw(rng.uniform(), pdf);
            pdf *= 1.0 - s.pass_share;
        }
        double f = spectrum->eval(lambda_nm) / pdf;
        for (uint16_t k = 0; k < chain_length; ++k)
            f *= scene.materials[chains[chain + k]].albedo->eval(lambda_nm);
        power *= f;
        chain_length = 0;
    }

    void hit(const Interaction& it, const Vec3& direction, int depth) {
        if (!(it.scattering.diffuse > 0.0 && !it.material->color.is_black()) || depth == 0) return;
        hits.push_back(record(it.point(), facing(it, direction)));
    }

    void scatter(const Vec3& p, const Vec3& direction, int depth) {
        // Straight from a light whose single scattering the camera's segments gather
        // (add_light_in_scattering): not a photon's to bring.
        if (depth == 0 && scene.lights()[static_cast<size_t>(light)]->samples_in_scattering())
            return;
        const Aabb& box = s.volume_bounds;
        if (!box.empty() && !box.contains(p)) return;
        volume.push_back(record(p, direction));
    }

    PhotonHit record(const Vec3& p, const Vec3& unit) const {
        PhotonHit h{};
        h.position[0] = static_cast<float>(p.x);
        h.position[1] = static_cast<float>(p.y);
        h.position[2] = static_cast<float>(p.z);
        encode_octahedral(unit, h.normal);
        h.power = static_cast<float>(power);
        if (lambda_nm > 0) {
            h.lambda_nm = static_cast<float>(lambda_nm);
        } else {
            h.chain = chain;
            h.chain_length = chain_length;
        }
        h.light = static_cast<uint16_t>(light);
        h.wavelength = kind;
        return h;
    }

    void attenuate(double t) { power *= t; }

    double diffuse_probability(const Interaction& it) const {
        return diffuse_continuation(it.scattering, *it.material);
    }

    bool diffuse(const Interaction& it, Ray& ray, double survive, int, Rng& rng) {
        power *= it.scattering.diffuse / survive;
        if (lambda_nm > 0) {
            power *= it.material->albedo->eval(lambda_nm);
        } else {
            chains.push_back(static_cast<uint32_t>(it.object->material));
            ++chain_length;
        }
        ray = {it.point(), sample_diffuse_direction(facing(it, ray.direction), rng)};
        return true;
    }

    // The surface normal on the side the photon arrives from.
    static Vec3 facing(const Interaction& it, const Vec3& direction) {
        const Vec3& n = it.normal();
        return dot(direction, n) < 0.0 ? n : -n;
    }
};

}  // namespace

PhotonPlan photon_pass_plan(const Scene& scene, const PhotonPassSettings& s) {
    return PhotonPlan(scene, s.photons_per_light, s.caustic_photons_per_light, s.aim, s.seed);
}

uint64_t photon_pass_bytes(const Scene& scene, const PhotonPassSettings& s) {
    // A photon leaves on average a few hits (one per diffuse bounce after the first); four
    // per photon bounds what the scenes here need with room to spare.
    const long double bytes = static_cast<long double>(photon_pass_plan(scene, s).total()) *
                              (4 * sizeof(PhotonHit) + 4 * sizeof(uint32_t));
    return bytes > 1.8e19L ? UINT64_MAX : static_cast<uint64_t>(bytes);
}

PhotonPass trace_photon_pass(const Scene& scene, const PhotonPassSettings& s,
                             RenderControl& control) {
    const PhotonPlan plan = photon_pass_plan(scene, s);
    const size_t chunks = static_cast<size_t>(photon_chunks(plan.total()));
    std::vector<std::vector<PhotonHit>> hits(chunks), volume(chunks);
    std::vector<std::vector<uint32_t>> chains(chunks);
    for_each_photon_chunk(plan.total(), control, [&](int64_t chunk, int64_t first, int64_t last) {
        const size_t c = static_cast<size_t>(chunk);
        PhotonWalker<PassDeposit> walker(scene, plan, s.max_depth);
        trace_photon_range(first, last, control, [&](int64_t i) {
            walker.trace(i, s.seed, [&](const PhotonPlan::Photon& p) {
                return PassDeposit{scene,
                                   s,
                                   hits[c],
                                   volume[c],
                                   chains[c],
                                   p.start.spectrum,
                                   p.light,
                                   p.start.scale,
                                   static_cast<uint32_t>(chains[c].size())};
            });
        });
    });
    // In a job of several ranks each traced the chunks dealt to it: every rank gets them all,
    // chunk by chunk, so the pass is the one a single process traces.
    share_dealt_parts(control.cluster(), hits);
    share_dealt_parts(control.cluster(), volume);
    share_dealt_parts(control.cluster(), chains);
    PhotonPass pass;
    if (control.cancelled()) return pass;
    std::vector<size_t> chain_at, hit_at;
    pass.chains = join_chunks(chains, chain_at);
    tbb::parallel_for(size_t{0}, chunks, [&](size_t c) {  // chains counted from the pass's first
        for (auto* part : {&hits[c], &volume[c]})
            for (PhotonHit& h : *part)
                if (h.wavelength == PhotonWavelength::All)
                    h.chain += static_cast<uint32_t>(chain_at[c]);
    });
    pass.hits = join_chunks(hits, hit_at);
    pass.volume = join_chunks(volume, hit_at);
    pass.emitted = plan.total();
    pass.aimed = plan.aimed_total();
    return pass;
}

}  // namespace lenslab
