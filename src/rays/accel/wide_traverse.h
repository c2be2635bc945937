// Traversal of 8-wide BVH nodes (triangle_bvh_layout.h), shared by the triangle BVH and the object
// BVH: a conservative 8-wide slab test, near-first ordering for closest-hit queries (children hit
// sorted by entry distance, a stack of (node, distance) entries culled against the current hit,
// pushed children prefetched) and an unordered any-hit variant. What a leaf holds and how it is
// intersected is the caller's: a leaf callback receives the leaf reference.
#pragma once

#include <cmath>
#include <cstdint>

#include "rays/accel/simd.h"
#include "rays/accel/triangle_bvh_layout.h"

namespace rays::tribvh {

constexpr int kStackSize = 1024;  // >= 7 * maximum depth + 1 (the builder bounds the depth by ~90)

/// Per-ray constants of the box test: t = box * rd - od per axis, with the near planes lowered and
/// the far planes raised by a few ulps (relative) plus |org * rd| ulps (absolute), so rounding
/// never culls a box the ray touches. Direction components below 1e-30 count as +-1e-30.
struct BoxRay {
    VFloat8 rdNear[3], odNear[3], rdFar[3], odFar[3];
    uint32_t nearRow[3], farRow[3];

    BoxRay(const float org[3], const float dir[3]) {
        for (int a = 0; a < 3; ++a) {
            float d = dir[a];
            // Avoid infinities (0 * inf = NaN in the slab test): a tiny direction behaves the same.
            if (std::fabs(d) < 1e-30f) d = std::copysign(1e-30f, d);
            const float rd = 1.0f / d;
            const float od = org[a] * rd;
            const float slack = std::fabs(od) * 0x1p-20f;
            const float grow = 1.0f + 0x1p-20f;
            rdNear[a] = VFloat8::broadcast(rd);
            odNear[a] = VFloat8::broadcast(od + slack);
            rdFar[a] = VFloat8::broadcast(rd * grow);
            odFar[a] = VFloat8::broadcast(od * grow - slack);
            nearRow[a] = uint32_t(2 * a + (d < 0.0f ? 1 : 0));
            farRow[a] = nearRow[a] ^ 1u;
        }
    }
};

/// Bit i set when child i of n is entered within [tMin, tHit]; tn receives the entry distances.
RAYS_FORCEINLINE uint32_t childHits(const WideNode& n, const BoxRay& r, VFloat8 vtMin, VFloat8 vtHit, VFloat8& tn) {
    const float* box = n.box[0];
    const VFloat8 tnx = fmsub(VFloat8::load(box + 8 * r.nearRow[0]), r.rdNear[0], r.odNear[0]);
    const VFloat8 tny = fmsub(VFloat8::load(box + 8 * r.nearRow[1]), r.rdNear[1], r.odNear[1]);
    const VFloat8 tnz = fmsub(VFloat8::load(box + 8 * r.nearRow[2]), r.rdNear[2], r.odNear[2]);
    const VFloat8 tfx = fmsub(VFloat8::load(box + 8 * r.farRow[0]), r.rdFar[0], r.odFar[0]);
    const VFloat8 tfy = fmsub(VFloat8::load(box + 8 * r.farRow[1]), r.rdFar[1], r.odFar[1]);
    const VFloat8 tfz = fmsub(VFloat8::load(box + 8 * r.farRow[2]), r.rdFar[2], r.odFar[2]);
    tn = max(max(tnx, tny), max(tnz, vtMin));
    const VFloat8 tf = min(min(tfx, tfy), min(tfz, vtHit));
    return lessEqualBits(tn, tf);
}

/// Walks the tree from the root (nodes[0]) and calls leaf(ref, tHit) for every leaf the ray enters
/// within [tMin, tHit]. AnyHit: leaf returns true when it blocks the ray, and the walk stops with
/// true. Closest hit: leaf lowers tHit when it finds a closer hit (its return value is ignored);
/// entries farther than tHit are skipped, and the result is false. prefetchLeaf(ref) starts
/// loading a leaf's data when the leaf is pushed.
template <bool AnyHit, bool Ordered, class PrefetchLeaf, class Leaf>
RAYS_FORCEINLINE bool traverseWide(const WideNode* nodes, const BoxRay& r, float tMin, float& tHit,
                                   PrefetchLeaf&& prefetchLeaf, Leaf&& leaf) {
    struct Entry {
        uint32_t ref;
        float dist;
    };
    Entry stack[kStackSize];
    Entry* sp = stack;
    VFloat8 vtHit = VFloat8::broadcast(tHit);
    const VFloat8 vtMin = VFloat8::broadcast(tMin);
    uint32_t ref = 0;
    // Pushed entries are visited later: start fetching them now.
    auto prefetch = [&](uint32_t c) {
        if (isLeaf(c)) {
            prefetchLeaf(c);
            return;
        }
        const char* p = reinterpret_cast<const char*>(nodes + c);
        __builtin_prefetch(p);
        __builtin_prefetch(p + 64);
        __builtin_prefetch(p + 128);
        __builtin_prefetch(p + 192);
    };

    for (;;) {
        if (!isLeaf(ref)) {
            const WideNode& n = nodes[ref];
            VFloat8 tn;
            uint32_t mask = childHits(n, r, vtMin, vtHit, tn);
            if constexpr (AnyHit || !Ordered) {
                // No ordering: continue with the first child hit, push the others.
                if (mask) {
                    alignas(32) float dist[8];
                    if constexpr (!AnyHit) tn.store(dist);
                    ref = n.child[lowestBit(mask)];
                    for (mask &= mask - 1; mask; mask &= mask - 1) {
                        const unsigned i = lowestBit(mask);
                        prefetch(n.child[i]);
                        *sp++ = {n.child[i], AnyHit ? 0.0f : dist[i]};
                    }
                    continue;
                }
            } else if (mask) {
                alignas(32) float dist[8];
                tn.store(dist);
                const unsigned i0 = lowestBit(mask);
                mask &= mask - 1;
                if (!mask) {
                    ref = n.child[i0];
                    continue;
                }
                const unsigned i1 = lowestBit(mask);
                mask &= mask - 1;
                const uint32_t c0 = n.child[i0], c1 = n.child[i1];
                const float d0 = dist[i0], d1 = dist[i1];
                if (!mask) {
                    if (d0 <= d1) {
                        prefetch(c1);
                        *sp++ = {c1, d1};
                        ref = c0;
                    } else {
                        prefetch(c0);
                        *sp++ = {c0, d0};
                        ref = c1;
                    }
                    continue;
                }
                Entry* base = sp;
                prefetch(c0);
                prefetch(c1);
                *sp++ = {c0, d0};
                *sp++ = {c1, d1};
                do {
                    const unsigned i = lowestBit(mask);
                    mask &= mask - 1;
                    prefetch(n.child[i]);
                    *sp++ = {n.child[i], dist[i]};
                } while (mask);
                // Sort the new entries by decreasing distance: the nearest ends on top.
                for (Entry* e = base + 1; e < sp; ++e) {
                    const Entry x = *e;
                    Entry* f = e;
                    while (f > base && f[-1].dist < x.dist) {
                        *f = f[-1];
                        --f;
                    }
                    *f = x;
                }
                ref = (--sp)->ref;
                continue;
            }
        } else {
            if constexpr (AnyHit) {
                if (leaf(ref, tHit)) return true;
            } else {
                leaf(ref, tHit);
                vtHit = VFloat8::broadcast(tHit);
            }
        }
        // Pop the nearest pending entry that can still hold a closer hit.
        for (;;) {
            if (sp == stack) return false;
            --sp;
            if (AnyHit || sp->dist <= tHit) {
                ref = sp->ref;
                break;
            }
        }
    }
}

}  // namespace rays::tribvh
