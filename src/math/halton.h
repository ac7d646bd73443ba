#pragma once
// The Halton sequence (radical inverses in the first primes), rotated by a random offset per
// dimension (Cranley-Patterson): points that fill the unit cube evenly, so photons drawn
// from consecutive indices spread over a caustic without the clumps and holes of
// independent random numbers (pbrt-v4 shoots its SPPM photons from Halton points too).

#include <array>
#include <cstdint>

namespace lenslab {

inline constexpr int kHaltonDimensions = 6;

// The radical inverse of `index` in `base`: its digits mirrored about the point.
inline double radical_inverse_of(uint64_t base, uint64_t index) {
    const double inv_base = 1.0 / static_cast<double>(base);
    double inv = inv_base, result = 0;
    while (index > 0) {
        result += static_cast<double>(index % base) * inv;
        index /= base;
        inv *= inv_base;
    }
    return result;
}

// The same with the base a constant, so that once inlined the digit divisions compile to
// multiplications (a 64-bit division by a run-time value costs tens of cycles, and an aimed
// photon needs about fifty of them).
template <uint64_t Base>
double radical_inverse_in_base(uint64_t index) {
    return radical_inverse_of(Base, index);
}

// The radical inverse of `index` in the `dimension`-th prime (2, 3, 5, 7, 11, 13).
inline double radical_inverse(int dimension, uint64_t index) {
    switch (dimension) {
        case 0:
            return radical_inverse_in_base<2>(index);
        case 1:
            return radical_inverse_in_base<3>(index);
        case 2:
            return radical_inverse_in_base<5>(index);
        case 3:
            return radical_inverse_in_base<7>(index);
        case 4:
            return radical_inverse_in_base<11>(index);
        default:
            return radical_inverse_in_base<13>(index);
    }
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
