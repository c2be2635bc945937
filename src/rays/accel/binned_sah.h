// Binned SAH builder (Wald 2007) producing a binary BVH over primitive boxes. The surface area
// heuristic counts primitives in blocks (the leaves are intersected blockSize at a time with
// SIMD), splits are chosen among 8-32 planes per axis (more for larger ranges) over the centroid
// bounds, and leaves hold at most maxLeafSize primitives. Ranges deeper than 56 levels are split
// at the object median, which bounds the depth (traversal stacks are fixed-size).
//
// Threads: the upper levels are processed one range at a time, binned and partitioned
// data-parallel over fixed-size chunks (each chunk partitioned in place, then misplaced runs
// swapped k-th with k-th); the subtrees below are then built as independent tasks, largest first.
// Chunk boundaries, merge order and the partition algorithm depend only on the range sizes,
// never on the thread count, so the tree (and the order of the primitive references) is the same
// for any number of threads. Node indices may differ; only the tree structure is meaningful.
#pragma once

#include <cstdint>

#include "rays/accel/huge_pages.h"
#include "rays/accel/task_pool.h"

namespace rays::tribvh {

/// A primitive's box and index, 32 bytes (two 16-byte rows for SIMD loads).
struct alignas(32) PrimRef {
    float lo[3];
    uint32_t id;
    float hi[3];
    uint32_t pad;
};

struct BinaryNode {
    float lo[3], hi[3];
    uint32_t first;  ///< leaf: first PrimRef; inner node: left child (right child = first + 1)
    uint32_t count;  ///< leaf: number of primitives (> 0); inner node: 0
    bool leaf() const { return count != 0; }
    float halfArea() const;
};

struct SahSettings {
    uint32_t blockSize = 4;      ///< leaves are intersected this many primitives at a time
    uint32_t maxLeafSize = 4;    ///< hard cap on primitives per leaf
    float traversalCost = 1.0f;  ///< cost of a node visit relative to intersecting one block
};

struct BinaryBvh {
    HugeArray<BinaryNode> nodes;
    uint32_t root = 0;
};

/// Builds over refs (non-empty; reordered so that each leaf references a contiguous range).
BinaryBvh buildBinnedSah(HugeArray<PrimRef>& refs, const SahSettings& settings, TaskPool& pool);

}  // namespace rays::tribvh
