// Collapsing a binary BVH (binned_sah.h) into 8-wide nodes (triangle_bvh_layout.h), shared by the
// triangle BVH and the object BVH: both store leaves as consecutive blocks of kBlockSize primitives.
#pragma once

#include <cstdint>
#include <vector>

#include "rays/accel/binned_sah.h"
#include "rays/accel/huge_pages.h"
#include "rays/accel/task_pool.h"
#include "rays/accel/triangle_bvh_layout.h"

namespace rays::tribvh {

/// Collapses a binary BVH into 8-wide nodes: starting from a node's two children, the child with
/// the largest surface area is repeatedly replaced by its own children until there are eight
/// (or only leaves). Sibling nodes are stored contiguously; leaves get consecutive blocks in
/// depth-first order.
class Collapser {
public:
    struct LeafJob {
        uint32_t firstBlock, firstRef, count;
    };

    using NodeVector = std::vector<WideNode, HugePageAllocator<WideNode>>;
    Collapser(const BinaryBvh& bin, NodeVector& nodes, uint32_t leafBlockCap)
        : bin_(bin), nodes_(nodes), leafBlockCap_(leafBlockCap) {}

    void run();
    std::vector<LeafJob> leaves;
    uint32_t blockCount = 0;

private:
    void fill(uint32_t w, uint32_t b);

    const BinaryBvh& bin_;
    NodeVector& nodes_;
    uint32_t leafBlockCap_;
};

/// The result of buildWideTree besides the nodes: where each leaf's primitives go and the bounds.
struct WideTree {
    std::vector<Collapser::LeafJob> leaves;  ///< block ranges per leaf, refs ranges in leaf order
    uint32_t blockCount = 0;
    float lo[3], hi[3];  ///< bounds of all refs
};

/// Builds the 8-wide tree over refs (non-empty; reordered): binned SAH with leaves of at most
/// kBlockSize primitives (one block), collapsed into nodes.
WideTree buildWideTree(HugeArray<PrimRef>& refs, TaskPool& pool, Collapser::NodeVector& nodes);

}  // namespace rays::tribvh
