#pragma once
// The photon tracer shared by the photon map (render/photon_tracer.h), the detectors (through
// trace_photon_path) and the photon pass of stochastic progressive photon mapping
// (render/sppm_photons.h). A photon leaves its light (render/photon_emission.h), meets a
// surface, and one event is chosen with the material's weights as probabilities (Russian
// roulette: pick_event); aimed photons may instead split at each surface into all its
// branches. What a photon carries and leaves behind is a deposit policy's, a class with:
//   kSplitAimed            (static constexpr bool) aimed photons split, else they play roulette
//   lambda_nm              (double) its wavelength once dispersed, 0 until then (traced at kLineD)
//   arrive(it, dir, depth) it reached a surface, the material not acted yet (detectors)
//   disperse(rng)          its first dispersive refraction: set lambda_nm
//   hit(it, dir, depth)    at every surface, its scattering known: deposit here, if at all
//   diffuse_probability(it)  of the diffuse event in roulette
//   diffuse(it, ray, p, depth, rng)  roulette chose it: false ends the path, true goes on
//                          along `ray` (set by the policy)
//   attenuate(t)           Beer-Lambert: it kept the fraction t of its power through glass
//                          or a medium
//   scatter(p, dir, depth) it scattered in a participating medium at p, travelling along dir
//                          (a volume photon, if at all); it goes on in a new direction
//   scale, carry(w)        splitting only: its share of its light, and a branch keeping `w`
// Each photon draws from its own random stream, so it takes the same path whoever traces it.
//
// Through a participating medium (scene/segment_medium.h) a photon scatters where free flight
// by the scattering coefficient says, and loses to absorption exactly exp(-sigma_a d) of its
// power on the way (no roulette: a beam through a clear absorbing slab arrives with exactly
// the Beer-Lambert share). A scattering event counts as a bounce towards max_depth, crossing a
// medium's surfaceless edge does not. In a medium that is not grey a photon still carrying
// the whole spectrum takes one wavelength first, as in absorbing glass, and the coefficients
// of its band apply.

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "cluster/dealt_parts.h"
#include "math/rng.h"
#include "optics/phase_function.h"
#include "render/density_tracking.h"
#include "render/photon_emission.h"
#include "render/render_control.h"
#include "scene/interaction.h"
#include "scene/scattering.h"
#include "scene/scene.h"
#include "scene/segment_medium.h"
#include "util/parallel_in_order.h"

namespace lenslab {

// Branches of an aimed photon weaker than this share of its power play Russian roulette
// (surviving at this share), so splitting stays bounded.
inline constexpr double kSplitFloor = 0.5;

// Photons per parallel task; the users keep each chunk's deposits apart and join them in
// chunk order, so the result does not depend on the threads.
inline constexpr int64_t kPhotonChunk = 4096;

inline int64_t photon_chunks(int64_t photons) {
    return (photons + kPhotonChunk - 1) / kPhotonChunk;
}

// Photons traced between two looks at the cancel flag inside a chunk: a chunk of slow photons
// (deep glass paths, 30 million of them) took seconds to notice Ctrl-C; an atomic load per
// 256 photons costs nothing next to tracing them.
inline constexpr int64_t kPhotonCancelCheck = 256;

// Calls `trace(i)` for photons [first, last) in order, stopping early once `control` is
// cancelled (looked at every kPhotonCancelCheck photons). Chunks stay as they are, so an
// uncancelled run traces the same photons in the same chunks.
template <class Trace>
void trace_photon_range(int64_t first, int64_t last, const RenderControl& control,
                        const Trace& trace) {
    for (int64_t i = first; i < last; ++i) {
        if ((i - first) % kPhotonCancelCheck == 0 && control.cancelled()) return;
        trace(i);
    }
}

// Calls `body(chunk, first, last)` for each chunk of photons [first, last) of `photons`, in
// parallel; chunks not begun when `control` is cancelled are skipped (the body stops within
// its chunk with trace_photon_range). In a job of several ranks, only the chunks dealt to
// this one (cluster/dealt_parts.h): the caller shares the deposits afterwards.
// Chunks are begun in order (util/parallel_in_order.h): the deposits of a chunk wait until
// every earlier one is in, so chunks far ahead would have to be held and copied late.
template <class Body>
void for_each_photon_chunk(int64_t photons, RenderControl& control, const Body& body) {
    const Communicator& comm = control.cluster();
    parallel_for_in_order(photon_chunks(photons), [&](int64_t chunk) {
        if (!dealt_to(chunk, comm) || control.cancelled()) return;
        const int64_t first = chunk * kPhotonChunk;
        body(chunk, first, std::min(photons, first + kPhotonChunk));
    });
}

// Joins the chunks' deposits in chunk order, in parallel, freeing them: the same result at any
// thread count. `offset[c]` is where chunk c's begin (and `offset.back()` the total).
template <class T>
std::vector<T> join_chunks(std::vector<std::vector<T>>& parts, std::vector<size_t>& offset) {
    offset.assign(parts.size() + 1, 0);
    for (size_t c = 0; c < parts.size(); ++c) offset[c + 1] = offset[c] + parts[c].size();
    std::vector<T> out(offset.back());
    tbb::parallel_for(size_t{0}, parts.size(), [&](size_t c) {
        std::copy(parts[c].begin(), parts[c].end(),
                  out.begin() + static_cast<ptrdiff_t>(offset[c]));
        std::vector<T>().swap(parts[c]);
    });
    return out;
}

template <class Policy>
class PhotonWalker {
public:
    PhotonWalker(const Scene& scene, const PhotonPlan& plan, int max_depth)
        : m_scene(scene), m_plan(plan), m_max_depth(max_depth) {}

    // Traces photon `index` of the plan with its own random stream; `make_policy(photon)`
    // gives the policy that carries it.
    template <class MakePolicy>
    void trace(int64_t index, uint64_t seed, const MakePolicy& make_policy) {
        // Random streams for photons are offset from the per-pixel camera streams.
        Rng rng(seed, (uint64_t{1} << 62) + static_cast<uint64_t>(index));
        const PhotonPlan::Photon photon = m_plan.start(m_scene, index, rng);
        if (photon.start.scale == 0.0) return;  // sampled where the light sends nothing
        m_photon = &photon;
        m_rng = &rng;
        Policy policy = make_policy(photon);
        // With media in shapes the first surface may be only a medium's edge: the stream's
        // part of the emission is decided by the first real surface along the emitted ray.
        m_counted = m_scene.has_media();
        if (m_counted && !counts(first_real_surface(photon.start.ray))) return;
        if constexpr (Policy::kSplitAimed) {
            if (photon.aimed) return split(policy, photon.start.ray);
        }
        roulette(policy, photon.start.ray);
    }

private:
    enum class Step { Lost, Surface, Scattered };

    // The next surface (Surface, `it` filled), a scattering event in a medium on the way
    // (Scattered, `ray` turned there), or Lost; the first surface along the emitted ray must
    // be in this stream's part of the light's emission (photon_emission.h).
    Step reach(Ray& ray, Policy& policy, int depth, Interaction& it) {
        const double nm = policy.lambda_nm > 0 ? policy.lambda_nm : kLineD;
        const bool hit = next_interaction(m_scene, ray, nm, it);
        if (depth == 0 && !m_counted && !counts(hit ? it.hit.object : -1)) return Step::Lost;
        if (const Medium* medium = segment_medium(m_scene, ray, hit ? &it : nullptr)) {
            if (cross_medium(*medium, ray, hit ? it.hit.surface.t : INFINITY, policy, depth))
                return Step::Scattered;
        }
        if (!hit) return Step::Lost;
        if (absorption_before(it, ray.direction)) {
            // Absorption depends on wavelength: a photon still carrying the whole spectrum
            // (emitted inside the glass) takes one first.
            if (policy.lambda_nm == 0) policy.disperse(*m_rng);
            policy.attenuate(segment_transmittance(it, ray.direction, policy.lambda_nm));
        }
        policy.arrive(it, ray.direction, depth);
        if (policy.lambda_nm == 0 && it.scattering.dispersive) {
            // From here the path depends on wavelength: take one.
            policy.disperse(*m_rng);
            it.scattering = scatter_at(it, it.direction, policy.lambda_nm);
        }
        policy.hit(it, ray.direction, depth);
        return Step::Surface;
    }

    // The object of the first surface along `ray` that is not a medium's surfaceless edge,
    // or -1.
    int first_real_surface(Ray ray) const {
        Interaction it;
        while (next_interaction(m_scene, ray, kLineD, it)) {
            if (!it.material->surfaceless) return it.hit.object;
            ray = {it.point(), ray.direction};
        }
        return -1;
    }

    bool counts(int first_object) const {
        if (first_object >= 0)
            return m_plan.counts(m_scene, m_photon->light, m_photon->aimed, first_object);
        return !m_photon->aimed;  // nothing hit: only the emitted stream sends photons there
    }

    // Free flight along `ray` through `medium` up to the surface at `t_max`: true when the
    // photon scattered on the way (the policy saw it, `ray` leaves from there), false when it
    // reached the surface, dimmed by absorption.
    bool cross_medium(const Medium& medium, Ray& ray, double t_max, Policy& policy, int depth) {
        if (policy.lambda_nm == 0 && !medium.is_grey()) policy.disperse(*m_rng);
        const int band = policy.lambda_nm > 0 ? band_of(policy.lambda_nm) : 0;
        const double sigma_s = medium.scattering[band], sigma_a = medium.absorption[band];
        if (medium.is_heterogeneous())
            return cross_heterogeneous(medium, sigma_s, sigma_a, ray, t_max, policy, depth);
        const double t = sigma_s > 0 ? -std::log1p(-m_rng->uniform()) / sigma_s : INFINITY;
        if (!(t < t_max)) {
            if (sigma_a > 0) policy.attenuate(std::exp(-sigma_a * t_max));
            return false;
        }
        if (sigma_a > 0) policy.attenuate(std::exp(-sigma_a * t));
        scatter(medium, ray, t, policy, depth);
        return true;
    }

    // As in a homogeneous medium, scattering and absorption apart: the photon scatters at
    // the first real collision of sigma_s f(x) (delta tracking), and absorption on the way
    // dims it by ratio tracking's unbiased estimate of exp(-sigma_a \int f).
    bool cross_heterogeneous(const Medium& medium, double sigma_s, double sigma_a, Ray& ray,
                             double t_max, Policy& policy, int depth) {
        const double t =
            sigma_s > 0 ? delta_track(*medium.density, sigma_s, ray, t_max, *m_rng) : INFINITY;
        const bool scattered = t < t_max;
        if (sigma_a > 0) {
            policy.attenuate(
                ratio_track(*medium.density, sigma_a, ray, scattered ? t : t_max, *m_rng));
        }
        if (!scattered) return false;
        scatter(medium, ray, t, policy, depth);
        return true;
    }

    // The photon scatters `t` along `ray`: the policy sees it, and `ray` leaves from there.
    void scatter(const Medium& medium, Ray& ray, double t, Policy& policy, int depth) {
        const Vec3 p = ray.at(t);
        policy.scatter(p, ray.direction, depth);
        const HenyeyGreenstein phase(medium.g);
        const double u1 = m_rng->uniform(), u2 = m_rng->uniform();
        ray = {p, phase.sample(ray.direction, u1, u2)};
    }

    // Russian roulette picks one event per surface: the diffuse one with the policy's
    // probability, a specular branch with its weight (its power unchanged), or absorption.
    void roulette(Policy& policy, Ray ray) {
        for (int depth = 0; depth <= m_max_depth; ++depth) {
            Interaction it;
            const Step step = reach(ray, policy, depth, it);
            if (step == Step::Lost) return;
            if (step == Step::Scattered) continue;
            if (it.material->surfaceless) {  // a medium's edge: no event, no bounce
                ray = {it.point(), ray.direction};
                --depth;
                continue;
            }
            const double p = policy.diffuse_probability(it);
            const EventPick event = pick_event(it.scattering, p, m_rng->uniform());
            if (event.diffuse) {
                if (!policy.diffuse(it, ray, p, depth, *m_rng)) return;
                continue;
            }
            if (!event.branch) return;  // absorbed (or the diffuse share of a black surface)
            ray = {it.point(), event.branch->direction};
        }
    }

    // Every event at once: the policy's hit sees the diffuse share and each specular branch
    // goes on with its weight. Branches wait on a list, not the call stack: a mirror
    // corridor is a thousand deep.
    void split(const Policy& policy, const Ray& ray) {
        m_pending.clear();
        m_pending.push_back({policy, ray, 0});
        while (!m_pending.empty()) {
            Pending p = m_pending.back();
            m_pending.pop_back();
            Interaction it;
            if (p.depth > m_max_depth) continue;
            const Step step = reach(p.ray, p.policy, p.depth, it);
            if (step == Step::Lost) continue;
            if (step == Step::Scattered) {
                m_pending.push_back({p.policy, p.ray, p.depth + 1});
                continue;
            }
            if (it.material->surfaceless) {
                m_pending.push_back({p.policy, {it.point(), p.ray.direction}, p.depth});
                continue;
            }
            const Scattering& s = it.scattering;
            for (int i = 0; i < s.count; ++i) {
                double w = s.branches[i].weight;
                const double share = w * p.policy.scale / m_photon->start.scale;
                if (share < kSplitFloor) {
                    // Survives with probability share / floor, carrying the floor.
                    if (m_rng->uniform() * kSplitFloor >= share) continue;
                    w *= kSplitFloor / share;
                }
                Policy branch = p.policy;
                branch.carry(w);
                m_pending.push_back({branch, {it.point(), s.branches[i].direction}, p.depth + 1});
            }
        }
    }

    struct Pending {
        Policy policy;
        Ray ray;
        int depth;
    };

    const Scene& m_scene;
    const PhotonPlan& m_plan;
    int m_max_depth;
    const PhotonPlan::Photon* m_photon = nullptr;  // the one being traced
    bool m_counted = false;                        // its stream's part was checked at the start
    Rng* m_rng = nullptr;                          // its stream
    std::vector<Pending> m_pending;
};

}  // namespace lenslab
