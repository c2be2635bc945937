#include "rays/scene/csg.h"

#include <algorithm>
#include <cmath>
#include <new>

#include "rays/scene/mesh.h"
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
    // The inside reaches a little beyond the surface (insideShape: 1e-10 in the plane's own units,
    // which a transform may stretch): a margin well beyond that.
    d += 1e-8 * (1 + std::fabs(d));
    Bounds b = allSpace();
    for (int a = 0; a < 3; ++a) {
        const int b1 = (a + 1) % 3, b2 = (a + 2) % 3;
        if (std::fabs(n[b1]) > kAxisTolerance || std::fabs(n[b2]) > kAxisTolerance) continue;
        if (n[a] > 0) b.hi[a] = d / n[a];
        else b.lo[a] = d / n[a];
    }
    return b;
}

// Box b (sides may be infinite) mapped by the affine m: the box of the mapped box, where a zero
// entry of m takes nothing from an infinite side (no 0·∞).
Bounds mapBox(const Transform& m, const Bounds& b) {
    Bounds w;
    for (int i = 0; i < 3; ++i) {
        double centre = m.m[i][3], half = 0;
        for (int j = 0; j < 3; ++j) {
            if (m.m[i][j] == 0) continue;
            const bool finite = std::isfinite(b.lo[j]) && std::isfinite(b.hi[j]);
            centre += finite ? m.m[i][j] * 0.5 * (b.lo[j] + b.hi[j]) : 0;
            half += finite ? std::fabs(m.m[i][j]) * 0.5 * (b.hi[j] - b.lo[j]) : kInfinity;
        }
        w.lo[i] = std::isfinite(half) ? centre - half : -kInfinity;
        w.hi[i] = std::isfinite(half) ? centre + half : kInfinity;
    }
    return w;
}

// World bounds of a leaf (its surface and its inside), all space for unbounded ones (planes,
// polys); the sides of a quadric's box that are infinite (cylinders) may remain so.
Bounds leafWorldBox(const Object& o) {
    const Bounds b = o.type == ShapeType::Plane ? Bounds{} : worldBounds(o);
    if (!b.empty() || (o.type != ShapeType::Plane && o.type != ShapeType::Poly)) return b;
    Bounds q;
    if (o.type == ShapeType::Poly && quadricInsideBox(*o.data, q)) return o.transformed ? mapBox(o.toObject.inverse(), q) : q;
    return allSpace();
}

// World bounds of a quadric leaf's inside within the world box `clip` (poly.h, quadricBoxWithin),
// all space for other leaves.
Bounds quadricWithin(const Object& o, const Bounds& clip) {
    if (o.type != ShapeType::Poly || !o.data) return allSpace();
    const Bounds local = o.transformed ? mapBox(o.toObject, clip) : clip;
    Bounds q;
    if (!quadricBoxWithin(*o.data, local, q)) return allSpace();
    if (q.empty()) return q;
    return o.transformed ? mapBox(o.toObject.inverse(), q) : q;
}

Bounds leafBounds(const Object& o, bool inverse) {
    if (o.type == ShapeType::Plane) return planeBounds(o, inverse);
    if (inverse || o.type == ShapeType::Disc) return allSpace();  // a disc's inside is its plane's half-space
    return leafWorldBox(o);
}

// Node n's bounds from its children's, nb (a child is added after its parent: its index is larger).
Bounds nodeBounds(const Csg& c, int n, const std::vector<Bounds>& nb) {
    const CsgNode& node = c.nodes[size_t(n)];
    if (node.op == CsgOp::Leaf) return leafBounds(c.leaves[size_t(node.leaf)], node.inverse);
    if (node.inverse) return allSpace();
    Bounds b;
    switch (node.op) {
        case CsgOp::Union: case CsgOp::Merge:
            for (int s = node.firstChild; s >= 0; s = c.nodes[size_t(s)].nextSibling) b.extend(nb[size_t(s)]);
            break;
        case CsgOp::Intersection: case CsgOp::Clip:
            if (node.firstChild < 0) break;
            b = allSpace();
            for (int s = node.firstChild; s >= 0; s = c.nodes[size_t(s)].nextSibling) b = meet(b, nb[size_t(s)]);
            // A quadric's inside can be unbounded (a hyperboloid) and yet bounded within the box of
            // the other children (two planes): met with its part within the box.
            for (int s = node.firstChild; s >= 0 && !b.empty(); s = c.nodes[size_t(s)].nextSibling) {
                const CsgNode& sn = c.nodes[size_t(s)];
                if (sn.op == CsgOp::Leaf && !sn.inverse) b = meet(b, quadricWithin(c.leaves[size_t(sn.leaf)], b));
            }
            break;
        case CsgOp::Difference:
            if (node.firstChild >= 0) b = nb[size_t(node.firstChild)];
            break;
        case CsgOp::Leaf: case CsgOp::Empty: break;
    }
    return b;
}

// Every node's bounds, children first: a union of n children below a difference costs O(n), not
// O(n) for each of its leaves.
std::vector<Bounds> allNodeBounds(const Csg& c) {
    std::vector<Bounds> nb(c.nodes.size());
    for (size_t n = c.nodes.size(); n-- > 0;) nb[n] = nodeBounds(c, int(n), nb);
    return nb;
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
        const int wide = c.childTree.empty() ? -1 : c.childTree[size_t(p)];
        // With a box tree over the children: whether a child other than `child` and `skip` holds q.
        auto anyOther = [&](int skip) {
            return c.childTrees[size_t(wide)].anyHolding(
                q, [&](int s) { return s != child && s != skip && insideCsg(c, s, q); });
        };
        switch (node.op) {
            case CsgOp::Union: case CsgOp::Leaf: break;
            case CsgOp::Merge:
                if (wide >= 0 ? anyOther(-1) : !siblings([&](int s) { return !insideCsg(c, s, q); })) return false;
                break;
            case CsgOp::Intersection: case CsgOp::Clip:
                if (!siblings([&](int s) { return insideCsg(c, s, q); })) return false;
                break;
            case CsgOp::Difference:
                if (child == node.firstChild) {
                    if (wide >= 0 ? anyOther(-1) : !siblings([&](int s) { return !insideCsg(c, s, q); })) return false;
                } else {
                    const int first = node.firstChild;
                    if (wide >= 0 ? !insideCsg(c, first, q) || anyOther(first)
                                  : !siblings([&](int s) { return s == first ? insideCsg(c, s, q) : !insideCsg(c, s, q); }))
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

// Whether leaf o (inverted or not) has a convex inside that insideInterval can follow.
bool convexInside(const Object& o, bool inverse) {
    Bounds box;
    switch (o.type) {
        case ShapeType::Plane: return true;
        case ShapeType::Sphere: case ShapeType::Box: return !inverse;
        case ShapeType::Poly: return !inverse && quadricInsideBox(*o.data, box);
        default: return false;
    }
}

// The stretch [a, b] of the world ray within the closed inside of convex leaf o (convexInside),
// widened a little for rounding; false when the ray misses it (a, b unset). Infinite ends for
// shapes without a convex inside.
bool insideSpan(const Object& o, bool inverse, const Ray& worldRay, double& spanLo, double& spanHi) {
    const Ray r = o.localSpace ? Ray{o.toObject.point(worldRay.origin), o.toObject.vector(worldRay.dir)} : worldRay;
    double a = -kInfinity, b = kInfinity;
    switch (o.type) {
        case ShapeType::Plane: {  // inside: p0·x < r0 (inverse: >)
            double slope = dot(o.p0, r.dir), value = dot(o.p0, r.origin) - o.r0;
            if (inverse) slope = -slope, value = -value;
            if (slope == 0) {
                if (value > 0) b = a;
            } else if (slope > 0) {
                b = -value / slope;
            } else {
                a = -value / slope;
            }
            break;
        }
        case ShapeType::Sphere: {
            const Vec3 c = o.localSpace ? o.p0 : o.p1;
            const double rad = o.localSpace ? o.r0 : o.r1;
            const Vec3 oc = r.origin - c;
            const double A = dot(r.dir, r.dir), B = dot(oc, r.dir), C = dot(oc, oc) - rad * rad;
            const double disc = B * B - A * C;
            if (!(disc >= 0) || A == 0) {
                b = a;
                break;
            }
            const double q = -(B + std::copysign(std::sqrt(disc), B));  // the stable pair of roots
            double t0 = q / A, t1 = q != 0 ? C / q : t0;
            if (t0 > t1) std::swap(t0, t1);
            a = t0, b = t1;
            break;
        }
        case ShapeType::Box:
            for (int i = 0; i < 3; ++i) {
                if (r.dir[i] == 0) {
                    if (r.origin[i] < o.p0[i] || r.origin[i] > o.p1[i]) b = a;
                    continue;
                }
                double n = (o.p0[i] - r.origin[i]) / r.dir[i], f = (o.p1[i] - r.origin[i]) / r.dir[i];
                if (n > f) std::swap(n, f);
                a = std::max(a, n);
                b = std::min(b, f);
            }
            break;
        case ShapeType::Poly: quadricInsideInterval(*o.data, r, a, b); break;
        default:
            spanLo = -kInfinity, spanHi = kInfinity;
            return true;
    }
    if (!(a <= b)) return false;
    const double pad = 1e-7 * ((std::isfinite(a) ? std::fabs(a) : 0) + (std::isfinite(b) ? std::fabs(b) : 0)) + 1e-12;
    spanLo = a - pad, spanHi = b + pad;
    return true;
}

// Narrows [lo, hi] to the stretch of the world ray within the closed inside of convex leaf o
// (insideSpan); lo ≥ hi when the ray misses it.
void insideInterval(const Object& o, bool inverse, const Ray& worldRay, double& lo, double& hi) {
    double a, b;
    if (!insideSpan(o, inverse, worldRay, a, b)) {
        hi = lo;
        return;
    }
    lo = std::max(lo, a);
    hi = std::min(hi, b);
}

}  // namespace

// The box trees of wide nodes (over their children's bounds) and, for a tree of many leaves, over
// the leaves' windows (csg_box_tree.h). Triangles and meshes are sought over the whole ray
// (intersectCsg): they are visited always.
void Csg::buildBoxTrees(const std::vector<Bounds>& nb) {
    childTree.assign(nodes.size(), -1);
    childTrees.clear();
    for (size_t n = 0; n < nodes.size(); ++n) {
        const CsgNode& node = nodes[n];
        if (node.op != CsgOp::Union && node.op != CsgOp::Merge && node.op != CsgOp::Difference) continue;
        if (childCount(int(n)) < kCsgWideNode) continue;
        std::vector<Bounds> boxes;
        std::vector<int32_t> ids;
        for (int s = node.firstChild; s >= 0; s = nodes[size_t(s)].nextSibling) {
            // Widened: some insides reach a little beyond their surfaces (insideShape).
            Bounds b = nb[size_t(s)];
            for (int a = 0; a < 3; ++a) {
                const double pad = 1e-8 * (1 + (std::isfinite(b.lo[a]) ? std::fabs(b.lo[a]) : 0) +
                                           (std::isfinite(b.hi[a]) ? std::fabs(b.hi[a]) : 0));
                b.lo[a] -= pad;
                b.hi[a] += pad;
            }
            boxes.push_back(b);
            ids.push_back(s);
        }
        childTree[n] = int32_t(childTrees.size());
        childTrees.push_back(CsgBoxTree::build(boxes, ids));
    }
    leafTree = CsgBoxTree{};
    if (leaves.size() <= size_t(kCsgCachedLeaves)) return;
    std::vector<Bounds> boxes;
    std::vector<int32_t> ids;
    for (size_t k = 0; k < leaves.size(); ++k) {
        if (!hasSurface[k]) continue;
        const bool whole = leaves[k].type == ShapeType::Mesh || leaves[k].type == ShapeType::Triangle;
        Bounds b = leafWindow[k];
        if (whole && !b.empty()) b = Bounds{Vec3(-kInfinity), Vec3(kInfinity)};
        boxes.push_back(b);
        ids.push_back(int32_t(k));
    }
    leafTree = CsgBoxTree::build(boxes, ids);
}

namespace {

// POV-Ray inverts a CSG object by rewriting its tree, and a union inverted once or more shows no
// inner surfaces, as a merge. Measured with POV-Ray 3.7 (tests/pov_csg_test.cpp): `union { A B
// inverse }`, an intersection with it, a difference that subtracts a union, and a union inverted
// twice all hide the surface of A inside B; an uninverted union in an intersection shows it. So
// a union under an inverse (its own or an ancestor's) or within a subtracted child of a
// difference becomes a merge; inside and outside do not change.
void mergeInvertedUnions(Csg& c) {
    if (c.nodes.empty()) return;
    struct Item {
        int32_t node;
        bool inverted;
    };
    std::vector<Item> stack{{0, false}};
    while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        CsgNode& node = c.nodes[size_t(it.node)];
        const bool inverted = it.inverted || node.inverse;
        if (inverted && node.op == CsgOp::Union) node.op = CsgOp::Merge;
        for (int32_t s = node.firstChild; s >= 0; s = c.nodes[size_t(s)].nextSibling)
            stack.push_back({s, inverted || (node.op == CsgOp::Difference && s != node.firstChild)});
    }
}

}  // namespace

void Csg::finish() {
    mergeInvertedUnions(*this);
    const std::vector<Bounds> nb = allNodeBounds(*this);
    bounds = nodes.empty() ? Bounds{} : nb[0];
    hasSurface.resize(leaves.size());
    leafWindow.resize(leaves.size());
    for (size_t k = 0; k < leaves.size(); ++k) {
        hasSurface[k] = leafHasSurface(*this, int(k));
        // A surface point of the leaf that the tree shows lies on the surface of every node above
        // it, so within each one's bounds (a union's and a merge's hold their children's, an
        // intersection's and a clip's lie inside all their children, a difference's inside its
        // first child): the leaf's box met with all of them.
        int child = leafNode[k];
        Bounds b = leafWorldBox(leaves[k]);
        for (int p = nodes[size_t(child)].parent; p >= 0; p = nodes[size_t(p)].parent) b = meet(b, nb[size_t(p)]);
        if (!b.empty()) {  // room for the rounding of the slab test
            Vec3 pad;
            for (int a = 0; a < 3; ++a)
                pad[a] = 1e-9 * ((std::isfinite(b.lo[a]) ? std::fabs(b.lo[a]) : 0) +
                                 (std::isfinite(b.hi[a]) ? std::fabs(b.hi[a]) : 0)) + 1e-12;
            b = Bounds{b.lo - pad, b.hi + pad};
        }
        leafWindow[k] = b;
    }
    buildBoxTrees(nb);
    // The convex constraints of each leaf with a surface.
    clipStart.assign(1, 0);
    clipList.clear();
    for (size_t k = 0; k < leaves.size(); ++k) {
        auto take = [&](int s) {
            const CsgNode& sn = nodes[size_t(s)];
            if (sn.op == CsgOp::Leaf && convexInside(leaves[size_t(sn.leaf)], sn.inverse)) clipList.push_back(sn.leaf);
        };
        int child = leafNode[k];
        for (int p = nodes[size_t(child)].parent; hasSurface[k] && p >= 0; child = p, p = nodes[size_t(p)].parent) {
            const CsgNode& node = nodes[size_t(p)];
            if (node.op == CsgOp::Intersection || node.op == CsgOp::Clip) {
                for (int s = node.firstChild; s >= 0; s = nodes[size_t(s)].nextSibling)
                    if (s != child) take(s);
            } else if (node.op == CsgOp::Difference && child != node.firstChild) {
                take(node.firstChild);
            }
        }
        clipStart.push_back(int32_t(clipList.size()));
    }
}

bool Csg::boundsEmpty() const {
    for (int a = 0; a < 3; ++a)
        if (!(bounds.lo[a] <= bounds.hi[a])) return true;
    return false;
}

namespace {

// POV-Ray's inside tests at their boundaries, measured with POV-Ray 3.7's inside() at points
// 10^-4 … 10^-16 either side of each one (tests/pov_csg_test.cpp): a cylinder or a cone holds a
// point only 1e-10 within its canonical form (axis and radius scaled to 1; a cone's apex at 0 and
// its big end at 1), so that a surface lying on a cap or a side counts as outside it; a plane
// reaches 1e-10 beyond its surface; boxes and tori are closed; spheres and discs are open.
constexpr double kPovInsideTolerance = 1e-10;

// Rays' cone frame (object.cpp hitCone): axis z ∈ [0, h], radius r0 + k·z.
bool insideCone(const Object& o, Vec3 p) {
    const double h = o.p2.x, r0 = o.r0, r1 = o.r0 + o.p2.y * h, eps = kPovInsideTolerance;
    if (!(h > 0)) return false;
    const double rho2 = p.x * p.x + p.y * p.y;
    if (r0 == r1) {  // a cylinder: z/h ∈ [0, 1], radius 1
        const double z = p.z / h;
        return z >= eps && z <= 1 - eps && rho2 / (r0 * r0) <= 1 - eps;
    }
    const double big = std::max(r0, r1), small = std::min(r0, r1);
    const double length = h * big / (big - small);  // from the apex to the big end
    const double u = r0 > r1 ? (length - p.z) / length : (p.z - (h - length)) / length;
    return u >= small / big + eps && u <= 1 - eps && rho2 / (big * big) <= u * u - eps;
}

}  // namespace

int insideShape(const Object& o, Vec3 q) {
    const Vec3 p = o.localSpace ? o.toObject.point(q) : q;
    switch (o.type) {
        case ShapeType::Sphere: {  // p1, r1: the sphere intersected (world space when not localSpace)
            const Vec3 c = o.localSpace ? o.p0 : o.p1;
            const double r = o.localSpace ? o.r0 : o.r1;
            return dot(p - c, p - c) < r * r;
        }
        case ShapeType::Box:
            return p.x >= o.p0.x && p.x <= o.p1.x && p.y >= o.p0.y && p.y <= o.p1.y && p.z >= o.p0.z && p.z <= o.p1.z;
        case ShapeType::Cone: return insideCone(o, p);
        case ShapeType::Plane: return dot(o.p0, p) - o.r0 < kPovInsideTolerance * length(o.p0);
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
        // "The inside of a disc is the inside of the plane that contains the disc" (reference
        // 3.4.5.2.2): the side its normal points away from, whatever the radius.
        case ShapeType::Disc: return dot(o.p1, p - o.p0) < 0;
        case ShapeType::Mesh: return o.mesh->hasInside ? int(insideMesh(*o.mesh, p)) : -1;
        case ShapeType::Triangle: case ShapeType::Polygon: return -1;
    }
    return -1;
}

bool insideCsg(const Csg& c, int n, Vec3 q) {
    const CsgNode& node = c.nodes[size_t(n)];
    const int wide = c.childTree.empty() ? -1 : c.childTree[size_t(n)];
    bool in = false;
    switch (node.op) {
        case CsgOp::Leaf: in = insideShape(c.leaves[size_t(node.leaf)], q) > 0; break;
        case CsgOp::Union: case CsgOp::Merge:
            if (wide >= 0) {
                in = c.childTrees[size_t(wide)].anyHolding(q, [&](int s) { return insideCsg(c, s, q); });
                break;
            }
            for (int s = node.firstChild; s >= 0 && !in; s = c.nodes[size_t(s)].nextSibling) in = insideCsg(c, s, q);
            break;
        case CsgOp::Intersection: case CsgOp::Clip:
            in = node.firstChild >= 0;
            for (int s = node.firstChild; s >= 0 && in; s = c.nodes[size_t(s)].nextSibling) in = insideCsg(c, s, q);
            break;
        case CsgOp::Difference:
            in = node.firstChild >= 0 && insideCsg(c, node.firstChild, q);
            if (in && wide >= 0) {
                const int first = node.firstChild;
                in = !c.childTrees[size_t(wide)].anyHolding(q, [&](int s) { return s != first && insideCsg(c, s, q); });
                break;
            }
            for (int s = node.firstChild >= 0 ? c.nodes[size_t(node.firstChild)].nextSibling : -1; s >= 0 && in;
                 s = c.nodes[size_t(s)].nextSibling)
                in = !insideCsg(c, s, q);
            break;
        case CsgOp::Empty: break;
    }
    return in != node.inverse;
}

namespace {

// The part of [tMin, tMax] where the ray is within box b (slab test; an undecided NaN leaves the
// interval as it is), widened a little for the slab test's rounding; lo > hi when the ray misses.
void clipToBox(const Bounds& b, const Ray& r, Vec3 invDir, double& tMin, double& tMax) {
    double lo = -kInfinity, hi = kInfinity;
    for (int a = 0; a < 3; ++a) {
        double n = (b.lo[a] - r.origin[a]) * invDir[a], f = (b.hi[a] - r.origin[a]) * invDir[a];
        if (n > f) std::swap(n, f);
        if (n > lo) lo = n;
        if (f < hi) hi = f;
    }
    const double pad = 1e-9 * ((std::isfinite(lo) ? std::fabs(lo) : 0) + (std::isfinite(hi) ? std::fabs(hi) : 0));
    tMin = std::max(tMin, lo - pad);
    tMax = std::min(tMax, hi + pad);
}

}  // namespace

namespace {

// cutaway_textures: the surface of leaf k, without a texture of its own, shows the textured leaf
// holding the hit point p (its texture evaluated there); where two or more hold it, their textures
// averaged (measured with POV-Ray 3.7: a cut inside a red box and a blue sphere is (0.5, 0, 0.5)
// linear): the first becomes the part and the tracer finds them all again (shadePovCutaway).
void cutawayPart(const Csg& c, int k, Vec3 p, ShapeHit& h) {
    if (!c.cutaway || size_t(k) >= c.leafTextured.size() || c.leafTextured[size_t(k)]) return;
    bool found = false;
    for (size_t j = 0; j < c.leaves.size() && j < c.leafTextured.size(); ++j)
        if (int(j) != k && c.leafTextured[j] && insideShape(c.leaves[j], p) > 0) {
            if (found) {
                h.cutawayBlend = true;
                return;
            }
            h.part = &c.leaves[j];
            found = true;
        }
}

// Whether the ray passes POV-Ray's bounded_by test of gate g: it starts inside g or meets it at
// some t > 0, whatever the range the caller asks about (measured with POV-Ray 3.7: objects seen
// only through the rays that cross their too-small bound, and whole beyond it).
bool meetsGate(const Csg& g, const Ray& ray) {
    return insideCsg(g, 0, ray.origin) || intersectCsg(g, ray, 1e-9, kInfinity, nullptr);
}

}  // namespace

bool intersectCsg(const Csg& c, const Ray& ray, double tMin, double tMax, ShapeHit* hit) {
    if (c.gate && !meetsGate(*c.gate, ray)) return false;
    const int n = int(c.leaves.size());
    // A tree with a box tree over its leaves keeps no cache: the walk asks the box tree instead.
    const bool walkTree = n > kCsgCachedLeaves && !c.leafTree.empty();
    const int cached = std::min(n, kCsgCachedLeaves);
    const Vec3 invDir{1 / ray.dir.x, 1 / ray.dir.y, 1 / ray.dir.z};
    // Leaf i's hits are sought only where the ray is within its window and the convex leaves it
    // must be inside (csg.h).
    double winLo[kCsgCachedLeaves], winHi[kCsgCachedLeaves];
    // The convex leaves' inside spans along this ray, each found once (a leaf clips the windows of
    // all the others of its intersection): 0 not yet, 1 found, −1 the ray misses it.
    signed char spanState[kCsgCachedLeaves];
    double spanLo[kCsgCachedLeaves], spanHi[kCsgCachedLeaves];
    if (!c.clipList.empty()) std::fill(spanState, spanState + cached, static_cast<signed char>(0));
    auto clipToWindow = [&](int i, double& lo, double& hi) {
        clipToBox(c.leafWindow[size_t(i)], ray, invDir, lo, hi);
        for (int j = c.clipStart[size_t(i)]; j < c.clipStart[size_t(i) + 1] && lo < hi; ++j) {
            const int k = c.clipList[size_t(j)];
            const bool inverse = c.nodes[size_t(c.leafNode[size_t(k)])].inverse;
            if (k >= cached) {
                insideInterval(c.leaves[size_t(k)], inverse, ray, lo, hi);
                continue;
            }
            if (spanState[k] == 0)
                spanState[k] = insideSpan(c.leaves[size_t(k)], inverse, ray, spanLo[k], spanHi[k]) ? 1 : -1;
            if (spanState[k] < 0) {
                hi = lo;
            } else {
                lo = std::max(lo, spanLo[k]);
                hi = std::min(hi, spanHi[k]);
            }
        }
    };
    auto window = [&](int i, double& lo, double& hi) {
        if (i < cached) {
            lo = winLo[i], hi = winHi[i];
            return;
        }
        lo = tMin, hi = tMax;
        if (c.hasSurface[size_t(i)]) clipToWindow(i, lo, hi);
        else hi = lo;
    };
    // Leaf i's nearest hit in (from, to) within its window (lo, hi).
    auto solve = [&](int i, double lo, double hi, double from, double to, ShapeHit& h) {
        lo = std::max(lo, from), hi = std::min(hi, to);
        if (!(lo < hi)) return false;
        // Meshes keep the whole interval: their float traversal may miss a hit on a sliver of it
        // (a flat mesh's window is one).
        const Object& leaf = c.leaves[size_t(i)];
        if (leaf.type == ShapeType::Mesh || leaf.type == ShapeType::Triangle) lo = from, hi = to;
        return intersect(leaf, ray, lo, hi, h);
    };
    auto hitLeaf = [&](int i, double from, double to, ShapeHit& h) {
        double lo, hi;
        window(i, lo, hi);
        return solve(i, lo, hi, from, to, h);
    };
    // The same with the window found afresh (the walk over the box tree keeps no cache).
    auto hitWide = [&](int i, double from, double to, ShapeHit& h) {
        double lo = tMin, hi = tMax;
        clipToWindow(i, lo, hi);
        return solve(i, lo, hi, from, to, h);
    };
    // The hit on leaf best at the nearest hit after `from`, found on the tree's surface: the same
    // test again, for the normals, flipped for subtracted or inverted parts.
    auto take = [&](int best, double from, bool flip) {
        const Object& leaf = c.leaves[size_t(best)];
        if (!(walkTree ? hitWide(best, from, tMax, *hit) : hitLeaf(best, from, tMax, *hit))) return false;
        if (flip) {
            hit->normal = -hit->normal;
            hit->geomNormal = -hit->geomNormal;
        }
        if (!hit->part) hit->part = &leaf;  // a blob's component texture stays
        cutawayPart(c, best, ray.at(hit->t), *hit);
        return true;
    };
    ShapeHit sh;
    if (walkTree) {
        // Many leaves: the nearest leaf hit after the last one taken comes from the box tree over
        // the leaves' windows (a tie with a taken hit is lost, as for the leaves beyond the cache).
        double tLast = tMin;
        for (;;) {
            int best = -1;
            double bestT = tMax;
            c.leafTree.alongRay(ray, invDir, tLast, bestT, [&](int i, double& hi) {
                if (hitWide(i, tLast, hi, sh)) best = i, hi = sh.t;
            });
            if (best < 0) return false;
            bool flip = false;
            if (onSurface(c, best, ray.at(bestT), flip)) return !hit || take(best, tLast, flip);
            tLast = bestT;
        }
    }
    double nextT[kCsgCachedLeaves];  // leaf i's nearest hit after from[i] (infinite: none)
    double from[kCsgCachedLeaves];
    // The first leaves' hits themselves, kept when the caller wants the surface's normals: the hit
    // taken is then the one already found, not found again (a quartic's or a lathe's roots twice).
    // Unconstructed until a leaf's search writes its slot.
    union HitSlot {
        ShapeHit h;
        HitSlot() {}
    };
    HitSlot kept[kCsgKeptHits];
    const int keep = hit ? std::min(cached, kCsgKeptHits) : 0;
    auto nextHit = [&](int i, double after) {
        ShapeHit& h = i < keep ? *new (&kept[i].h) ShapeHit{} : sh;
        return hitLeaf(i, after, tMax, h) ? h.t : kInfinity;
    };
    for (int i = 0; i < cached; ++i) {
        winLo[i] = tMin, winHi[i] = tMax;
        if (c.hasSurface[size_t(i)]) clipToWindow(i, winLo[i], winHi[i]);
        else winHi[i] = winLo[i];
        from[i] = tMin;
        nextT[i] = nextHit(i, tMin);
    }
    double tLast = tMin;  // the hits taken so far lie at or before it
    for (;;) {
        int best = -1;
        double bestT = tMax, bestFrom = tLast;
        for (int i = 0; i < cached; ++i)
            if (nextT[i] < bestT) best = i, bestT = nextT[i];
        for (int i = cached; i < n; ++i)  // beyond the cache: recomputed (a tie with a taken hit is lost)
            if (hitLeaf(i, tLast, bestT, sh)) best = i, bestT = sh.t;
        if (best < 0) return false;
        if (best < cached) bestFrom = from[best];
        bool flip = false;
        if (onSurface(c, best, ray.at(bestT), flip)) {
            if (!hit) return true;
            if (best >= keep) return take(best, bestFrom, flip);  // bestT: the nearest after bestFrom
            *hit = kept[best].h;
            if (flip) {
                hit->normal = -hit->normal;
                hit->geomNormal = -hit->geomNormal;
            }
            if (!hit->part) hit->part = &c.leaves[size_t(best)];
            cutawayPart(c, best, ray.at(hit->t), *hit);
            return true;
        }
        tLast = bestT;
        if (best < cached) {
            from[best] = bestT;
            nextT[best] = nextHit(best, bestT);
        }
    }
}

}  // namespace rays
