// Constructive solid geometry of POV-Ray scenes (reference 3.4.5.4 "Constructive Solid Geometry",
// 3.4.5.5.1 "Clipped By"): a tree of union, merge, intersection, difference and clip nodes over
// primitive objects (leaves), each with its own world transform and material. A scene object of
// type ShapeType::Csg points at one tree (owned by the Scene).
//
// A ray's hits are found exactly by walking the leaves' surface hits along the ray in order (each
// leaf's next hit is cached, so every leaf is intersected once per hit it contributes) and keeping
// the first that lies on the tree's surface: going up from the hit leaf, a union keeps every
// surface of its children (POV-Ray keeps a union's inner surfaces), a merge keeps those outside
// its other children, an intersection those inside all of them, a difference those of its first
// child outside the rest and those of the rest inside the first and outside the others, a clip
// node those of its object inside all its clipping objects (the clipping objects have no
// surface of their own). Each leaf is intersected only on the stretch of the ray inside its
// window (Csg::leafWindow), so a clipped unbounded surface (a poly clipped by a cylinder and two
// planes) is solved on the clip's box alone, not along the whole ray. No heap allocation or
// virtual call per ray: the walk keeps the next hits of the first kCachedLeaves leaves on the
// stack and recomputes those of the others at each step; the inside tests recurse at most as deep
// as the tree.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "rays/scene/csg_box_tree.h"
#include "rays/scene/object.h"

namespace rays {

enum class CsgOp : unsigned char {
    Leaf,          ///< one primitive object (Csg::leaves[leaf])
    Union,         ///< inside any child; every child surface is kept
    Merge,         ///< inside any child; surfaces inside another child are removed
    Intersection,  ///< inside all children
    Difference,    ///< inside the first child and outside the others
    Clip,          ///< the first child's surface where it is inside all other children (clipped_by)
    Empty,         ///< nothing (a CSG whose needed child was not rendered)
};

struct CsgNode {
    CsgOp op = CsgOp::Leaf;
    bool inverse = false;      ///< `inverse`: inside and outside swapped
    int32_t parent = -1;       ///< -1 for the root (node 0)
    int32_t firstChild = -1, lastChild = -1, nextSibling = -1;
    int32_t leaf = -1;         ///< Leaf only: index into Csg::leaves
};

struct Csg {
    /// POV-Ray's `bounded_by` on the object (scene_builder.cpp says on which kinds): a ray that
    /// neither starts inside this tree nor meets it anywhere along its length does not see the
    /// object, even where the object reaches beyond it. Null when there is none.
    std::shared_ptr<const Csg> gate;
    /// POV-Ray's `cutaway_textures` on the tree: a surface of a leaf without a texture of its own
    /// shows the texture of the first textured leaf holding the hit point (reference,
    /// "Cutaway Textures"; where several do, POV-Ray averages them and Rays takes the first).
    bool cutaway = false;
    std::vector<unsigned char> leafTextured;  ///< per leaf: a texture was given to it or above it
    std::vector<CsgNode> nodes;   ///< node 0 is the root
    std::vector<Object> leaves;   ///< primitives in world space (prepared), with their materials
    std::vector<int32_t> leafNode;  ///< node of each leaf
    std::vector<unsigned char> hasSurface;  ///< per leaf: may its surface be seen (not a clipping object)
    /// Per leaf: its window, the box where its surface can be part of the tree's surface: its world
    /// box (all space for planes and polys; a quadric's inside box) met with the bounds of every
    /// node above it, slightly widened. The walk seeks the leaf's hits only where the ray is in it.
    std::vector<Bounds> leafWindow;
    /// Per leaf k: the convex leaves (planes, spheres, boxes, ellipsoid and cylinder quadrics) whose
    /// inside the tree asks k's surface to be in (the other children of an intersection or clip
    /// above k, the first child of a difference that subtracts k), as leaf indices
    /// clipList[clipStart[k] .. clipStart[k + 1]): the walk seeks k's hits only on the stretch of the
    /// ray within all of them (Roth, "Ray casting for modeling solids", 1982: a ray's intervals in
    /// the solids of an intersection are intersected). Each such stretch is found once per ray and
    /// shared by the leaves it clips (`advanced/chess2.pov`, intersections of about ten convex
    /// leaves: render 960 → 840 ms at 160×120).
    std::vector<int32_t> clipStart, clipList;
    /// Trees with more than kCsgCachedLeaves leaves: a box tree over the leaves' windows, which
    /// the walk asks for the nearest leaf hit (csg_box_tree.h).
    CsgBoxTree leafTree;
    /// Per node: its children's box tree in childTrees (union, merge and difference nodes with at
    /// least kCsgWideNode children), or -1. Inside tests ask it which children may hold a point.
    std::vector<int32_t> childTree;
    std::vector<CsgBoxTree> childTrees;
    Bounds bounds;                ///< world bounds; components may be infinite (planes)

    /// Appends a node under parent (-1: the root) and returns its index.
    int add(int parent, CsgOp op, bool inverse);
    /// Appends leaf object o (prepared, world space) under parent; returns its node.
    int addLeaf(int parent, const Object& o, bool inverse);
    /// True when the tree asks whether a point is inside leaf k (some ancestor other than a union
    /// or, for the clipped object, a clip node).
    bool needsInside(int k) const;
    /// Number of children of node n.
    int childCount(int n) const;
    /// Call once the tree is complete: sets hasSurface and the bounds (intersection → the
    /// children's boxes intersected, difference → the first child's, union and merge → their
    /// union, axis-aligned planes → half-spaces, anything inverted → all space).
    void finish();
    void buildBoxTrees(const std::vector<Bounds>& nb);  ///< part of finish()
    /// True when the bounds hold no point (the object can never be seen).
    bool boundsEmpty() const;
};

/// Leaves whose next hits the walk keeps on the stack; the hits of further leaves are recomputed
/// at every step of the walk (correct, slower).
constexpr int kCsgCachedLeaves = 128;
/// Of those, the first ones whose hits intersectCsg keeps for the normals of the hit it returns.
constexpr int kCsgKeptHits = 8;
/// Nodes with this many children or more get a box tree over them (Csg::childTree).
constexpr int kCsgWideNode = 8;

/// Whether world point q is strictly inside solid primitive o: 1 or 0; -1 when o has no inside
/// (triangles, meshes). A plane's inside is the side its normal points away from; open cones
/// and cylinders keep the inside of the closed solid.
int insideShape(const Object& o, Vec3 q);

/// Whether world point q is inside node n of c.
bool insideCsg(const Csg& c, int n, Vec3 q);

/// Nearest hit of the world ray on c's surface with t in (tMin, tMax); the hit's normal is the
/// CSG's outward normal there (a leaf's normal flipped for subtracted or inverted parts) and
/// hit.part the leaf. hit may be null (shadow rays: no normal).
bool intersectCsg(const Csg& c, const Ray& worldRay, double tMin, double tMax, ShapeHit* hit);

}  // namespace rays
