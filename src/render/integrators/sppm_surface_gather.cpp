// sppm's gather on surfaces (sppm.h): for every pixel, the photons within its radius on the
// same side of the same surface (a hash grid), and the pixel's statistics updated.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "accel/hash_grid.h"
#include "accel/photon.h"
#include "cluster/dealt_parts.h"
#include "math/constants.h"
#include "render/integrators/sppm_photon_colours.h"

namespace lenslab {

namespace {

// A photon counts at a visible point only if their surfaces face the same way: the photon
// arrived on the side the camera sees (no light through thin objects) and on a surface
// turned less than 60 degrees from the point's (not the wall round a corner).
constexpr double kSameSurfaceCos = 0.5;

}  // namespace

size_t SppmIntegrator::gather_surface(const PhotonPass& photons, const PhotonColours& colours) {
    const Communicator& comm = *m_cluster;
    std::vector<double> radii;
    radii.reserve(m_points.size());
    for (size_t i = 0; i < m_points.size(); ++i)
        if (m_points[i].valid) radii.push_back(m_pixels[i].radius);
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
    const double alpha = m_scene.render.alpha;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, m_pixels.size(), 256),
                      [&](const tbb::blocked_range<size_t>& range) {
                          for (size_t i = range.begin(); i != range.end(); ++i) {
                              if (!dealt_to(static_cast<int64_t>(i) / m_width, comm)) continue;
                              const VisiblePoint& vp = m_points[i];
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

    return hits.size();
}

}  // namespace lenslab
