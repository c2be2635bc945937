// A tree of boxes over the parts of one CSG tree (csg.h): over its leaves (the walk along a ray
// asks for the nearest leaf hit after a point) or over the children of one wide node (an inside
// test asks whether any child holds a point). Built once when the CSG is finished; read-only while
// rendering. A union of 20,000 spheres inside a difference is then found in O(log n) per step
// instead of testing every sphere (issue: "bound the children, do not test them all").
//
// A plain bounding volume hierarchy split at the median of the box centres along their widest
// axis (as in Ray Tracing: The Next Week, "Bounding Volume Hierarchies"), four items per leaf at
// most. Items whose box is not finite (planes, inverted objects) cannot be placed: they are kept
// aside and visited by every query; items with an empty box are left out.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "rays/geometry/ray.h"

namespace rays {

struct CsgBoxTree {
    struct Node {
        Bounds box;
        int32_t first = 0;  ///< leaf: its items ids[first, first + count); inner: its right child (left: this + 1)
        int32_t count = 0;  ///< 0 for inner nodes
    };
    std::vector<Node> nodes;           ///< node 0 is the root (none when no item has a finite box)
    std::vector<int32_t> ids;          ///< the items, in leaf order
    std::vector<int32_t> unbounded;    ///< items visited by every query

    /// Builds the tree over items ids[i] with boxes boxes[i].
    static CsgBoxTree build(const std::vector<Bounds>& boxes, const std::vector<int32_t>& ids);
    bool empty() const { return nodes.empty() && unbounded.empty(); }

    /// Calls visit(id, hi) for every item whose box the ray meets within (lo, hi), nearest boxes
    /// first; visit may lower hi (a hit found), which prunes the rest.
    template <class Visit>
    void alongRay(const Ray& ray, Vec3 invDir, double lo, double& hi, Visit&& visit) const;

    /// Calls test(id) for the items whose box holds q until one returns true; returns whether one did.
    template <class Test>
    bool anyHolding(Vec3 q, Test&& test) const;
};

namespace csg_box_tree_detail {

// The ray's entry into box b within (lo, hi), or +infinity when it misses (slab test).
inline double entry(const Bounds& b, const Ray& r, Vec3 invDir, double lo, double hi) {
    for (int a = 0; a < 3; ++a) {
        double n = (b.lo[a] - r.origin[a]) * invDir[a], f = (b.hi[a] - r.origin[a]) * invDir[a];
        if (n > f) std::swap(n, f);
        if (n == n) lo = std::max(lo, n);  // NaN (0 · infinity): the slab does not decide
        if (f == f) hi = std::min(hi, f);
    }
    // Widened for the slab test's rounding, as the leaves' windows are.
    const double pad = 1e-9 * (std::fabs(lo) + std::fabs(hi)) + 1e-12;
    return lo <= hi + pad ? lo : kInfinity;
}

inline bool holds(const Bounds& b, Vec3 q) {
    return q.x >= b.lo.x && q.x <= b.hi.x && q.y >= b.lo.y && q.y <= b.hi.y && q.z >= b.lo.z && q.z <= b.hi.z;
}

}  // namespace csg_box_tree_detail

template <class Visit>
void CsgBoxTree::alongRay(const Ray& ray, Vec3 invDir, double lo, double& hi, Visit&& visit) const {
    using csg_box_tree_detail::entry;
    for (int32_t id : unbounded) visit(id, hi);
    if (nodes.empty()) return;
    struct Pending {
        int32_t node;
        double t;
    };
    Pending stack[64];  // the tree is split at medians: at most log2(items) + 1 levels deep
    int top = 0;
    const double t0 = entry(nodes[0].box, ray, invDir, lo, hi);
    if (t0 == kInfinity) return;
    stack[top++] = {0, t0};
    while (top > 0) {
        const Pending p = stack[--top];
        if (p.t > hi) continue;
        const Node& n = nodes[size_t(p.node)];
        if (n.count > 0) {
            for (int32_t i = n.first; i < n.first + n.count; ++i) visit(ids[size_t(i)], hi);
            continue;
        }
        const int32_t a = p.node + 1, b = n.first;
        const double ta = entry(nodes[size_t(a)].box, ray, invDir, lo, hi);
        const double tb = entry(nodes[size_t(b)].box, ray, invDir, lo, hi);
        // The nearer child is taken first (pushed last).
        if (ta <= tb) {
            if (tb != kInfinity) stack[top++] = {b, tb};
            if (ta != kInfinity) stack[top++] = {a, ta};
        } else {
            if (ta != kInfinity) stack[top++] = {a, ta};
            stack[top++] = {b, tb};
        }
    }
}

template <class Test>
bool CsgBoxTree::anyHolding(Vec3 q, Test&& test) const {
    using csg_box_tree_detail::holds;
    for (int32_t id : unbounded)
        if (test(id)) return true;
    if (nodes.empty() || !holds(nodes[0].box, q)) return false;
    int32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes[size_t(stack[--top])];
        if (n.count > 0) {
            for (int32_t i = n.first; i < n.first + n.count; ++i)
                if (test(ids[size_t(i)])) return true;
            continue;
        }
        const int32_t self = int32_t(&n - nodes.data());
        if (holds(nodes[size_t(n.first)].box, q)) stack[top++] = n.first;
        if (holds(nodes[size_t(self + 1)].box, q)) stack[top++] = self + 1;
    }
    return false;
}

}  // namespace rays
