#include "accel/hash_grid.h"

#include <algorithm>
#include <bit>

namespace lenslab {

HashGrid::HashGrid(size_t count, const std::function<Vec3(size_t)>& position, double cell) {
    if (count == 0) return;
    Aabb bounds;
    std::vector<Vec3> points(count);
    for (size_t i = 0; i < count; ++i) {
        points[i] = position(i);
        bounds.expand(points[i]);
    }
    const Vec3 extent = bounds.extent();
    const double widest = std::max(extent.x, std::max(extent.y, extent.z));
    m_origin = bounds.lo;
    m_cell = std::max(cell, widest / (kCellsPerAxis - 2));
    if (!(m_cell > 0)) m_cell = 1;  // all points at one place
    // About two buckets per point keeps most buckets to one cell.
    const uint64_t buckets = std::bit_ceil(std::max<uint64_t>(2 * count, 16));
    m_mask = buckets - 1;

    std::vector<uint32_t> bucket_of(count);
    std::vector<uint64_t> key_of(count);
    m_starts.assign(buckets + 1, 0);
    for (size_t i = 0; i < count; ++i) {
        const int x = coordinate(points[i].x, 0), y = coordinate(points[i].y, 1),
                  z = coordinate(points[i].z, 2);
        key_of[i] = pack(x, y, z);
        bucket_of[i] = bucket(x, y, z);
        ++m_starts[bucket_of[i] + 1];
    }
    for (uint64_t b = 0; b < buckets; ++b) m_starts[b + 1] += m_starts[b];
    std::vector<uint32_t> fill(m_starts.begin(), m_starts.end() - 1);
    m_cells.resize(count);
    m_items.resize(count);
    for (size_t i = 0; i < count; ++i) {
        const uint32_t slot = fill[bucket_of[i]]++;
        m_cells[slot] = key_of[i];
        m_items[slot] = static_cast<uint32_t>(i);
    }
}

}  // namespace lenslab
