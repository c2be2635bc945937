// TriangleBvh construction: triangle boxes -> binned SAH binary BVH -> 8-wide nodes + SoA
// triangle blocks. Traversal lives in triangle_bvh_traverse.cpp.
#include "rays/accel/triangle_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include "rays/accel/binned_sah.h"
#include "rays/accel/task_pool.h"
#include "rays/accel/wide_collapse.h"

namespace rays {
namespace {

using namespace tribvh;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr uint32_t kPrepChunk = 16384;

}  // namespace

void TriangleBvh::build(const float* positions, size_t vertexCount, const uint32_t* indices, size_t triangleCount,
                        int threads) {
    nodes_.clear();
    blocks_.clear();
    triangles_ = 0;
    for (int a = 0; a < 3; ++a) {
        lo_[a] = kInf;
        hi_[a] = -kInf;
    }
    if (triangleCount == 0 || positions == nullptr || indices == nullptr) return;
    if (triangleCount > kMaxBlockIndex) throw std::length_error("TriangleBvh: too many triangles");

    // Small inputs are built on the calling thread: starting threads would cost more than it saves.
    if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
    threads = int(std::min<size_t>(size_t(threads), std::max<size_t>(1, triangleCount / 16384)));
    TaskPool pool(threads);

    // Triangle boxes; degenerate (zero-area, computed in double) and non-finite triangles are
    // marked and dropped.
    HugeArray<PrimRef> refs(triangleCount);
    std::vector<uint8_t> valid(triangleCount);
    const size_t chunks = (triangleCount + kPrepChunk - 1) / kPrepChunk;
    pool.run(chunks, [&](size_t c) {
        const size_t end = std::min(triangleCount, (c + 1) * kPrepChunk);
        for (size_t i = c * kPrepChunk; i < end; ++i) {
            const uint32_t* idx = indices + 3 * i;
            PrimRef& r = refs[i];
            r.id = uint32_t(i);
            r.pad = 0;
            valid[i] = 0;
            if (idx[0] >= vertexCount || idx[1] >= vertexCount || idx[2] >= vertexCount) continue;
            const float* p[3] = {positions + 3 * size_t(idx[0]), positions + 3 * size_t(idx[1]),
                                 positions + 3 * size_t(idx[2])};
            bool finite = true;
            for (int a = 0; a < 3; ++a) {
                r.lo[a] = std::min({p[0][a], p[1][a], p[2][a]});
                r.hi[a] = std::max({p[0][a], p[1][a], p[2][a]});
                finite = finite && std::isfinite(p[0][a]) && std::isfinite(p[1][a]) && std::isfinite(p[2][a]);
            }
            if (!finite) continue;
            double e1[3], e2[3];
            for (int a = 0; a < 3; ++a) {
                e1[a] = double(p[1][a]) - double(p[0][a]);
                e2[a] = double(p[2][a]) - double(p[0][a]);
            }
            const double nx = e1[1] * e2[2] - e1[2] * e2[1];
            const double ny = e1[2] * e2[0] - e1[0] * e2[2];
            const double nz = e1[0] * e2[1] - e1[1] * e2[0];
            valid[i] = (nx != 0.0 || ny != 0.0 || nz != 0.0) ? 1 : 0;
        }
    });
    size_t n = 0;
    for (size_t i = 0; i < triangleCount; ++i)
        if (valid[i]) refs[n++] = refs[i];
    refs.truncate(n);
    valid = {};
    if (n == 0) return;

    const WideTree tree = buildWideTree(refs, pool, nodes_);
    for (int a = 0; a < 3; ++a) {
        lo_[a] = tree.lo[a];
        hi_[a] = tree.hi[a];
    }

    // Triangle blocks, in parallel (each leaf writes only its own blocks).
    blocks_.resize(tree.blockCount);
    const std::vector<Collapser::LeafJob>& jobs = tree.leaves;
    const size_t jobChunk = 4096;
    pool.run((jobs.size() + jobChunk - 1) / jobChunk, [&](size_t c) {
        const size_t end = std::min(jobs.size(), (c + 1) * jobChunk);
        for (size_t j = c * jobChunk; j < end; ++j) {
            const Collapser::LeafJob& job = jobs[j];
            for (uint32_t k = 0; k < job.count; k += kBlockSize) {
                TriBlock& b = blocks_[job.firstBlock + k / kBlockSize];
                for (uint32_t lane = 0; lane < uint32_t(kBlockSize); ++lane) {
                    const bool used = k + lane < job.count;
                    // Unused lanes: a zero-area triangle at the block's first vertex.
                    const uint32_t tri = refs[job.firstRef + (used ? k + lane : k)].id;
                    const uint32_t* idx = indices + 3 * size_t(tri);
                    for (int vtx = 0; vtx < 3; ++vtx) {
                        const float* p = positions + 3 * size_t(idx[used ? vtx : 0]);
                        for (int a = 0; a < 3; ++a) b.v[vtx][a][lane] = p[a];
                    }
                    b.prim[lane] = used ? tri : UINT32_MAX;
                }
            }
        }
    });
    triangles_ = n;
}

size_t TriangleBvh::memoryBytes() const {
    return hugeFootprint(nodes_.capacity() * sizeof(WideNode)) + hugeFootprint(blocks_.capacity() * sizeof(TriBlock));
}

void TriangleBvh::bounds(float lo[3], float hi[3]) const {
    for (int a = 0; a < 3; ++a) {
        lo[a] = lo_[a];
        hi[a] = hi_[a];
    }
}

TriangleBvh::Stats TriangleBvh::stats() const {
    Stats s;
    s.nodes = nodes_.size();
    s.blocks = blocks_.size();
    s.triangles = triangles_;
    if (nodes_.empty()) return s;
    auto area = [](const WideNode& n, int i) {
        const float dx = n.box[1][i] - n.box[0][i], dy = n.box[3][i] - n.box[2][i], dz = n.box[5][i] - n.box[4][i];
        return double(dx) * (double(dy) + double(dz)) + double(dy) * double(dz);
    };
    const double rootArea = [&] {
        const float dx = hi_[0] - lo_[0], dy = hi_[1] - lo_[1], dz = hi_[2] - lo_[2];
        return std::max(1e-30, double(dx) * (double(dy) + double(dz)) + double(dy) * double(dz));
    }();
    struct Item {
        uint32_t node;
        int depth;
        double area;
    };
    std::vector<Item> stack{{0, 1, rootArea}};
    while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        s.depth = std::max(s.depth, it.depth);
        s.sahCost += it.area / rootArea;  // one node visit (8 boxes)
        const WideNode& n = nodes_[it.node];
        for (uint32_t i = 0; i < n.childCount; ++i) {
            const uint32_t ref = n.child[i];
            if (isLeaf(ref)) {
                ++s.leaves;
                s.sahCost += area(n, int(i)) / rootArea * leafBlockCount(ref);
            } else {
                stack.push_back({ref, it.depth + 1, area(n, int(i))});
            }
        }
    }
    return s;
}

}  // namespace rays
