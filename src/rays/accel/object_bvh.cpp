// ObjectBvh construction: padded float boxes -> binned SAH binary BVH -> 8-wide nodes + blocks of
// four object slots with their bounding spheres.
#include "rays/accel/object_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rays/accel/wide_collapse.h"

namespace rays {
namespace {

using namespace tribvh;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr uint32_t kParallelBuild = 65536;  ///< objects from which the build uses all cores

// Float box containing [lo, hi] with a margin for the float rounding of the ray (origin and
// inverse direction) in the box test.
void paddedBox(const ObjectBvh::Prim& p, PrimRef& r) {
    for (int a = 0; a < 3; ++a) {
        const double ext = p.hi[a] - p.lo[a];
        const double pad = 1e-6 * (ext + std::max(std::fabs(p.lo[a]), std::fabs(p.hi[a]))) + 1e-30;
        r.lo[a] = std::nextafter(float(p.lo[a] - pad), -kInf);
        r.hi[a] = std::nextafter(float(p.hi[a] + pad), kInf);
    }
}

// Bounding sphere of a slot for the reject test, or radius +inf when there is none or when its
// numbers are too large for the single-precision test to be trusted.
void sphereSlot(const ObjectBvh::Prim& p, objbvh::ShapeBlock& b, int lane) {
    double size = p.sphereRadius;
    for (int a = 0; a < 3; ++a) size += std::fabs(p.center[a]);
    const bool usable = p.sphereRadius >= 0 && std::isfinite(size) && size < 1e15;
    b.cx[lane] = usable ? float(p.center[0]) : 0.0f;
    b.cy[lane] = usable ? float(p.center[1]) : 0.0f;
    b.cz[lane] = usable ? float(p.center[2]) : 0.0f;
    // Rounded up, and the margin covers float rounding of the centre, the ray origin and every
    // step of the test with a factor of several hundred to spare (see object_bvh_traverse.h).
    b.radius[lane] = usable ? std::nextafter(float(p.sphereRadius), kInf) : kInf;
    b.margin[lane] = usable ? float(0x1p-12 * size) : 0.0f;
}

}  // namespace

void ObjectBvh::build(const std::vector<Prim>& prims) {
    nodes_.clear();
    blocks_.clear();
    spheres_.clear();
    anySphere_ = false;
    if (prims.empty()) return;
    if (prims.size() > kMaxBlockIndex) throw std::length_error("too many objects for the BVH");
    TaskPool pool(prims.size() >= kParallelBuild ? 0 : 1);

    HugeArray<PrimRef> refs(prims.size());
    for (size_t i = 0; i < prims.size(); ++i) {
        paddedBox(prims[i], refs[i]);
        refs[i].id = uint32_t(i);
        refs[i].pad = 0;
    }
    const WideTree tree = buildWideTree(refs, pool, nodes_);

    blocks_.resize(tree.blockCount);
    spheres_.assign(blocks_.size() * kBlockSize, ExactSphere{{0, 0, 0}, -1});
    for (const Collapser::LeafJob& job : tree.leaves) {
        for (uint32_t k = 0; k < job.count; k += kBlockSize) {
            objbvh::ShapeBlock& b = blocks_[job.firstBlock + k / kBlockSize];
            for (uint32_t lane = 0; lane < uint32_t(kBlockSize); ++lane) {
                if (k + lane >= job.count) {  // unused: a NaN radius fails every comparison
                    b.cx[lane] = b.cy[lane] = b.cz[lane] = b.margin[lane] = 0.0f;
                    b.radius[lane] = std::numeric_limits<float>::quiet_NaN();
                    b.id[lane] = UINT32_MAX;
                    continue;
                }
                const Prim& p = prims[refs[job.firstRef + k + lane].id];
                sphereSlot(p, b, int(lane));
                anySphere_ = anySphere_ || std::isfinite(b.radius[lane]);
                b.id[lane] = p.id;
                spheres_[size_t(job.firstBlock + k / kBlockSize) * kBlockSize + lane] = exactSphere(p);
            }
        }
    }
}

int ObjectBvh::depth() const {
    if (nodes_.empty()) return 0;
    struct Item {
        uint32_t node;
        int depth;
    };
    int deepest = 0;
    std::vector<Item> stack{{0, 1}};
    while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        deepest = std::max(deepest, it.depth);
        const WideNode& n = nodes_[it.node];
        for (uint32_t i = 0; i < n.childCount; ++i)
            if (!isLeaf(n.child[i])) stack.push_back({n.child[i], it.depth + 1});
    }
    return deepest;
}

}  // namespace rays
