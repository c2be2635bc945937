// TriangleBvh traversal: 8-wide box tests, near-first ordering, 4-wide watertight triangle
// tests. See triangle_bvh.h for the robustness argument. The Unordered and ScalarLeaves variants
// exist to measure what ordering and SIMD leaves buy (bench/traverse.cpp --ablation).
#include <cmath>
#include <cstring>
#include <limits>

#include "rays/accel/simd.h"
#include "rays/accel/triangle_bvh.h"
#include "rays/accel/wide_traverse.h"

namespace rays {

#ifdef RAYS_TRIBVH_COUNTERS
// Development statistics (compile with -DRAYS_TRIBVH_COUNTERS).
thread_local uint64_t gTriBvhBlockTests = 0, gTriBvhRays = 0;
#define RAYS_COUNT(x) (++(x))
#else
#define RAYS_COUNT(x) ((void)0)
#endif

namespace {

using namespace tribvh;

/// Per-ray constants for the triangle tests (Woop et al. 2013): axis permutation, shear, permuted
/// origin. The box test has its own (BoxRay, wide_traverse.h).
struct RayData {
    int kx, ky, kz;
    float shx, shy, shz;     // shear: dir[kx] / dir[kz], dir[ky] / dir[kz], 1 / dir[kz]
    float orgx, orgy, orgz;  // org[kx], org[ky], org[kz]
    VFloat4 sx, sy, sz, ox, oy, oz;

    explicit RayData(const TriRay& r) {
        const float ax = std::fabs(r.dir[0]), ay = std::fabs(r.dir[1]), az = std::fabs(r.dir[2]);
        kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        kx = kz == 2 ? 0 : kz + 1;
        ky = kx == 2 ? 0 : kx + 1;
        if (r.dir[kz] < 0.0f) {
            const int t = kx;
            kx = ky;
            ky = t;
        }
        shz = 1.0f / r.dir[kz];
        shx = r.dir[kx] * shz;
        shy = r.dir[ky] * shz;
        sx = VFloat4::broadcast(shx);
        sy = VFloat4::broadcast(shy);
        sz = VFloat4::broadcast(shz);
        orgx = r.org[kx];
        orgy = r.org[ky];
        orgz = r.org[kz];
        ox = VFloat4::broadcast(r.org[kx]);
        oy = VFloat4::broadcast(r.org[ky]);
        oz = VFloat4::broadcast(r.org[kz]);
    }
};

/// Edge functions and determinant of a block's four triangles (lanes).
struct BlockTest {
    VFloat4 u, v, w, det, t;  // t = T with the sign of det folded in, |det| in det
    uint32_t mask;            // lanes that pass the edge tests and have det != 0
};

RAYS_FORCEINLINE void edgeTest(const TriBlock& b, const RayData& r, BlockTest& o) {
    const VFloat4 akx = VFloat4::load(b.v[0][r.kx]) - r.ox, aky = VFloat4::load(b.v[0][r.ky]) - r.oy;
    const VFloat4 akz = VFloat4::load(b.v[0][r.kz]) - r.oz;
    const VFloat4 bkx = VFloat4::load(b.v[1][r.kx]) - r.ox, bky = VFloat4::load(b.v[1][r.ky]) - r.oy;
    const VFloat4 bkz = VFloat4::load(b.v[1][r.kz]) - r.oz;
    const VFloat4 ckx = VFloat4::load(b.v[2][r.kx]) - r.ox, cky = VFloat4::load(b.v[2][r.ky]) - r.oy;
    const VFloat4 ckz = VFloat4::load(b.v[2][r.kz]) - r.oz;
    const VFloat4 ax = fnmadd(r.sx, akz, akx), ay = fnmadd(r.sy, akz, aky);
    const VFloat4 bx = fnmadd(r.sx, bkz, bkx), by = fnmadd(r.sy, bkz, bky);
    const VFloat4 cx = fnmadd(r.sx, ckz, ckx), cy = fnmadd(r.sy, ckz, cky);
    // Separately rounded products: U(B,C), V(C,A), W(A,B) are exact negations of the neighbour's
    // values on a shared edge.
    o.u = materialize(cx * by) - materialize(cy * bx);
    o.v = materialize(ax * cy) - materialize(ay * cx);
    o.w = materialize(bx * ay) - materialize(by * ax);
    const VFloat4 zero = VFloat4::zero();
    const VFloat4 inside = cmpGe(min(min(o.u, o.v), o.w), zero) | cmpLe(max(max(o.u, o.v), o.w), zero);
    o.mask = bits(inside);
    if (!o.mask) return;
    const VFloat4 det = o.u + o.v + o.w;
    o.mask &= bits(cmpNe(det, zero));
    if (!o.mask) return;
    const VFloat4 t = fmadd(o.u, r.sz * akz, fmadd(o.v, r.sz * bkz, o.w * (r.sz * ckz)));
    const VFloat4 sign = det & signMask4();
    o.t = t ^ sign;
    o.det = det ^ sign;
}

/// The same watertight test on one lane of a block, in scalar code (ScalarLeaves variant).
/// Returns true with t, u, v when the triangle is hit with tMin < t < tHit.
bool scalarTriangle(const TriBlock& b, int lane, const RayData& r, float tMin, float tHit, float& t, float& u,
                    float& v) {
    float px[3], py[3], pz[3];
    for (int k = 0; k < 3; ++k) {
        const float dx = b.v[k][r.kx][lane] - r.orgx, dy = b.v[k][r.ky][lane] - r.orgy;
        const float dz = b.v[k][r.kz][lane] - r.orgz;
        px[k] = std::fma(-r.shx, dz, dx);
        py[k] = std::fma(-r.shy, dz, dy);
        pz[k] = r.shz * dz;
    }
    const float e0 = materialize(px[2] * py[1]) - materialize(py[2] * px[1]);
    const float e1 = materialize(px[0] * py[2]) - materialize(py[0] * px[2]);
    const float e2 = materialize(px[1] * py[0]) - materialize(py[1] * px[0]);
    const bool inside = (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
    const float det = e0 + e1 + e2;
    if (!inside || det == 0.0f) return false;
    const float tt = std::fma(e0, pz[0], std::fma(e1, pz[1], e2 * pz[2]));
    const float sgn = det < 0.0f ? -1.0f : 1.0f;
    const float tn = tt * sgn, dn = det * sgn;
    if (!(tn > tMin * dn && tn < tHit * dn)) return false;
    const float tv = tn / dn;
    if (!(tv > tMin && tv < tHit)) return false;
    t = tv;
    u = e1 / det;
    v = e2 / det;
    return true;
}

}  // namespace

template <bool AnyHit, bool Ordered, bool SimdLeaves>
bool TriangleBvh::traverse(const TriRay& ray, float tMin, float tMax, TriHit* hit) const {
    if (nodes_.empty() || !(tMax > tMin)) return false;
    if (ray.dir[0] == 0.0f && ray.dir[1] == 0.0f && ray.dir[2] == 0.0f) return false;
    const RayData r(ray);
    const BoxRay br(ray.org, ray.dir);
    RAYS_COUNT(gTriBvhRays);
    float tHit = tMax;
    const VFloat4 vtMin4 = VFloat4::broadcast(tMin);
    const TriBlock* blocks = blocks_.data();
    uint32_t bestPrim = UINT32_MAX;
    float bestU = 0, bestV = 0;
    auto prefetchLeaf = [&](uint32_t c) {
        const char* p = reinterpret_cast<const char*>(blocks + leafFirstBlock(c));
        __builtin_prefetch(p);
        __builtin_prefetch(p + 64);
        __builtin_prefetch(p + 128);
    };
    // Tests the leaf's blocks; any-hit: true at the first hit; closest: lowers tHit.
    auto leaf = [&](uint32_t ref, float& tBest) -> bool {
        const TriBlock* b = blocks + leafFirstBlock(ref);
        const TriBlock* end = b + leafBlockCount(ref);
        for (; b < end; ++b) {
            RAYS_COUNT(gTriBvhBlockTests);
            if constexpr (!SimdLeaves) {
                for (int lane = 0; lane < kBlockSize; ++lane) {
                    float t, u, v;
                    if (!scalarTriangle(*b, lane, r, tMin, tBest, t, u, v)) continue;
                    if constexpr (AnyHit) return true;
                    tBest = t;
                    bestPrim = b->prim[lane];
                    bestU = u;
                    bestV = v;
                }
                continue;
            }
            BlockTest bt;
            edgeTest(*b, r, bt);
            if (!bt.mask) continue;
            // Distance test before dividing: tMin < t < tBest.
            const VFloat4 tHit4 = VFloat4::broadcast(tBest);
            uint32_t m = bt.mask & bits(cmpGt(bt.t, vtMin4 * bt.det) & cmpLt(bt.t, tHit4 * bt.det));
            if (!m) continue;
            if constexpr (AnyHit) {
                return true;
            } else {
                const VFloat4 t = bt.t / bt.det;
                m &= bits(cmpGt(t, vtMin4) & cmpLt(t, tHit4));
                if (!m) continue;
                alignas(16) float ts[4];
                t.store(ts);
                unsigned lane = lowestBit(m);
                for (uint32_t mm = m & (m - 1); mm; mm &= mm - 1) {
                    const unsigned l = lowestBit(mm);
                    if (ts[l] < ts[lane]) lane = l;
                }
                alignas(16) float vs[4], ws[4], ds[4];
                bt.v.store(vs);
                bt.w.store(ws);
                (bt.u + bt.v + bt.w).store(ds);
                tBest = ts[lane];
                bestPrim = b->prim[lane];
                bestU = vs[lane] / ds[lane];
                bestV = ws[lane] / ds[lane];
            }
        }
        return false;
    };
    const bool blocked = traverseWide<AnyHit, Ordered>(nodes_.data(), br, tMin, tHit, prefetchLeaf, leaf);
    if constexpr (AnyHit) {
        return blocked;
    } else {
        if (bestPrim == UINT32_MAX) return false;
        hit->prim = bestPrim;
        hit->t = tHit;
        hit->u = bestU;
        hit->v = bestV;
        return true;
    }
}

bool TriangleBvh::intersect(const TriRay& ray, float tMin, float tMax, TriHit& hit) const {
    return traverse<false, true, true>(ray, tMin, tMax, &hit);
}

bool TriangleBvh::occluded(const TriRay& ray, float tMin, float tMax) const {
    return traverse<true, false, true>(ray, tMin, tMax, nullptr);
}

bool TriangleBvh::intersect(const TriRay& ray, float tMin, float tMax, TriHit& hit, TraversalVariant variant) const {
    switch (variant) {
        case TraversalVariant::Unordered:
            return traverse<false, false, true>(ray, tMin, tMax, &hit);
        case TraversalVariant::ScalarLeaves:
            return traverse<false, true, false>(ray, tMin, tMax, &hit);
        case TraversalVariant::ScalarLeavesUnordered:
            return traverse<false, false, false>(ray, tMin, tMax, &hit);
        case TraversalVariant::Default:
            break;
    }
    return traverse<false, true, true>(ray, tMin, tMax, &hit);
}

bool TriangleBvh::occluded(const TriRay& ray, float tMin, float tMax, TraversalVariant variant) const {
    if (variant == TraversalVariant::ScalarLeaves || variant == TraversalVariant::ScalarLeavesUnordered)
        return traverse<true, false, false>(ray, tMin, tMax, nullptr);
    return traverse<true, false, true>(ray, tMin, tMax, nullptr);
}

}  // namespace rays
