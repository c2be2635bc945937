// ObjectBvh: the 8-wide BVH over a scene's bounded objects other than plain triangles (spheres,
// boxes, cones, transformed triangles, mesh instances). Built like the triangle BVH (binned SAH,
// binned_sah.h, collapsed to 8-wide nodes, wide_collapse.h) and walked by the same 8-wide box test
// (wide_traverse.h). Leaves are blocks of four object slots; each slot may carry a bounding sphere
// (the sphere itself for spheres), which a 4-wide single-precision test uses to reject the slots
// the ray cannot hit before the caller's exact double-precision test runs. The reject test is
// conservative (margins far above its rounding error), so results are those of the exact tests.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rays/accel/huge_pages.h"
#include "rays/accel/triangle_bvh_layout.h"

namespace rays {

namespace objbvh {

/// Four object slots, SoA. radius: the slot's bounding sphere, +inf when it has none (only the
/// box in the parent node culls it), NaN for an unused slot (never tested).
struct alignas(16) ShapeBlock {
    float cx[tribvh::kBlockSize], cy[tribvh::kBlockSize], cz[tribvh::kBlockSize];
    float radius[tribvh::kBlockSize];
    float margin[tribvh::kBlockSize];  ///< rounding margin of the reject test (0 when radius is +inf)
    uint32_t id[tribvh::kBlockSize];   ///< the caller's object index
};
static_assert(sizeof(ShapeBlock) == 96);

}  // namespace objbvh

class ObjectBvh {
public:
    /// A bounded object: its world box (double) and, when sphereRadius >= 0, a bounding sphere.
    struct Prim {
        double lo[3], hi[3];
        double center[3];
        double sphereRadius = -1;
        bool isSphere = false;  ///< the object is exactly that sphere (world space)
        uint32_t id = 0;
    };
    /// A slot's sphere in double precision when the object is a world-space sphere (radius < 0
    /// otherwise): the caller's exact test can use it without touching the object itself.
    struct ExactSphere {
        double centre[3];
        double radius;
    };
    /// The prim's sphere when it is a world-space sphere, else radius -1.
    static ExactSphere exactSphere(const Prim& p) {
        return p.isSphere ? ExactSphere{{p.center[0], p.center[1], p.center[2]}, p.sphereRadius}
                          : ExactSphere{{0, 0, 0}, -1};
    }

    /// Builds over prims (boxes must be non-empty and finite). Replaces any previous content.
    void build(const std::vector<Prim>& prims);
    bool empty() const { return nodes_.empty(); }
    size_t nodeCount() const { return nodes_.size(); }
    size_t blockCount() const { return blocks_.size(); }
    /// Wide levels (root = 1), 0 when empty.
    int depth() const;

    /// Walks the leaves the ray (float origin and direction, need not be unit length) may hit with
    /// t in [tMin, tHit] and calls exact(id, sphere, tHit) for each object slot its sphere test
    /// cannot reject (sphere: the slot's ExactSphere). AnyHit: exact returns true when the object blocks the ray, and so does the walk.
    /// Closest hit: exact lowers tHit (a float upper bound of the best hit so far) when it finds a
    /// closer hit. Defined in object_bvh_traverse.h.
    template <bool AnyHit, class Exact>
    bool traverse(const float org[3], const float dir[3], float tMin, float tHit, Exact&& exact) const;

private:
    std::vector<tribvh::WideNode, tribvh::HugePageAllocator<tribvh::WideNode>> nodes_;
    std::vector<objbvh::ShapeBlock> blocks_;
    std::vector<ExactSphere> spheres_;  ///< per slot (block * 4 + lane)
    bool anySphere_ = false;            ///< some slot has a bounding sphere (finite radius)
};

}  // namespace rays
