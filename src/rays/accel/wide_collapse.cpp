#include "rays/accel/wide_collapse.h"

#include <limits>
#include <stdexcept>

namespace rays::tribvh {

namespace {
constexpr float kInf = std::numeric_limits<float>::infinity();
}

void Collapser::run() {
    nodes_.clear();
    nodes_.reserve(bin_.nodes.size() / 4 + 1);
    nodes_.emplace_back();
    fill(0, bin_.root);
}

// Fills nodes_[w] from binary node b (the root may itself be a leaf).
void Collapser::fill(uint32_t w, uint32_t b) {
    uint32_t kids[kWidth];
    int k = 0;
    const BinaryNode& bn = bin_.nodes[b];
    if (bn.leaf()) {
        kids[k++] = b;
    } else {
        kids[k++] = bn.first;
        kids[k++] = bn.first + 1;
    }
    while (k < kWidth) {
        int best = -1;
        float bestArea = -1.0f;
        for (int i = 0; i < k; ++i) {
            const BinaryNode& c = bin_.nodes[kids[i]];
            if (c.leaf()) continue;
            const float a = c.halfArea();
            if (a > bestArea) {
                bestArea = a;
                best = i;
            }
        }
        if (best < 0) break;
        const uint32_t c = kids[best];
        kids[best] = bin_.nodes[c].first;
        kids[k++] = bin_.nodes[c].first + 1;
    }
    // Allocate inner children contiguously, then set boxes and references.
    uint32_t refs[kWidth];
    for (int i = 0; i < k; ++i) {
        const BinaryNode& c = bin_.nodes[kids[i]];
        if (c.leaf()) {
            const uint32_t blocks = (c.count + kBlockSize - 1) / kBlockSize;
            if (blocks > leafBlockCap_ || blockCount + blocks > kMaxBlockIndex)
                throw std::length_error("BVH: too many primitives");
            refs[i] = leafRef(blockCount, blocks);
            leaves.push_back({blockCount, c.first, c.count});
            blockCount += blocks;
        } else {
            refs[i] = uint32_t(nodes_.size());
            nodes_.emplace_back();
        }
    }
    WideNode& node = nodes_[w];
    for (int i = 0; i < kWidth; ++i) {
        const bool used = i < k;
        const BinaryNode* c = used ? &bin_.nodes[kids[i]] : nullptr;
        for (int a = 0; a < 3; ++a) {
            node.box[2 * a][i] = used ? c->lo[a] : kInf;
            node.box[2 * a + 1][i] = used ? c->hi[a] : -kInf;
        }
        node.child[i] = used ? refs[i] : kLeafFlag;
    }
    node.childCount = uint32_t(k);
    for (uint32_t& p : node.pad) p = 0;
    for (int i = 0; i < k; ++i)
        if (!isLeaf(refs[i])) fill(refs[i], kids[i]);
}

WideTree buildWideTree(HugeArray<PrimRef>& refs, TaskPool& pool, Collapser::NodeVector& nodes) {
    SahSettings settings;
    settings.blockSize = kBlockSize;
    settings.maxLeafSize = kBlockSize;
    const BinaryBvh bin = buildBinnedSah(refs, settings, pool);
    Collapser collapse(bin, nodes, kMaxLeafBlocks);
    collapse.run();
    nodes.shrink_to_fit();
    WideTree tree;
    tree.leaves = std::move(collapse.leaves);
    tree.blockCount = collapse.blockCount;
    const BinaryNode& root = bin.nodes[bin.root];
    for (int a = 0; a < 3; ++a) {
        tree.lo[a] = root.lo[a];
        tree.hi[a] = root.hi[a];
    }
    return tree;
}

}  // namespace rays::tribvh
