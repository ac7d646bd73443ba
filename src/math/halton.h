#pragma once
// The Halton sequence (radical inverses in the first primes), rotated by a random offset per
// dimension (Cranley-Patterson): points that fill the unit cube evenly, so photons drawn
// from consecutive indices spread over a caustic without the clumps and holes of
// independent random numbers (pbrt-v4 shoots its SPPM photons from Halton points too).

#include <array>
#include <cstdint>

namespace lenslab {

inline constexpr int kHaltonDimensions = 5;

// The radical inverse of `index` in the `dimension`-th prime (2, 3, 5, 7, 11).
inline double radical_inverse(int dimension, uint64_t index) {
    constexpr uint64_t kPrimes[kHaltonDimensions] = {2, 3, 5, 7, 11};
    const uint64_t base = kPrimes[dimension];
    const double inv_base = 1.0 / static_cast<double>(base);
    double inv = inv_base, result = 0;
    while (index > 0) {
        result += static_cast<double>(index % base) * inv;
        index /= base;
        inv *= inv_base;
    }
    return result;
}

// Point `index` of the sequence, each coordinate shifted by `rotation` modulo 1.
inline std::array<double, kHaltonDimensions> halton_point(
    uint64_t index, const std::array<double, kHaltonDimensions>& rotation) {
    std::array<double, kHaltonDimensions> u{};
    for (int d = 0; d < kHaltonDimensions; ++d) {
        u[d] = radical_inverse(d, index) + rotation[d];
        if (u[d] >= 1.0) u[d] -= 1.0;
    }
    return u;
}

}  // namespace lenslab
