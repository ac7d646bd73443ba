// sppm's first step (sppm.h): one camera path per pixel to its visible point, the light found
// on the way, and the path's segments through media for the volume gather.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "cluster/dealt_parts.h"
#include "math/constants.h"
#include "math/rng.h"
#include "optics/glass.h"
#include "render/density_tracking.h"
#include "render/direct_light.h"
#include "render/integrators/sppm_state.h"
#include "render/medium_transport.h"
#include "render/path_colour.h"
#include "scene/interaction.h"
#include "scene/segment_medium.h"

namespace lenslab {

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
    if (segments) std::fill(segments, segments + sppm::kMaxSegments, MediumSegment{});
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
            if (segment_count < sppm::kMaxSegments)
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

bool SppmIntegrator::trace_camera_paths(const PassState& pass, RenderControl& control) {
    const Communicator& comm = control.cluster();
    const RenderSettings& r = m_scene.render;
    std::vector<VisiblePoint>& points = m_points;
    points.resize(m_pixels.size());
    tbb::parallel_for(
        tbb::blocked_range<int>(0, m_height, 1), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y != rows.end(); ++y) {
                if (!dealt_to(y, comm)) continue;
                if (control.cancelled()) return;
                for (int x = 0; x < m_width; ++x) {
                    const size_t i = size_t(y) * m_width + x;
                    trace_camera_path(
                        x, y, pass, points[i],
                        m_segments.empty() ? nullptr : &m_segments[i * sppm::kMaxSegments]);
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
    return true;
}

}  // namespace lenslab
