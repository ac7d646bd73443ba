#pragma once
// A uniform grid over points, stored as a hash table of its cells (Teschner et al. 2003,
// "Optimized Spatial Hashing for Collision Detection of Deformable Objects"): memory follows
// the points, not the volume, so a grid of cells the size of a gather radius fits any scene.
// sppm uses it to find the photons near each visible point.
//
// The points are sorted by bucket with a counting sort that keeps index order: slot s of the
// grid holds point item(s), and a query visits its slots in the same order on any thread
// count (sums over them are reproducible). Callers keep their data in slot order (reorder())
// so the points of one cell lie side by side in memory: the lookups are memory-bound.

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "math/aabb.h"

namespace lenslab {

class HashGrid {
public:
    HashGrid() = default;
    // `count` points, `position(i)` the i-th; `cell`: the cells' edge (> 0), enlarged when
    // the points span more than 2^21 cells along an axis.
    HashGrid(size_t count, const std::function<Vec3(size_t)>& position, double cell);

    double cell_size() const { return m_cell; }
    size_t size() const { return m_items.size(); }
    // The point held in slot `slot`.
    size_t item(size_t slot) const { return m_items[slot]; }
    // `data` (one value per point, in point order) rearranged into slot order.
    template <class T>
    std::vector<T> reorder(const std::vector<T>& data) const {
        std::vector<T> out(m_items.size());
        for (size_t s = 0; s < m_items.size(); ++s) out[s] = data[m_items[s]];
        return out;
    }

    // Calls f(slot) once for every slot whose point's cell overlaps the cube of half-edge
    // `radius` about `centre` (a superset of the points within `radius`: the caller tests
    // distance).
    template <class F>
    void for_each_near(const Vec3& centre, double radius, F&& f) const {
        if (m_items.empty()) return;
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = coordinate(centre[a] - radius, a);
            hi[a] = coordinate(centre[a] + radius, a);
        }
        for (int z = lo[2]; z <= hi[2]; ++z) {
            for (int y = lo[1]; y <= hi[1]; ++y) {
                for (int x = lo[0]; x <= hi[0]; ++x) {
                    const uint64_t key = pack(x, y, z);
                    const uint32_t b = bucket(x, y, z);
                    // Several cells can share a bucket: the key tells this cell's points apart.
                    for (uint32_t s = m_starts[b]; s < m_starts[b + 1]; ++s) {
                        if (m_cells[s] == key) f(static_cast<size_t>(s));
                    }
                }
            }
        }
    }

private:
    static constexpr int kCellsPerAxis = 1 << 21;

    int coordinate(double v, int axis) const {
        const double c = std::floor((v - m_origin[axis]) / m_cell);
        return c < 0 ? 0 : (c >= kCellsPerAxis - 1 ? kCellsPerAxis - 1 : static_cast<int>(c));
    }
    static uint64_t pack(int x, int y, int z) {
        return uint64_t(x) | (uint64_t(y) << 21) | (uint64_t(z) << 42);
    }
    uint32_t bucket(int x, int y, int z) const {
        // Teschner et al.'s primes.
        return static_cast<uint32_t>(
            (uint64_t(x) * 73856093u ^ uint64_t(y) * 19349663u ^ uint64_t(z) * 83492791u) & m_mask);
    }

    Vec3 m_origin;
    double m_cell = 1;
    uint64_t m_mask = 0;
    std::vector<uint32_t> m_starts;  // bucket b holds slots [m_starts[b], m_starts[b + 1])
    std::vector<uint64_t> m_cells;   // per slot: its point's cell
    std::vector<uint32_t> m_items;   // per slot: its point
};

}  // namespace lenslab
