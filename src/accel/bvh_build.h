#pragma once
// The part of a bounding volume hierarchy that does not depend on what it holds: a binned
// SAH build over boxes (Wald 2007, "On fast Construction of SAH-based Bounding Volume
// Hierarchies") and a stack traversal visiting the nearer child first. The scene's BVH
// (`Bvh`, one Shape per object) and a triangle mesh's own BVH share it; each supplies its
// primitive test as a callback.

#include <cstdint>
#include <vector>

#include "math/aabb.h"

namespace lenslab {

struct BvhNode {
    Aabb box;
    int32_t first = 0;  // leaf: first index into BvhLayout::order; inner: index of the right child
    int32_t count = 0;  // leaf: number of primitives; inner: 0 (the left child is this + 1)
    int32_t axis = 0;   // inner: the split axis
};

struct BvhLayout {
    std::vector<BvhNode> nodes;  // depth-first; nodes[0] is the root (empty for no primitives)
    std::vector<int> order;      // primitive indices, leaf ranges contiguous
};

// Builds over primitives with the given bounds; leaves hold at most `max_leaf_size` of them,
// coincident centres too (split by index); accel/bvh_stats.h measures the result.
BvhLayout build_bvh(const std::vector<Aabb>& boxes, int max_leaf_size);

// How many times build_bvh has run in this process (scene and mesh BVHs alike), so tests can
// check that an edit rebuilds only what it must (a camera move: nothing).
uint64_t bvh_build_count();

// Deepest tree build_bvh makes is kMaxSahDepth + log2(n) + 1: far below the stack size.
inline constexpr int kBvhStackSize = 128;

// Visits the leaves whose boxes the ray crosses within (t_min, t_max), nearer child first.
// `leaf(first, count, t_max)` tests order[first .. first + count) and returns true when it
// found a hit, after lowering t_max to it (it takes t_max by reference). With `any_hit` the
// walk stops at the first leaf that reports a hit. Returns whether any leaf reported one.
template <typename LeafFn>
bool traverse_bvh(const std::vector<BvhNode>& nodes, const Ray& ray, double t_min, double t_max,
                  bool any_hit, LeafFn&& leaf) {
    if (nodes.empty()) return false;
    const Vec3 inv{1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z};
    int stack[kBvhStackSize];
    int top = 0;
    stack[top++] = 0;
    bool found = false;
    while (top > 0) {
        const int index = stack[--top];
        const BvhNode& node = nodes[index];
        if (!node.box.hit(ray, inv, t_min, t_max)) continue;
        if (node.count > 0) {
            if (leaf(node.first, node.count, t_max)) {
                found = true;
                if (any_hit) return true;
            }
            continue;
        }
        // The left child holds the lower coordinates along the split axis. Push the farther
        // child first so the nearer one is visited first and shrinks t_max.
        const int left = index + 1;
        const int right = node.first;
        if (ray.direction[node.axis] < 0) {
            stack[top++] = left;
            stack[top++] = right;
        } else {
            stack[top++] = right;
            stack[top++] = left;
        }
    }
    return found;
}

}  // namespace lenslab
