// The collapse of a binary BVH into 8-wide nodes (accel/wide_collapse.h): every leaf kept exactly
// once, at most eight children per node, and the least total surface area of the wide nodes that
// any collapse of the same binary tree can reach (checked against an enumeration of all of them).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "rays/accel/wide_collapse.h"

using namespace rays::tribvh;

namespace { namespace RAYS_TEST_UNIT {

double halfArea(const float lo[3], const float hi[3]) {
    const double dx = double(hi[0]) - lo[0], dy = double(hi[1]) - lo[1], dz = double(hi[2]) - lo[2];
    return dx * (dy + dz) + dy * dz;
}

// A random binary tree over `leaves` leaves (one primitive each), boxes of random sizes at random
// places, inner boxes the union of their children's. Children are stored in pairs (first, first + 1).
BinaryBvh randomTree(int leaves, std::mt19937& rng) {
    std::vector<BinaryNode> nodes(1);
    std::uniform_real_distribution<float> pos(0.0f, 100.0f), size(0.1f, 30.0f);
    uint32_t nextRef = 0;
    std::function<void(uint32_t, int)> grow = [&](uint32_t n, int count) {
        if (count == 1) {
            BinaryNode& leaf = nodes[n];
            for (int a = 0; a < 3; ++a) {
                leaf.lo[a] = pos(rng);
                leaf.hi[a] = leaf.lo[a] + size(rng);
            }
            leaf.first = nextRef++;
            leaf.count = 1;
            return;
        }
        const int left = std::uniform_int_distribution<int>(1, count - 1)(rng);
        const uint32_t first = uint32_t(nodes.size());
        nodes.resize(nodes.size() + 2);
        nodes[n].first = first;
        nodes[n].count = 0;
        grow(first, left);
        grow(first + 1, count - left);
        for (int a = 0; a < 3; ++a) {
            nodes[n].lo[a] = std::min(nodes[first].lo[a], nodes[first + 1].lo[a]);
            nodes[n].hi[a] = std::max(nodes[first].hi[a], nodes[first + 1].hi[a]);
        }
    };
    grow(0, leaves);
    BinaryBvh bin;
    bin.nodes = HugeArray<BinaryNode>(nodes.size());
    std::copy(nodes.begin(), nodes.end(), bin.nodes.data());
    bin.root = 0;
    return bin;
}

// The least total area over all collapses: every choice of inner nodes (the root always) that
// become wide nodes, where each wide node's children (the nodes below it down to the next chosen
// node or leaf) number at most eight.
double bruteForceLeastArea(const BinaryBvh& bin) {
    std::vector<uint32_t> inner;
    for (uint32_t n = 0; n < bin.nodes.size(); ++n)
        if (!bin.nodes[n].leaf() && n != bin.root) inner.push_back(n);
    double best = std::numeric_limits<double>::infinity();
    std::vector<char> chosen(bin.nodes.size());
    for (uint64_t mask = 0; mask < (uint64_t(1) << inner.size()); ++mask) {
        std::fill(chosen.begin(), chosen.end(), 0);
        chosen[bin.root] = 1;
        for (size_t i = 0; i < inner.size(); ++i) chosen[inner[i]] = (mask >> i) & 1;
        std::function<int(uint32_t)> children = [&](uint32_t n) {  // slots n's subtree takes below a wide node
            const BinaryNode& b = bin.nodes[n];
            if (b.leaf() || chosen[n]) return 1;
            return children(b.first) + children(b.first + 1);
        };
        bool ok = true;
        double area = 0;
        for (uint32_t n = 0; n < bin.nodes.size() && ok; ++n) {
            if (!chosen[n]) continue;
            const BinaryNode& b = bin.nodes[n];
            ok = children(b.first) + children(b.first + 1) <= kWidth;
            area += halfArea(b.lo, b.hi);
        }
        if (ok) best = std::min(best, area);
    }
    return best;
}

struct Collapsed {
    double area = 0;   // root box + every inner child's box
    int leafRefs = 0;  // leaf references in the nodes
    bool fanoutOk = true;
};

Collapsed inspect(const Collapser::NodeVector& nodes, const BinaryBvh& bin) {
    Collapsed c;
    const BinaryNode& root = bin.nodes[bin.root];
    c.area = halfArea(root.lo, root.hi);
    for (const WideNode& n : nodes) {
        c.fanoutOk = c.fanoutOk && n.childCount >= 1 && n.childCount <= uint32_t(kWidth);
        for (uint32_t i = 0; i < n.childCount; ++i) {
            if (isLeaf(n.child[i])) {
                ++c.leafRefs;
                continue;
            }
            const float lo[3] = {n.box[0][i], n.box[2][i], n.box[4][i]};
            const float hi[3] = {n.box[1][i], n.box[3][i], n.box[5][i]};
            c.area += halfArea(lo, hi);
        }
    }
    return c;
}

TEST(WideCollapse, ReachesTheLeastTotalAreaOfAnyCollapse) {
    std::mt19937 rng(473);
    int severalNodes = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const int leaves = 2 + trial % 15;  // up to 15 inner nodes: 2^14 choices to enumerate
        const BinaryBvh bin = randomTree(leaves, rng);
        Collapser::NodeVector nodes;
        Collapser collapse(bin, nodes, kMaxLeafBlocks);
        collapse.run();
        const Collapsed c = inspect(nodes, bin);
        ASSERT_TRUE(c.fanoutOk) << "trial " << trial;
        ASSERT_EQ(c.leafRefs, leaves) << "trial " << trial;
        ASSERT_EQ(collapse.leaves.size(), size_t(leaves));
        std::vector<uint32_t> refs;
        for (const Collapser::LeafJob& job : collapse.leaves) refs.push_back(job.firstRef);
        std::sort(refs.begin(), refs.end());
        for (int i = 0; i < leaves; ++i) ASSERT_EQ(refs[size_t(i)], uint32_t(i)) << "trial " << trial;
        const double least = bruteForceLeastArea(bin);
        ASSERT_NEAR(c.area, least, 1e-5 * least) << "trial " << trial << ", " << leaves << " leaves";
        severalNodes += nodes.size() > 1;
    }
    EXPECT_GT(severalNodes, 0);  // the trees are big enough to need several wide nodes
}

TEST(WideCollapse, ALeafRootMakesOneNodeWithOneChild) {
    std::mt19937 rng(1);
    const BinaryBvh bin = randomTree(1, rng);
    Collapser::NodeVector nodes;
    Collapser collapse(bin, nodes, kMaxLeafBlocks);
    collapse.run();
    ASSERT_EQ(nodes.size(), 1u);
    EXPECT_EQ(nodes[0].childCount, 1u);
    EXPECT_TRUE(isLeaf(nodes[0].child[0]));
}

// With a pool of two threads the costs of the subtrees below the top six levels are computed side
// by side; the nodes and leaf blocks must be those of the one-thread collapse, byte for byte.
TEST(WideCollapse, TwoThreadCollapseEqualsOneThread) {
    std::mt19937 rng(2026);
    for (int leaves : {2, 40, 300, 5000}) {  // from trees shallower than the parallel levels up
        const BinaryBvh bin = randomTree(leaves, rng);
        Collapser::NodeVector one, two;
        Collapser a(bin, one, kMaxLeafBlocks), b(bin, two, kMaxLeafBlocks);
        a.run();
        TaskPool pool(2);
        b.run(&pool);
        ASSERT_EQ(one.size(), two.size()) << leaves << " leaves";
        EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(WideNode)), 0) << leaves << " leaves";
        ASSERT_EQ(a.leaves.size(), b.leaves.size());
        for (size_t i = 0; i < a.leaves.size(); ++i) {
            EXPECT_EQ(a.leaves[i].firstBlock, b.leaves[i].firstBlock);
            EXPECT_EQ(a.leaves[i].firstRef, b.leaves[i].firstRef);
        }
    }
}

}}  // namespace RAYS_TEST_UNIT, namespace
