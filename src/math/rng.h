#pragma once
// Deterministic random numbers: one PCG32 stream per pixel or photon index, so a render
// is identical for a given seed whatever the thread count.

#include <cstdint>
#include <pcg_random.hpp>

namespace lenslab {

class Rng {
public:
    // `seed` is the user's seed; `stream` separates pixels / photons (any 64-bit value).
    Rng(uint64_t seed, uint64_t stream) : m_gen(seed, stream) {}

    // Uniform in [0, 1), never 1: 53 random bits would need two draws; 32 suffice for sampling.
    double uniform() { return static_cast<double>(m_gen()) * 0x1p-32; }

private:
    pcg32 m_gen;
};

}  // namespace lenslab
