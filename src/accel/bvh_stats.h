#pragma once
// The shape of a built BVH, for tests and diagnostics: how many primitives its fullest leaf
// holds (bounded by the build's leaf size, even for a pile of coincident triangles).

#include <cstddef>

#include "accel/bvh_build.h"

namespace lenslab {

struct BvhStats {
    size_t nodes = 0;
    size_t leaves = 0;
    int max_leaf_size = 0;  // the most primitives in one leaf
};

BvhStats bvh_stats(const BvhLayout& layout);

}  // namespace lenslab
