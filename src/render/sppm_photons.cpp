#include "render/sppm_photons.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "accel/photon.h"
#include "math/rng.h"
#include "optics/glass.h"
#include "render/pass_wavelength.h"
#include "render/photon_emission.h"
#include "scene/interaction.h"

namespace lenslab {

namespace {

constexpr uint64_t kPhotonStreamBase = uint64_t{1} << 62;
constexpr int64_t kChunk = 4096;

struct ChunkOut {
    std::vector<PhotonHit> hits;
    std::vector<uint32_t> chains;
};

void trace_one(const Scene& scene, const PhotonPassSettings& s, const PhotonPlan& plan,
               int64_t index, Rng& rng, ChunkOut& out) {
    const PhotonPlan::Photon photon = plan.start(scene, index, rng);
    const PhotonStart& start = photon.start;
    if (start.scale == 0.0) return;  // sampled where the light sends nothing
    const int light = photon.light;
    Ray ray = start.ray;
    double power = start.scale;
    bool dispersed = false;
    PhotonWavelength kind = PhotonWavelength::All;
    double lambda = kLineD;
    const uint32_t chain = static_cast<uint32_t>(out.chains.size());
    uint16_t chain_length = 0;
    for (int depth = 0; depth <= s.max_depth; ++depth) {
        Interaction it;
        if (!next_interaction(scene, ray, lambda, it)) return;
        // Only in its stream's part of the light's emission (photon_emission.h).
        if (depth == 0 && !plan.counts(scene, light, photon.aimed, it.hit.object)) return;
        if (!dispersed && it.scattering.dispersive) {
            // From here the path depends on wavelength: take one.
            dispersed = true;
            double pdf = s.lambda_pdf * s.pass_share;
            if (rng.uniform() < s.pass_share) {
                kind = PhotonWavelength::Pass;
                lambda = s.lambda_nm;
            } else {
                kind = PhotonWavelength::Own;
                lambda = s.wavelengths->draw(rng.uniform(), pdf);
                pdf *= 1.0 - s.pass_share;
            }
            double f = start.spectrum->eval(lambda) / pdf;
            for (uint16_t k = 0; k < chain_length; ++k)
                f *= scene.materials[out.chains[chain + k]].albedo->eval(lambda);
            power *= f;
            chain_length = 0;
            it.scattering = scatter_at(it, ray.direction, lambda);
        }
        const Scattering& sc = it.scattering;
        const Material& m = *it.material;
        const Vec3& n = it.normal();
        const Vec3 facing = dot(ray.direction, n) < 0.0 ? n : -n;
        const bool diffuse = sc.diffuse > 0.0 && !m.color.is_black();
        if (diffuse && depth > 0) {
            PhotonHit h{};
            const Vec3& p = it.point();
            h.position[0] = static_cast<float>(p.x);
            h.position[1] = static_cast<float>(p.y);
            h.position[2] = static_cast<float>(p.z);
            encode_octahedral(facing, h.normal);
            h.power = static_cast<float>(power);
            if (dispersed) {
                h.lambda_nm = static_cast<float>(lambda);
            } else {
                h.chain = chain;
                h.chain_length = chain_length;
            }
            h.light = static_cast<uint16_t>(light);
            h.wavelength = kind;
            out.hits.push_back(h);
        }
        // One event with the material's weights as probabilities (Russian roulette); the
        // diffuse bounce survives with the albedo's largest component.
        const double survive = diffuse_continuation(sc, m);
        const EventPick event = pick_event(sc, survive, rng.uniform());
        if (event.diffuse) {
            power *= sc.diffuse / survive;
            if (dispersed) {
                power *= m.albedo->eval(lambda);
            } else {
                out.chains.push_back(static_cast<uint32_t>(it.object->material));
                ++chain_length;
            }
            ray = {it.point(), sample_diffuse_direction(facing, rng)};
            continue;
        }
        if (!event.branch) return;  // absorbed
        ray = {it.point(), event.branch->direction};
    }
}

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
    const int64_t chunks = (plan.total() + kChunk - 1) / kChunk;
    std::vector<ChunkOut> outs(static_cast<size_t>(chunks));
    tbb::parallel_for(
        tbb::blocked_range<int64_t>(0, chunks, 1), [&](const tbb::blocked_range<int64_t>& r) {
            for (int64_t c = r.begin(); c != r.end(); ++c) {
                if (control.cancelled()) return;
                const int64_t first = c * kChunk, last = std::min(plan.total(), first + kChunk);
                ChunkOut& out = outs[static_cast<size_t>(c)];
                for (int64_t i = first; i < last; ++i) {
                    Rng rng(s.seed, kPhotonStreamBase + static_cast<uint64_t>(i));
                    trace_one(scene, s, plan, i, rng, out);
                }
            }
        });
    PhotonPass pass;
    if (control.cancelled()) return pass;
    // Concatenate in chunk order: the same hits in the same order for any thread count.
    std::vector<size_t> hit_at(outs.size() + 1, 0), chain_at(outs.size() + 1, 0);
    for (size_t c = 0; c < outs.size(); ++c) {
        hit_at[c + 1] = hit_at[c] + outs[c].hits.size();
        chain_at[c + 1] = chain_at[c] + outs[c].chains.size();
    }
    pass.hits.resize(hit_at.back());
    pass.chains.resize(chain_at.back());
    tbb::parallel_for(size_t{0}, outs.size(), [&](size_t c) {
        const uint32_t offset = static_cast<uint32_t>(chain_at[c]);
        for (size_t i = 0; i < outs[c].hits.size(); ++i) {
            PhotonHit h = outs[c].hits[i];
            if (h.wavelength == PhotonWavelength::All) h.chain += offset;
            pass.hits[hit_at[c] + i] = h;
        }
        std::copy(outs[c].chains.begin(), outs[c].chains.end(),
                  pass.chains.begin() + static_cast<ptrdiff_t>(chain_at[c]));
    });
    pass.emitted = plan.total();
    pass.aimed = plan.aimed_total();
    return pass;
}

}  // namespace lenslab
