#include "rays/accel/wide_collapse.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace rays::tribvh {

namespace {
constexpr float kInf = std::numeric_limits<float>::infinity();
}

void Collapser::run(TaskPool* pool) {
    nodes_.clear();
    nodes_.reserve(bin_.nodes.size() / 4 + 1);
    cost_ = HugeArray<Slots>(bin_.nodes.size());  // written for inner nodes only, before any read
    if (!bin_.nodes[bin_.root].leaf()) {
        if (pool && pool->threads() > 1)
            costsInParallel(*pool);
        else
            costs(bin_.root);
    }
    nodes_.emplace_back();
    fill(0, bin_.root);
    cost_.reset();
}

namespace {
constexpr Collapser::Slots kLeafSlots{};  // a leaf takes one slot and makes no node
}

const Collapser::Slots& Collapser::slots(uint32_t n) const { return bin_.nodes[n].leaf() ? kLeafSlots : cost_[n]; }

// cost_[n][k - 1]: the least total surface area of the wide nodes made from n's subtree when n
// may fill at most k slots of its parent (k = 1: n becomes a wide node of its own). A ray enters
// a wide node about as often as its box's area says, so this is the expected number of node
// visits up to a constant. Leaves count nothing: each leaf is the child of some wide node
// whatever the collapse.
void Collapser::costs(uint32_t n) {
    const BinaryNode& bn = bin_.nodes[n];
    for (uint32_t c : {bn.first, bn.first + 1})
        if (!bin_.nodes[c].leaf()) costs(c);
    nodeCosts(n);
}

// costs(root) with the subtrees below the top levels on the pool's threads: the inner nodes of
// the first kParallelLevels levels are computed last, children before parents.
void Collapser::costsInParallel(TaskPool& pool) {
    constexpr int kParallelLevels = 6;  // up to 64 subtrees
    std::vector<uint32_t> top{bin_.root}, subtrees;
    for (size_t i = 0, levelEnd = 1, level = 1; i < top.size(); ++i) {
        if (i == levelEnd) {
            levelEnd = top.size();
            ++level;
        }
        const BinaryNode& bn = bin_.nodes[top[i]];
        for (uint32_t c : {bn.first, bn.first + 1})
            if (!bin_.nodes[c].leaf()) (level < kParallelLevels ? top : subtrees).push_back(c);
    }
    pool.run(subtrees.size(), [&](size_t i) { costs(subtrees[i]); });
    for (size_t i = top.size(); i-- > 0;) nodeCosts(top[i]);
}

// cost_[n] from its children's costs.
void Collapser::nodeCosts(uint32_t n) {
    const BinaryNode& bn = bin_.nodes[n];
    const Slots& l = slots(bn.first);
    const Slots& r = slots(bn.first + 1);
    // split()'s least costs without its choice of slots: minima without branches (which one of
    // equal costs wins does not matter here).
    auto least = [&](int j) {
        float best = kInf;
        for (int a = 1; a < j; ++a) best = std::min(best, l[a - 1] + r[j - a - 1]);
        return best;
    };
    Slots& s = cost_[n];
    s[0] = bn.halfArea() + least(kWidth);
    for (int k = 2; k <= kWidth; ++k) s[k - 1] = std::min(s[k - 2], least(k));
}

// The least cost of n's two subtrees sharing j >= 2 slots; leftSlots receives the left one's.
float Collapser::split(uint32_t n, int j, int& leftSlots) const {
    const BinaryNode& bn = bin_.nodes[n];
    const Slots& l = slots(bn.first);
    const Slots& r = slots(bn.first + 1);
    float best = kInf;
    for (int a = 1; a < j; ++a) {
        const float c = l[a - 1] + r[j - a - 1];
        if (c < best) {
            best = c;
            leftSlots = a;
        }
    }
    return best;
}

// Appends the binary nodes that become children of a wide node when binary node n may fill at
// most k of its slots: n itself (a leaf, or an inner node that becomes a wide node), or the
// children its two subtrees give in the split that costs least.
void Collapser::gather(uint32_t n, int k, uint32_t* kids, int& count) const {
    const BinaryNode& bn = bin_.nodes[n];
    if (!bn.leaf())
        while (k > 1 && cost_[n][k - 2] <= cost_[n][k - 1]) --k;  // fewer slots cost no more
    if (bn.leaf() || k == 1) {
        kids[count++] = n;
        return;
    }
    int a = 1;
    split(n, k, a);
    gather(bn.first, a, kids, count);
    gather(bn.first + 1, k - a, kids, count);
}

// Fills nodes_[w] from binary node b (the root may itself be a leaf).
void Collapser::fill(uint32_t w, uint32_t b) {
    uint32_t kids[kWidth];
    int k = 0;
    const BinaryNode& bn = bin_.nodes[b];
    if (bn.leaf()) {
        kids[k++] = b;
    } else {  // the split of b's subtrees over the eight slots that costs least
        int a = 1;
        split(b, kWidth, a);
        gather(bn.first, a, kids, k);
        gather(bn.first + 1, kWidth - a, kids, k);
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
    collapse.run(&pool);
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
