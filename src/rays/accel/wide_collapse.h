// Collapsing a binary BVH (binned_sah.h) into 8-wide nodes (triangle_bvh_layout.h), shared by the
// triangle BVH and the object BVH: both store leaves as consecutive blocks of kBlockSize primitives.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "rays/accel/binned_sah.h"
#include "rays/accel/huge_pages.h"
#include "rays/accel/task_pool.h"
#include "rays/accel/triangle_bvh_layout.h"

namespace rays::tribvh {

/// Collapses a binary BVH into 8-wide nodes, choosing which binary nodes become wide nodes so
/// that the total surface area of the wide nodes is least (each wide node holding at most eight
/// children): a dynamic programme over the binary tree, bottom up, of the least cost of each
/// subtree when it may fill 1..8 slots of its parent (the SAH-optimal collapse of Ylitie, Karras
/// and Laine 2017, without leaf merging: the leaves stay those of the binary tree). Sibling nodes
/// are stored contiguously; leaves get consecutive blocks in depth-first order.
class Collapser {
public:
    using Slots = std::array<float, kWidth>;
    struct LeafJob {
        uint32_t firstBlock, firstRef, count;
    };

    using NodeVector = std::vector<WideNode, HugePageAllocator<WideNode>>;
    Collapser(const BinaryBvh& bin, NodeVector& nodes, uint32_t leafBlockCap)
        : bin_(bin), nodes_(nodes), leafBlockCap_(leafBlockCap) {}

    /// Collapses; with a pool of several threads the costs of the subtrees below the top levels
    /// are computed side by side (the nodes are the same).
    void run(TaskPool* pool = nullptr);
    std::vector<LeafJob> leaves;
    uint32_t blockCount = 0;

private:
    void fill(uint32_t w, uint32_t b);
    void costs(uint32_t n);
    void costsInParallel(TaskPool& pool);
    void nodeCosts(uint32_t n);
    const Slots& slots(uint32_t n) const;
    float split(uint32_t n, int j, int& leftSlots) const;
    void gather(uint32_t n, int k, uint32_t* kids, int& count) const;

    const BinaryBvh& bin_;
    NodeVector& nodes_;
    uint32_t leafBlockCap_;
    HugeArray<Slots> cost_;  ///< per inner binary node: least cost of its subtree in at most 1..8 slots
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
