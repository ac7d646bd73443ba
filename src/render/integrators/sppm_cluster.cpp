// The exchange between the ranks of a job (sppm.h, docs/cluster.md): each rank traces and
// gathers the image rows dealt to it; these share what every rank needs of the others'.

#include "cluster/dealt_parts.h"
#include "cluster/rank_order_sum.h"
#include "render/integrators/sppm_state.h"

namespace lenslab {

void SppmIntegrator::share_visible_points(Communicator& comm) {
    if (comm.alone()) return;
    // Per row: each pixel's radius, and whether its visible point is valid (1) and dispersed
    // (2), and its path crossed a medium (4). Every rank then picks the same grid cell and the same
    // share of dispersed photons.
    const size_t rows = static_cast<size_t>(m_height), width = static_cast<size_t>(m_width);
    std::vector<std::vector<double>> radius(rows);
    std::vector<std::vector<uint8_t>> flags(rows);
    for (size_t y = static_cast<size_t>(comm.rank()); y < rows; y += size_t(comm.size())) {
        for (size_t i = y * width; i < (y + 1) * width; ++i) {
            radius[y].push_back(m_pixels[i].radius);
            flags[y].push_back(uint8_t(m_points[i].valid) | uint8_t(m_points[i].dispersed << 1) |
                               uint8_t(m_points[i].in_medium << 2));
        }
    }
    share_dealt_parts(comm, radius);
    share_dealt_parts(comm, flags);
    for (size_t y = 0; y < rows; ++y) {
        if (dealt_to(static_cast<int64_t>(y), comm)) continue;
        for (size_t x = 0; x < width; ++x) {
            m_pixels[y * width + x].radius = radius[y][x];
            m_points[y * width + x].valid = flags[y][x] & 1;
            m_points[y * width + x].dispersed = flags[y][x] & 2;
            m_points[y * width + x].in_medium = flags[y][x] & 4;
        }
    }
}

std::vector<std::vector<SppmIntegrator::Pixel>> SppmIntegrator::pixel_rows_at_root() const {
    // Collective: every rank calls it (from develop).
    Communicator& comm = *m_cluster;
    std::vector<std::vector<Pixel>> rows(static_cast<size_t>(m_height));
    if (comm.alone()) return rows;
    for (int y = comm.rank(); y < m_height; y += comm.size()) {
        const auto row = m_pixels.begin() + static_cast<ptrdiff_t>(y) * m_width;
        rows[static_cast<size_t>(y)].assign(row, row + m_width);
    }
    gather_dealt_parts_to_root(comm, rows);
    return rows;
}

double SppmIntegrator::mean_radius() const {
    Communicator& comm = *m_cluster;
    double sum[2] = {0, 0};  // of the radii, and their count
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        if (m_pixels[i].radius > 0 && dealt_to(static_cast<int64_t>(i) / m_width, comm)) {
            sum[0] += m_pixels[i].radius;
            sum[1] += 1;
        }
    }
    sum_in_rank_order(comm, sum);
    return sum[1] > 0 ? sum[0] / sum[1] : 0.0;
}

}  // namespace lenslab
