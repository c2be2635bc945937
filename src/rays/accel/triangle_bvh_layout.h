// Memory layout of TriangleBvh: 8-wide nodes with SoA child boxes, and leaves made of blocks of
// 4 triangles stored SoA (vertex positions, ready for a 4-wide watertight intersection test).
//
// A child reference (uint32_t) is either
//   - an inner node: its index into the node array (bit 31 clear), or
//   - a leaf: bit 31 set, bits 28..30 = number of triangle blocks - 1, bits 0..27 = first block.
// Unused child slots have an empty box (lo = +inf, hi = -inf) that no ray can enter.
#pragma once

#include <cstdint>

namespace rays::tribvh {

constexpr int kWidth = 8;             ///< children per node
constexpr int kBlockSize = 4;         ///< triangles per leaf block
constexpr int kMaxLeafBlocks = 8;     ///< representable blocks per leaf
constexpr uint32_t kLeafFlag = 0x80000000u;
constexpr uint32_t kMaxBlockIndex = (1u << 28) - 1;

struct alignas(64) WideNode {
    uint32_t child[kWidth];
    uint32_t childCount;  ///< used slots (the first childCount)
    uint32_t pad[7];
    /// Child boxes, one lane per child: [0] lo.x, [1] hi.x, [2] lo.y, [3] hi.y, [4] lo.z, [5] hi.z.
    /// The near plane on axis a for a ray with dir[a] >= 0 is row 2a, the far plane 2a + 1.
    float box[6][kWidth];
};
static_assert(sizeof(WideNode) == 256);

/// Up to four triangles; lane i of v[k][a] is coordinate a of vertex k of triangle i. Unused
/// lanes repeat one point (a zero-area triangle, rejected by the det != 0 test).
struct alignas(32) TriBlock {
    float v[3][3][kBlockSize];
    uint32_t prim[kBlockSize];  ///< original triangle index per lane
};
static_assert(sizeof(TriBlock) == 160);

constexpr bool isLeaf(uint32_t ref) { return (ref & kLeafFlag) != 0; }
constexpr uint32_t leafRef(uint32_t firstBlock, uint32_t blockCount) {
    return kLeafFlag | ((blockCount - 1) << 28) | firstBlock;
}
constexpr uint32_t leafFirstBlock(uint32_t ref) { return ref & kMaxBlockIndex; }
constexpr uint32_t leafBlockCount(uint32_t ref) { return ((ref >> 28) & 7u) + 1; }

}  // namespace rays::tribvh
