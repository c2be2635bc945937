// SceneBuilder's CSG: intersection, difference, merge and clipped objects as csg trees (scene/csg.h).

#include "rays/pov/grammar.h"
#include "rays/pov/scene_builder.h"
#include "rays/pov/scene_builder_parts.h"

namespace rays::pov {

using sdl::VType;

// ---- CSG ------------------------------------------------------------------------------------

// The children of a CSG node (op from kind) under csgParent_. A child not rendered leaves an
// intersection empty, and a difference whose first child it is; a union or merge, or a
// difference losing a subtracted child, is drawn without it.
void SceneBuilder::addCsgChildren(Kw kind, bool inverse, const std::vector<const Item*>& children,
                                  const Transform& toWorld, const Appearance* own, int depth) {
    const CsgOp op = kind == Kw::difference ? CsgOp::Difference
                     : kind == Kw::intersection ? CsgOp::Intersection
                     : kind == Kw::merge        ? CsgOp::Merge
                                                : CsgOp::Union;
    const int node = csg_->add(csgParent_, op, inverse);
    const int outer = csgParent_;
    // Room for a leaf per child at once (a leaf is a whole Object: growing one at a time copied
    // them again and again), growing at least twofold so that nested operations stay linear.
    if (csg_->leaves.capacity() < csg_->leaves.size() + children.size())
        csg_->leaves.reserve(std::max(csg_->leaves.size() + children.size(), 2 * csg_->leaves.capacity()));
    bool empty = false;
    for (size_t i = 0; i < children.size(); ++i) {
        csgParent_ = node;
        const size_t before = csg_->nodes.size();  // what the child adds goes under node
        addObject(*children[i], toWorld, own, depth + 1);
        const bool lost = csg_->nodes.size() == before;
        empty = empty || (lost && (op == CsgOp::Intersection || (op == CsgOp::Difference && i == 0)));
    }
    csgParent_ = outer;
    if (empty) csg_->nodes[size_t(node)].op = CsgOp::Empty;
}

// The objects of a clipped_by block under csgParent_ (the clip node); `clipped_by { bounded_by }`
// takes the objects of the bounded_by block.
void SceneBuilder::addClippers(const Entry& clip, const Entry* bounds, const Transform& toWorld, int depth) {
    const int node = csgParent_;
    for (const Value& v : clip.args) {
        if (v.type != VType::Item) continue;
        for (const Entry& e : v.item().entries) {
            if (!e.positional() && e.key != kMapEntry && e.kw() == Kw::bounded_by && bounds && bounds != &clip) {
                addClippers(*bounds, nullptr, toWorld, depth);
                continue;
            }
            for (const Value& a : e.args)
                if (a.type == VType::Item && isObjectKind(a.item().kind)) {
                    csgParent_ = node;
                    addObject(a.item(), toWorld, nullptr, depth + 1);
                }
        }
    }
    csgParent_ = node;
}

// Whether a camera ray may start inside one of the tree's leaves: the camera read so far is a
// perspective one without focal blur and its location is outside every leaf, or not. A merge read
// before any camera, or under a camera whose rays start across a window (orthographic, mesh and
// the other projections) or round its location (focal blur), keeps its tree.
bool SceneBuilder::cameraMayStartInside(const Csg& tree) const {
    if (scene_.cameras.empty()) return true;
    const Camera& c = scene_.cameras.front();
    if (c.projection != Projection::Perspective || c.aperture > 0) return true;
    for (const Object& leaf : tree.leaves)
        if (insideShape(leaf, c.location) != 0) return true;  // inside, or no inside to ask (-1)
    return false;
}

// A finished CSG tree becomes one object, unless it needs the inside of a triangle or mesh (they
// have none) or can never be seen.
void SceneBuilder::finishCsg(Csg&& tree, Kw kind, const sdl::Loc& at) {
    if (tree.leaves.empty()) return;
    for (size_t k = 0; k < tree.leaves.size(); ++k)
        if (insideShape(tree.leaves[k], Vec3{}) < 0 && tree.needsInside(int(k))) {
            notes_.note(std::string(sdl::keywordName(kind)) + " of triangles or meshes", at, "(left out)");
            return;
        }
    // An opaque merge looks as a union does from outside (its inner surfaces are hidden): its
    // children become objects of their own, in the scene's BVH. Not where a camera ray may start
    // inside it, where the inner surfaces would show (measured with POV-Ray 3.7: from inside two
    // overlapping spheres it shows only their outer boundary).
    bool unionLike = true, merge = false;
    for (const CsgNode& n : tree.nodes) {
        unionLike = unionLike && !n.inverse && (n.op == CsgOp::Leaf || n.op == CsgOp::Union || n.op == CsgOp::Merge);
        merge = merge || n.op == CsgOp::Merge;
    }
    for (const Object& leaf : tree.leaves)
        unionLike = unionLike && leaf.material.filter == 0 && scene_.povSurfaces[size_t(leaf.material.pov)].transmit == 0;
    if (unionLike && merge && cameraMayStartInside(tree)) unionLike = false;
    if (unionLike && !tree.gate) {  // a bounded_by gate needs the tree
        for (const Object& leaf : tree.leaves) scene_.objects.push_back(leaf);
        return;
    }
    tree.finish();
    if (tree.boundsEmpty()) return;
    Object o;
    o.type = ShapeType::Csg;
    o.line = int(at.line);
    o.col = int(at.col);
    o.material = tree.leaves[0].material;
    for (size_t k = 0; k < tree.leaves.size(); ++k)
        if (tree.hasSurface[k]) {
            o.material = tree.leaves[k].material;  // the interior a ray inside it is in
            break;
        }
    scene_.csgs.push_back(std::make_unique<Csg>(std::move(tree)));
    o.csg = scene_.csgs.back().get();
    prepareObject(o, Transform{});
    scene_.objects.push_back(o);
}

}  // namespace rays::pov
