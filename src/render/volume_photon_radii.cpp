#include "render/volume_photon_radii.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace lenslab {

namespace {

constexpr int kLevels = 5;             // cells of radius/4, /2, 1, 2, 4 across
constexpr double kFinestShare = 0.25;  // the finest cell's side, in volume radii
constexpr double kCellToRadius = 0.6;  // a cell of side s holding k photons: radius ~0.6 s

uint64_t cell_key(const Vec3& p, double side) {
    // 21 bits a coordinate: cells 2^21 apart share a key, which only merges their counts.
    // Clamped first: a far point over a tiny cell must not overflow the integer.
    const auto c = [side](double v) {
        const double cell = std::clamp(std::floor(v / side), -1e18, 1e18);
        return static_cast<uint64_t>(static_cast<int64_t>(cell) & 0x1FFFFF);
    };
    return c(p.x) | (c(p.y) << 21) | (c(p.z) << 42);
}

}  // namespace

std::vector<double> volume_photon_radii(size_t count, const std::function<Vec3(size_t)>& position,
                                        const VolumeRadiusRule& rule) {
    std::vector<Vec3> points(count);
    for (size_t i = 0; i < count; ++i) points[i] = position(i);
    std::vector<double> radii(count);
    for (size_t i = 0; i < count; ++i)
        radii[i] = std::min(rule.radius, rule.footprint * length(points[i] - rule.eye));
    if (rule.neighbours <= 0) return radii;
    // Per photon, the finest level whose cell around it is crowded enough; kLevels: none.
    std::vector<int> level(count, kLevels);
    std::unordered_map<uint64_t, uint32_t> cells;
    for (int l = kLevels - 1; l >= 0; --l) {
        const double side = rule.radius * kFinestShare * double(1 << l);
        cells.clear();
        cells.reserve(count);
        for (const Vec3& p : points) ++cells[cell_key(p, side)];
        for (size_t i = 0; i < count; ++i) {
            if (cells[cell_key(points[i], side)] >= uint32_t(rule.neighbours)) level[i] = l;
        }
    }
    for (size_t i = 0; i < count; ++i) {
        const int l = std::min(level[i], kLevels - 1);  // none crowded: the coarsest
        const double sparse = kCellToRadius * rule.radius * kFinestShare * double(1 << l);
        radii[i] = std::max(radii[i], sparse);
    }
    return radii;
}

}  // namespace lenslab
