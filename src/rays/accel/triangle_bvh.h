// TriangleBvh: a standalone triangle-mesh acceleration structure for single rays.
//
// Build: binned SAH over triangle boxes into a binary BVH (multi-threaded, result independent of
// the thread count; binned_sah.h), collapsed into 8-wide nodes whose child boxes are stored SoA
// so that one AVX2 instruction tests eight boxes; leaves hold up to four triangles stored SoA for
// a 4-wide intersection test (triangle_bvh_layout.h).
//
// Traversal: closest hit with near-first ordering (hit children sorted by entry distance, a
// stack of (node, distance) entries culled against the current hit, pushed children
// prefetched), and an unordered any-hit variant for shadow rays that stops at the first blocker.
//
// Robustness: the triangle test is the watertight test of Woop, Benthin and Wald (JCGT 2013) in
// single precision: vertices are translated to the ray origin and sheared so that the ray runs
// along +z, then the three 2D edge functions are evaluated with separately rounded products.
// A shared vertex is transformed identically in every triangle, an edge shared by two triangles
// is evaluated from the same transformed vertices with the operands swapped, which yields exactly
// the negated value, and rounding a difference of two products is monotonic, so every computed
// edge sign is either the exact sign for the transformed vertices or zero. Zero counts as inside,
// so where a ray crosses a closed mesh through a shared edge or vertex it hits at least one of
// the adjacent triangles (possibly two, at the same t); no double-precision fallback is needed.
// The box test widens every slab by a few ulps (relative to t, plus |origin * (1 / direction)|
// ulps absolute) so that rounding cannot cull a box the ray touches; direction components below
// 1e-30 are treated as +-1e-30 there. Triangles whose area is exactly zero (computed in double)
// or with non-finite vertices are left out at build time and are never hit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rays/accel/huge_pages.h"
#include "rays/accel/triangle_bvh_layout.h"

namespace rays {

struct TriRay {
    float org[3];
    float dir[3];  ///< need not be unit length; t is measured in units of dir
};

struct TriHit {
    uint32_t prim = UINT32_MAX;  ///< index of the triangle hit (UINT32_MAX: none)
    float t = 0.0f;
    float u = 0.0f, v = 0.0f;  ///< barycentric weights of the triangle's vertices 1 and 2
};

class TriangleBvh {
public:
    /// Builds over triangles given by vertex positions (xyz floats) and 3 indices per triangle.
    /// threads: 0 = all cores. Degenerate triangles are accepted (never hit). Indices must be
    /// < vertexCount. Replaces any previous content.
    void build(const float* positions, size_t vertexCount, const uint32_t* indices, size_t triangleCount,
               int threads = 0);
    /// Nearest hit with t in (tMin, tMax); returns false when none. Thread-safe (const).
    bool intersect(const TriRay& ray, float tMin, float tMax, TriHit& hit) const;
    /// Any hit with t in (tMin, tMax) (shadow rays: stops at the first blocker).
    bool occluded(const TriRay& ray, float tMin, float tMax) const;

    /// Reduced traversals, for benchmarks that measure what each technique buys (same hits as
    /// the default up to ties; slower): without near-first ordering, and/or with the four
    /// triangles of a leaf block tested one at a time in scalar code.
    enum class TraversalVariant { Default, Unordered, ScalarLeaves, ScalarLeavesUnordered };
    bool intersect(const TriRay& ray, float tMin, float tMax, TriHit& hit, TraversalVariant variant) const;
    bool occluded(const TriRay& ray, float tMin, float tMax, TraversalVariant variant) const;
    /// BVH + triangle data it owns.
    size_t memoryBytes() const;
    bool empty() const { return nodes_.empty(); }
    /// World bounds of the triangles that can be hit (lo > hi when empty).
    void bounds(float lo[3], float hi[3]) const;

    struct Stats {
        size_t nodes = 0;      ///< wide nodes
        size_t leaves = 0;     ///< leaf references
        size_t blocks = 0;     ///< 4-triangle blocks
        size_t triangles = 0;  ///< triangles stored (non-degenerate input triangles)
        int depth = 0;         ///< wide levels (root = 1)
        double sahCost = 0;    ///< SAH of the wide tree (node visits + block tests, per root area)
    };
    Stats stats() const;

private:
    template <bool AnyHit, bool Ordered, bool SimdLeaves>
    bool traverse(const TriRay& ray, float tMin, float tMax, TriHit* hit) const;

    std::vector<tribvh::WideNode, tribvh::HugePageAllocator<tribvh::WideNode>> nodes_;  ///< [0]: root
    std::vector<tribvh::TriBlock, tribvh::HugePageAllocator<tribvh::TriBlock>> blocks_;
    size_t triangles_ = 0;
    float lo_[3] = {1, 1, 1}, hi_[3] = {-1, -1, -1};
};

}  // namespace rays
