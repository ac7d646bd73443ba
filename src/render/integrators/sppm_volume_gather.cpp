// sppm's gather in media (sppm.h): each camera segment through a medium collects the volume
// photons whose discs it crosses (the beam radiance estimate), and the volume radius shrinks.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <optional>

#include "accel/photon.h"
#include "accel/point_bvh.h"
#include "cluster/dealt_parts.h"
#include "math/rng.h"
#include "optics/phase_function.h"
#include "render/density_tracking.h"
#include "render/integrators/sppm_photon_colours.h"
#include "render/volume_photon_radii.h"

namespace lenslab {

namespace {

// A volume photon's radius: this many pixel footprints at its distance from the camera, at
// most the volume radius. A fixed radius in the scene would make a photon near the camera a
// disc across half the image.
constexpr double kVolumeFootprints = 3.0;

}  // namespace

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
            for (int k = 0; k < sppm::kMaxSegments; ++k) {
                const MediumSegment& seg = m_segments[i * sppm::kMaxSegments + size_t(k)];
                if (!(seg.beta > 0.0)) break;
                const HenyeyGreenstein phase(seg.medium->g);
                const int band = seg.dispersed ? band_of(pass.lambda_nm) : 0;
                const double sigma_t = seg.medium->extinction()[size_t(band)];
                // A heterogeneous medium's T(t): one ratio-tracking walk along the segment,
                // unbiased at every t (density_tracking.h), in its own random stream.
                std::optional<TransmittanceWalk> walk;
                if (seg.medium->is_heterogeneous()) {
                    Rng rng(pass.seed, sppm::kGatherStreams + i * sppm::kMaxSegments + size_t(k));
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

}  // namespace lenslab
