#pragma once
// A photon as stored in a photon map: 32 bytes (docs/performance.md: the budget is 32).
// Position and power in float: bulk storage stays compact; what is computed with them is double.

#include <cmath>
#include <cstdint>

#include "math/vec3.h"
#include "optics/rgb.h"

namespace lenslab {

// Which map a photon belongs to, by the path that brought it (Jensen 2001, section 7.5):
// direct: light -> diffuse (L D); caustic: light -> one or more specular -> diffuse (L S+ D).
enum class PhotonKind : uint8_t { None = 0, Direct = 1, Caustic = 2 };

// Octahedral encoding of unit vectors into 2 x 16 bits (Cigolle et al. 2014, "A Survey of
// Efficient Representations for Independent Unit Vectors"): error below 1e-4 rad.
inline void encode_octahedral(const Vec3& v, uint16_t out[2]) {
    const double l1 = std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
    double x = v.x / l1, y = v.y / l1;
    if (v.z < 0) {
        const double ox = (1.0 - std::abs(y)) * (x >= 0 ? 1.0 : -1.0);
        const double oy = (1.0 - std::abs(x)) * (y >= 0 ? 1.0 : -1.0);
        x = ox;
        y = oy;
    }
    auto quantise = [](double a) {
        return static_cast<uint16_t>(std::lround((std::clamp(a, -1.0, 1.0) * 0.5 + 0.5) * 65535.0));
    };
    out[0] = quantise(x);
    out[1] = quantise(y);
}

// The decoded direction before normalisation: the same direction, length between 1/sqrt(3)
// and 1, enough where only a sign is wanted (which side a photon came from).
inline Vec3 decode_octahedral_unnormalised(const uint16_t in[2]) {
    // A multiplication, not a division: the query's side test decodes every photon it keeps.
    constexpr double kScale = 2.0 / 65535.0;
    double x = in[0] * kScale - 1.0, y = in[1] * kScale - 1.0;
    const double z = 1.0 - std::abs(x) - std::abs(y);
    if (z < 0) {
        const double ox = (1.0 - std::abs(y)) * (x >= 0 ? 1.0 : -1.0);
        const double oy = (1.0 - std::abs(x)) * (y >= 0 ? 1.0 : -1.0);
        x = ox;
        y = oy;
    }
    return {x, y, z};
}

inline Vec3 decode_octahedral(const uint16_t in[2]) {
    return normalize(decode_octahedral_unnormalised(in));
}

struct Photon {
    float position[3];
    float power[3];       // flux carried, W per RGB channel
    uint16_t towards[2];  // unit direction back towards where the photon came from (octahedral)
    PhotonKind kind;
    uint8_t unused[3];

    Vec3 pos() const { return {position[0], position[1], position[2]}; }
    Rgb flux() const { return {power[0], power[1], power[2]}; }
    Vec3 incoming() const { return decode_octahedral(towards); }
    // Whether the photon arrived from the side `n` points to (no square root: a sign only).
    bool arrived_from_side(const Vec3& n) const {
        return dot(decode_octahedral_unnormalised(towards), n) > 0.0;
    }
};

static_assert(sizeof(Photon) == 32, "a stored photon must take at most 32 bytes");

}  // namespace lenslab
