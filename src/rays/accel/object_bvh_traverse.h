// ObjectBvh::traverse: the 8-wide walk of wide_traverse.h with a 4-wide bounding-sphere reject
// test in the leaves. Included by the code that supplies the exact per-object tests (bvh.cpp).
//
// The reject test, per slot with centre c and radius R, for the ray o + t d:
//   s = ((c - o) . d) / (d . d)      parameter of the point of the ray line nearest to c
//   q = (c - o) - s d                offset of c from the line; |q| <= R where the ray meets the sphere
//   the sphere spans at most t in [s - R / |d|, s + R / |d|]
// computed in single precision with R widened by a margin of 2^-12 (|c|_1 + |o|_1 + R). Every
// rounding error of these steps (inputs rounded from double, products, sums) is a few ulps of
// |c| + |o| + R, that is about 2^-22 of it, so the margin is some hundreds of times larger and no
// ray that meets the sphere is rejected. Rays whose numbers could overflow the test (direction
// lengths outside [1e-10, 1e10], origins beyond 1e15) skip it, as do slots without a sphere.
#pragma once

#include <cmath>

#include "rays/accel/object_bvh.h"
#include "rays/accel/simd.h"
#include "rays/accel/wide_traverse.h"

namespace rays {

template <bool AnyHit, class Exact>
bool ObjectBvh::traverse(const float org[3], const float dir[3], float tMin, float tHit, Exact&& exact) const {
    using namespace tribvh;
    if (nodes_.empty() || !(tHit > tMin)) return false;
    if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f) return false;
    const BoxRay br(org, dir);

    // The reject test's per-ray constants, only when some slot has a sphere (a scene of boxes
    // would pay a square root and two divisions per ray for nothing).
    struct Filter {
        bool on = false;
        VFloat4 ox, oy, oz, dx, dy, dz, invDd, invLen, originMargin;
    } f;
    if (anySphere_) {
        const float dd = dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2];
        const float originSize = std::fabs(org[0]) + std::fabs(org[1]) + std::fabs(org[2]);
        f.on = dd >= 1e-20f && dd <= 1e20f && originSize < 1e15f;
        f.ox = VFloat4::broadcast(org[0]);
        f.oy = VFloat4::broadcast(org[1]);
        f.oz = VFloat4::broadcast(org[2]);
        f.dx = VFloat4::broadcast(dir[0]);
        f.dy = VFloat4::broadcast(dir[1]);
        f.dz = VFloat4::broadcast(dir[2]);
        f.invDd = VFloat4::broadcast(1.0f / dd);
        f.invLen = VFloat4::broadcast(1.0f / std::sqrt(dd));
        f.originMargin = VFloat4::broadcast(0x1p-12f * originSize);
    }
    const VFloat4 vtMin = VFloat4::broadcast(tMin);
    const objbvh::ShapeBlock* blocks = blocks_.data();
    const ExactSphere* spheres = spheres_.data();

    // Slots of block b that the ray may hit within [tMin, tBest].
    auto candidates = [&](const objbvh::ShapeBlock& b, float tBest) -> uint32_t {
        const VFloat4 radius = VFloat4::load(b.radius);
        if (!f.on) return bits(cmpLe(radius, radius));  // every used slot (NaN marks unused)
        const VFloat4 ocx = VFloat4::load(b.cx) - f.ox, ocy = VFloat4::load(b.cy) - f.oy;
        const VFloat4 ocz = VFloat4::load(b.cz) - f.oz;
        const VFloat4 s = fmadd(ocx, f.dx, fmadd(ocy, f.dy, ocz * f.dz)) * f.invDd;
        const VFloat4 qx = fnmadd(s, f.dx, ocx), qy = fnmadd(s, f.dy, ocy), qz = fnmadd(s, f.dz, ocz);
        const VFloat4 dist2 = fmadd(qx, qx, fmadd(qy, qy, qz * qz));
        const VFloat4 reach = radius + VFloat4::load(b.margin) + f.originMargin;
        const VFloat4 span = reach * f.invLen;
        const VFloat4 inside = cmpLe(dist2, reach * reach) & cmpGe(s + span, vtMin) &
                               cmpLe(s - span, VFloat4::broadcast(tBest));
        return bits(inside);
    };
    auto prefetchLeaf = [&](uint32_t c) {
        const char* p = reinterpret_cast<const char*>(blocks + leafFirstBlock(c));
        __builtin_prefetch(p);
        __builtin_prefetch(p + 64);
    };
    auto leaf = [&](uint32_t ref, float& tBest) -> bool {
        const objbvh::ShapeBlock* b = blocks + leafFirstBlock(ref);
        const objbvh::ShapeBlock* end = b + leafBlockCount(ref);
        for (; b < end; ++b) {
            const ExactSphere* sphere = spheres + size_t(b - blocks) * kBlockSize;
            for (uint32_t m = candidates(*b, tBest); m; m &= m - 1) {
                const unsigned lane = lowestBit(m);
                if constexpr (AnyHit) {
                    if (exact(b->id[lane], sphere[lane], tBest)) return true;
                } else {
                    exact(b->id[lane], sphere[lane], tBest);
                }
            }
        }
        return false;
    };
    return traverseWide<AnyHit, !AnyHit>(nodes_.data(), br, tMin, tHit, prefetchLeaf, leaf);
}

}  // namespace rays
