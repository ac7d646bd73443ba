#include "render/sppm_photons.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "accel/photon.h"
#include "optics/glass.h"
#include "render/pass_wavelength.h"
#include "render/photon_walk.h"

namespace lenslab {

namespace {

struct ChunkOut {
    std::vector<PhotonHit> hits;
    std::vector<uint32_t> chains;
};

// The pass's deposit policy (render/photon_walk.h): a hit at every diffuse surface after the
// first, and the diffuse event goes on (Russian roulette on the albedo's largest component).
class PassDeposit {
public:
    static constexpr bool kSplitAimed = false;

    PassDeposit(const Scene& scene, const PhotonPassSettings& s, const PhotonPlan::Photon& photon,
                ChunkOut& out)
        : m_scene(scene),
          m_s(s),
          m_out(out),
          m_spectrum(photon.start.spectrum),
          m_light(photon.light),
          m_power(photon.start.scale),
          m_chain(static_cast<uint32_t>(out.chains.size())) {}

    double lambda_nm() const { return m_lambda; }
    bool dispersed() const { return m_kind != PhotonWavelength::All; }
    void arrive(const Interaction&, const Vec3&, int) const {}

    void disperse(Rng& rng) {
        double pdf = m_s.lambda_pdf * m_s.pass_share;
        if (rng.uniform() < m_s.pass_share) {
            m_kind = PhotonWavelength::Pass;
            m_lambda = m_s.lambda_nm;
        } else {
            m_kind = PhotonWavelength::Own;
            m_lambda = m_s.wavelengths->draw(rng.uniform(), pdf);
            pdf *= 1.0 - m_s.pass_share;
        }
        double f = m_spectrum->eval(m_lambda) / pdf;
        for (uint16_t k = 0; k < m_chain_length; ++k)
            f *= m_scene.materials[m_out.chains[m_chain + k]].albedo->eval(m_lambda);
        m_power *= f;
        m_chain_length = 0;
    }

    void hit(const Interaction& it, const Vec3& direction, int depth) {
        if (!(it.scattering.diffuse > 0.0 && !it.material->color.is_black()) || depth == 0) return;
        PhotonHit h{};
        const Vec3& p = it.point();
        h.position[0] = static_cast<float>(p.x);
        h.position[1] = static_cast<float>(p.y);
        h.position[2] = static_cast<float>(p.z);
        encode_octahedral(facing(it, direction), h.normal);
        h.power = static_cast<float>(m_power);
        if (dispersed()) {
            h.lambda_nm = static_cast<float>(m_lambda);
        } else {
            h.chain = m_chain;
            h.chain_length = m_chain_length;
        }
        h.light = static_cast<uint16_t>(m_light);
        h.wavelength = m_kind;
        m_out.hits.push_back(h);
    }

    double diffuse_probability(const Interaction& it) const {
        return diffuse_continuation(it.scattering, *it.material);
    }

    bool diffuse(const Interaction& it, Ray& ray, double survive, int, Rng& rng) {
        m_power *= it.scattering.diffuse / survive;
        if (dispersed()) {
            m_power *= it.material->albedo->eval(m_lambda);
        } else {
            m_out.chains.push_back(static_cast<uint32_t>(it.object->material));
            ++m_chain_length;
        }
        ray = {it.point(), sample_diffuse_direction(facing(it, ray.direction), rng)};
        return true;
    }

private:
    // The surface normal on the side the photon arrives from.
    static Vec3 facing(const Interaction& it, const Vec3& direction) {
        const Vec3& n = it.normal();
        return dot(direction, n) < 0.0 ? n : -n;
    }

    const Scene& m_scene;
    const PhotonPassSettings& m_s;
    ChunkOut& m_out;
    const Spectrum* m_spectrum;  // of its light
    int m_light;
    double m_power;
    PhotonWavelength m_kind = PhotonWavelength::All;
    double m_lambda = kLineD;
    uint32_t m_chain;  // its first diffuse bounce in m_out.chains
    uint16_t m_chain_length = 0;
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
    std::vector<ChunkOut> outs(static_cast<size_t>(photon_chunks(plan.total())));
    for_each_photon_chunk(plan.total(), control, [&](int64_t chunk, int64_t first, int64_t last) {
        ChunkOut& out = outs[static_cast<size_t>(chunk)];
        PhotonWalker<PassDeposit> walker(scene, plan, s.max_depth);
        for (int64_t i = first; i < last; ++i) {
            walker.trace(i, s.seed, [&](const PhotonPlan::Photon& p) {
                return PassDeposit(scene, s, p, out);
            });
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
