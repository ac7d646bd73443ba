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

// The same with the base a constant, several digits at a time: each block of k digits (Base^k
// at most 1024) is mirrored by a table, the mirrored blocks are gathered into one integer,
// and the result is that integer over Base^(digits), one rounding in all. An aimed photon
// needs about fifty digits over its six coordinates; one at a time they were 4% of the
// report scene's render.
template <uint64_t Base>
struct MirroredBlocks {
    static constexpr int digits = [] {
        int k = 0;
        for (uint64_t b = Base; b <= 1024; b *= Base) ++k;
        return k;
    }();
    static constexpr uint64_t size = [] {
        uint64_t n = 1;
        for (int i = 0; i < digits; ++i) n *= Base;
        return n;
    }();
    // Block value -> the same digits in the opposite order.
    static constexpr std::array<uint16_t, size> mirrored = [] {
        std::array<uint16_t, size> out{};
        for (uint64_t v = 0; v < size; ++v) {
            uint64_t m = 0, rest = v;
            for (int i = 0; i < digits; ++i) {
                m = m * Base + rest % Base;
                rest /= Base;
            }
            out[v] = static_cast<uint16_t>(m);
        }
        return out;
    }();
};

template <uint64_t Base>
double radical_inverse_in_base(uint64_t index) {
    using Blocks = MirroredBlocks<Base>;
    // Exact while the denominator stays within a double's 53 bits (indices below about 2^45).
    constexpr uint64_t kExact = uint64_t{1} << 53;
    uint64_t mirrored = 0, denominator = 1;
    for (uint64_t rest = index; rest > 0;) {
        if (denominator > kExact / Blocks::size) return radical_inverse_of(Base, index);
        const uint64_t next = rest / Blocks::size;
        mirrored = mirrored * Blocks::size + Blocks::mirrored[rest - next * Blocks::size];
        denominator *= Blocks::size;
        rest = next;
    }
    return static_cast<double>(mirrored) / static_cast<double>(denominator);
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
