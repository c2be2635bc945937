#include "rays/scene/csg.h"

#include <algorithm>
#include <cmath>

#include "rays/scene/text_shape.h"
#include "rays/scene/shapes/blob.h"
#include "rays/scene/shapes/height_field.h"
#include "rays/scene/shapes/isosurface.h"
#include "rays/scene/shapes/julia_fractal.h"
#include "rays/scene/shapes/lathe.h"
#include "rays/scene/shapes/ovus.h"
#include "rays/scene/shapes/poly.h"
#include "rays/scene/shapes/prism.h"
#include "rays/scene/shapes/sor.h"
#include "rays/scene/shapes/sphere_sweep.h"
#include "rays/scene/shapes/superellipsoid.h"
#include "rays/scene/shapes/torus.h"

namespace rays {

int Csg::add(int parent, CsgOp op, bool inverse) {
    const int n = int(nodes.size());
    CsgNode node;
    node.op = op;
    node.inverse = inverse;
    node.parent = parent;
    nodes.push_back(node);
    if (parent >= 0) {
        CsgNode& p = nodes[size_t(parent)];
        if (p.lastChild >= 0) nodes[size_t(p.lastChild)].nextSibling = n;
        else p.firstChild = n;
        p.lastChild = n;
    }
    return n;
}

int Csg::addLeaf(int parent, const Object& o, bool inverse) {
    const int n = add(parent, CsgOp::Leaf, inverse);
    nodes[size_t(n)].leaf = int32_t(leaves.size());
    leaves.push_back(o);
    leafNode.push_back(n);
    return n;
}

int Csg::childCount(int n) const {
    int count = 0;
    for (int s = nodes[size_t(n)].firstChild; s >= 0; s = nodes[size_t(s)].nextSibling) ++count;
    return count;
}

bool Csg::needsInside(int k) const {
    int child = leafNode[size_t(k)];
    for (int p = nodes[size_t(child)].parent; p >= 0; child = p, p = nodes[size_t(p)].parent) {
        const CsgNode& node = nodes[size_t(p)];
        if (node.op == CsgOp::Union || (node.op == CsgOp::Clip && child == node.firstChild)) continue;
        return true;
    }
    return false;
}

namespace {

constexpr double kAxisTolerance = 1e-12;

Bounds allSpace() { return Bounds{Vec3(-kInfinity), Vec3(kInfinity)}; }

Bounds meet(const Bounds& a, const Bounds& b) { return Bounds{vmax(a.lo, b.lo), vmin(a.hi, b.hi)}; }

// A plane's inside as a box: a half-space when its world normal lies along an axis, else all space.
Bounds planeBounds(const Object& o, bool inverse) {
    Vec3 n = o.p0;
    double d = o.r0;
    if (o.localSpace) {
        n = normalize(o.toObject.transposedVector(o.p0));
        d = dot(n, o.toObject.inverse().point(o.p0 * o.r0));
    }
    if (inverse) n = -n, d = -d;  // inside: n·x < d becomes −n·x < −d (the boundary aside)
    Bounds b = allSpace();
    for (int a = 0; a < 3; ++a) {
        const int b1 = (a + 1) % 3, b2 = (a + 2) % 3;
        if (std::fabs(n[b1]) > kAxisTolerance || std::fabs(n[b2]) > kAxisTolerance) continue;
        if (n[a] > 0) b.hi[a] = d / n[a];
        else b.lo[a] = d / n[a];
    }
    return b;
}

// World bounds of a leaf, all space for unbounded ones (planes, polys).
Bounds leafWorldBox(const Object& o) {
    const Bounds b = o.type == ShapeType::Plane ? Bounds{} : worldBounds(o);
    return b.empty() && (o.type == ShapeType::Plane || o.type == ShapeType::Poly) ? allSpace() : b;
}

Bounds leafBounds(const Object& o, bool inverse) {
    if (o.type == ShapeType::Plane) return planeBounds(o, inverse);
    if (inverse) return allSpace();
    return leafWorldBox(o);
}

Bounds nodeBounds(const Csg& c, int n) {
    const CsgNode& node = c.nodes[size_t(n)];
    if (node.op == CsgOp::Leaf) return leafBounds(c.leaves[size_t(node.leaf)], node.inverse);
    if (node.inverse) return allSpace();
    Bounds b;
    switch (node.op) {
        case CsgOp::Union: case CsgOp::Merge:
            for (int s = node.firstChild; s >= 0; s = c.nodes[size_t(s)].nextSibling) b.extend(nodeBounds(c, s));
            break;
        case CsgOp::Intersection: case CsgOp::Clip:
            if (node.firstChild < 0) break;
            b = allSpace();
            for (int s = node.firstChild; s >= 0; s = c.nodes[size_t(s)].nextSibling) b = meet(b, nodeBounds(c, s));
            break;
        case CsgOp::Difference:
            if (node.firstChild >= 0) b = nodeBounds(c, node.firstChild);
            break;
        case CsgOp::Leaf: case CsgOp::Empty: break;
    }
    return b;
}

// Whether leaf k's surface can be part of the tree's surface at all: not a clipping object, not
// under an Empty node.
bool leafHasSurface(const Csg& c, int k) {
    int child = c.leafNode[size_t(k)];
    for (int p = c.nodes[size_t(child)].parent; p >= 0; child = p, p = c.nodes[size_t(p)].parent) {
        const CsgNode& node = c.nodes[size_t(p)];
        if (node.op == CsgOp::Empty) return false;
        if (node.op == CsgOp::Clip && child != node.firstChild) return false;
    }
    return true;
}

// Whether leaf k's surface at world point q is on the tree's surface (see csg.h); flip: the
// tree's outward normal there is the leaf's inward one.
bool onSurface(const Csg& c, int k, Vec3 q, bool& flip) {
    int child = c.leafNode[size_t(k)];
    flip = c.nodes[size_t(child)].inverse;
    for (int p = c.nodes[size_t(child)].parent; p >= 0; child = p, p = c.nodes[size_t(p)].parent) {
        const CsgNode& node = c.nodes[size_t(p)];
        auto siblings = [&](auto&& test) {  // test(s) for every other child s; false at the first that fails
            for (int s = node.firstChild; s >= 0; s = c.nodes[size_t(s)].nextSibling)
                if (s != child && !test(s)) return false;
            return true;
        };
        switch (node.op) {
            case CsgOp::Union: case CsgOp::Leaf: break;
            case CsgOp::Merge:
                if (!siblings([&](int s) { return !insideCsg(c, s, q); })) return false;
                break;
            case CsgOp::Intersection: case CsgOp::Clip:
                if (!siblings([&](int s) { return insideCsg(c, s, q); })) return false;
                break;
            case CsgOp::Difference:
                if (child == node.firstChild) {
                    if (!siblings([&](int s) { return !insideCsg(c, s, q); })) return false;
                } else {
                    const int first = node.firstChild;
                    if (!siblings([&](int s) { return s == first ? insideCsg(c, s, q) : !insideCsg(c, s, q); }))
                        return false;
                    flip = !flip;  // a subtracted surface faces into the subtracted object
                }
                break;
            case CsgOp::Empty: return false;
        }
        if (node.inverse) flip = !flip;
    }
    return true;
}

}  // namespace

void Csg::finish() {
    bounds = nodes.empty() ? Bounds{} : nodeBounds(*this, 0);
    hasSurface.resize(leaves.size());
    leafBox.resize(leaves.size());
    for (size_t k = 0; k < leaves.size(); ++k) {
        hasSurface[k] = leafHasSurface(*this, int(k));
        Bounds b = leafWorldBox(leaves[k]);
        if (!b.empty()) {  // room for the rounding of the slab test
            Vec3 pad;
            for (int a = 0; a < 3; ++a) pad[a] = 1e-9 * (std::fabs(b.lo[a]) + std::fabs(b.hi[a])) + 1e-12;
            b = Bounds{b.lo - pad, b.hi + pad};
        }
        leafBox[k] = b;
    }
}

bool Csg::boundsEmpty() const {
    for (int a = 0; a < 3; ++a)
        if (!(bounds.lo[a] <= bounds.hi[a])) return true;
    return false;
}

int insideShape(const Object& o, Vec3 q) {
    const Vec3 p = o.localSpace ? o.toObject.point(q) : q;
    switch (o.type) {
        case ShapeType::Sphere: {  // p1, r1: the sphere intersected (world space when not localSpace)
            const Vec3 c = o.localSpace ? o.p0 : o.p1;
            const double r = o.localSpace ? o.r0 : o.r1;
            return dot(p - c, p - c) < r * r;
        }
        case ShapeType::Box:
            return p.x > o.p0.x && p.x < o.p1.x && p.y > o.p0.y && p.y < o.p1.y && p.z > o.p0.z && p.z < o.p1.z;
        case ShapeType::Cone: {  // the canonical frame: axis along z from 0 to p2.x, radius r0 + p2.y·z
            if (p.z < 0 || p.z > o.p2.x) return 0;
            const double r = o.r0 + o.p2.y * p.z;
            return p.x * p.x + p.y * p.y < r * r;
        }
        case ShapeType::Plane: return dot(o.p0, p) < o.r0;
        case ShapeType::Csg: return insideCsg(*o.csg, 0, q);
        case ShapeType::Text: return insideText(*o.text, p);
        case ShapeType::Torus: return insideTorus(o, p);
        case ShapeType::Poly: return insidePolySurface(o, p);
        case ShapeType::Superellipsoid: return insideSuperellipsoid(o, p);
        case ShapeType::Prism: return insidePrism(o, p);
        case ShapeType::Blob: return insideBlob(o, p);
        case ShapeType::Isosurface: return insideIsosurface(o, p);
        case ShapeType::Lathe: return insideLathe(o, p);
        case ShapeType::Sor: return insideSor(o, p);
        case ShapeType::SphereSweep: return insideSphereSweep(o, p);
        case ShapeType::HeightField: return insideHeightField(o, p);
        case ShapeType::JuliaFractal: return insideJuliaFractal(o, p);
        case ShapeType::Ovus: return insideOvus(o, p);
        case ShapeType::Triangle: case ShapeType::Mesh: case ShapeType::Disc: case ShapeType::Polygon: return -1;
    }
    return -1;
}

bool insideCsg(const Csg& c, int n, Vec3 q) {
    const CsgNode& node = c.nodes[size_t(n)];
    bool in = false;
    switch (node.op) {
        case CsgOp::Leaf: in = insideShape(c.leaves[size_t(node.leaf)], q) > 0; break;
        case CsgOp::Union: case CsgOp::Merge:
            for (int s = node.firstChild; s >= 0 && !in; s = c.nodes[size_t(s)].nextSibling) in = insideCsg(c, s, q);
            break;
        case CsgOp::Intersection: case CsgOp::Clip:
            in = node.firstChild >= 0;
            for (int s = node.firstChild; s >= 0 && in; s = c.nodes[size_t(s)].nextSibling) in = insideCsg(c, s, q);
            break;
        case CsgOp::Difference:
            in = node.firstChild >= 0 && insideCsg(c, node.firstChild, q);
            for (int s = node.firstChild >= 0 ? c.nodes[size_t(node.firstChild)].nextSibling : -1; s >= 0 && in;
                 s = c.nodes[size_t(s)].nextSibling)
                in = !insideCsg(c, s, q);
            break;
        case CsgOp::Empty: break;
    }
    return in != node.inverse;
}

namespace {

// Whether the ray may meet box b with t in [tMin, tMax] (slab test; an undecided NaN counts as a
// meeting).
bool meetsBox(const Bounds& b, const Ray& r, Vec3 invDir, double tMin, double tMax) {
    for (int a = 0; a < 3; ++a) {
        double n = (b.lo[a] - r.origin[a]) * invDir[a], f = (b.hi[a] - r.origin[a]) * invDir[a];
        if (n > f) std::swap(n, f);
        if (n > tMin) tMin = n;
        if (f < tMax) tMax = f;
        if (tMin > tMax) return false;
    }
    return true;
}

}  // namespace

bool intersectCsg(const Csg& c, const Ray& ray, double tMin, double tMax, ShapeHit* hit) {
    const int n = int(c.leaves.size());
    const int cached = std::min(n, kCsgCachedLeaves);
    const bool boxTest = n >= kCsgBoxTestLeaves;
    const Vec3 invDir{1 / ray.dir.x, 1 / ray.dir.y, 1 / ray.dir.z};
    // Whether leaf i can have a surface hit in (from, to).
    auto candidate = [&](int i, double from, double to) {
        return c.hasSurface[size_t(i)] && (!boxTest || meetsBox(c.leafBox[size_t(i)], ray, invDir, from, to));
    };
    double nextT[kCsgCachedLeaves];  // leaf i's nearest hit after from[i] (infinite: none)
    double from[kCsgCachedLeaves];
    ShapeHit sh;
    for (int i = 0; i < cached; ++i) {
        from[i] = tMin;
        nextT[i] = candidate(i, tMin, tMax) && intersect(c.leaves[size_t(i)], ray, tMin, tMax, sh) ? sh.t : kInfinity;
    }
    double tLast = tMin;  // the hits taken so far lie at or before it
    for (;;) {
        int best = -1;
        double bestT = tMax, bestFrom = tLast;
        for (int i = 0; i < cached; ++i)
            if (nextT[i] < bestT) best = i, bestT = nextT[i];
        for (int i = cached; i < n; ++i)  // beyond the cache: recomputed (a tie with a taken hit is lost)
            if (candidate(i, tLast, bestT) && intersect(c.leaves[size_t(i)], ray, tLast, bestT, sh))
                best = i, bestT = sh.t;
        if (best < 0) return false;
        if (best < cached) bestFrom = from[best];
        bool flip = false;
        if (onSurface(c, best, ray.at(bestT), flip)) {
            if (!hit) return true;
            // The same test again, for the normals: the nearest hit after bestFrom is bestT.
            const Object& leaf = c.leaves[size_t(best)];
            if (!intersect(leaf, ray, bestFrom, tMax, *hit)) return false;
            if (flip) {
                hit->normal = -hit->normal;
                hit->geomNormal = -hit->geomNormal;
            }
            if (!hit->part) hit->part = &leaf;  // a blob's component texture stays
            return true;
        }
        tLast = bestT;
        if (best < cached) {
            from[best] = bestT;
            nextT[best] = intersect(c.leaves[size_t(best)], ray, bestT, tMax, sh) ? sh.t : kInfinity;
        }
    }
}

}  // namespace rays
