#include "rays/accel/binned_sah.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "rays/accel/simd.h"

namespace rays::tribvh {
namespace {

constexpr int kMaxBins = 32;
constexpr uint32_t kChunk = 16384;        ///< granularity of the data-parallel loops
constexpr uint32_t kMinTask = 1024;       ///< smallest subtree task when building on several threads
constexpr uint32_t kMaxSahDepth = 56;     ///< deeper ranges are split at the object median
constexpr float kInf = std::numeric_limits<float>::infinity();

/// Bins used for a range of n primitives: fewer for small ranges (cheaper, same quality there).
int binCount(uint32_t n) { return n >= 1024 ? 32 : (n >= 64 ? 16 : 8); }

struct Box {
    VFloat4 lo = VFloat4::broadcast(kInf), hi = VFloat4::broadcast(-kInf);
    void grow(VFloat4 l, VFloat4 h) {
        lo = min(lo, l);
        hi = max(hi, h);
    }
    void grow(VFloat4 p) { grow(p, p); }
    template <class B>
    void grow(const B& b) {
        grow(b.lo, b.hi);
    }
    float halfArea() const {
        alignas(16) float d[4];
        (hi - lo).store(d);
        return d[0] * (d[1] + d[2]) + d[1] * d[2];
    }
};

RAYS_FORCEINLINE VFloat4 refLo(const PrimRef& r) { return xyz(VFloat4::load(r.lo)); }
RAYS_FORCEINLINE VFloat4 refHi(const PrimRef& r) { return xyz(VFloat4::load(r.hi)); }
/// Twice the centroid (no multiply needed; bins are over the same doubled space).
RAYS_FORCEINLINE VFloat4 refCentroid2(const PrimRef& r) { return refLo(r) + refHi(r); }

/// Per-axis bins; only the first `bins` of each axis are initialised and used.
struct Bins {
    struct Raw {
        VFloat4 lo, hi;
        void grow(VFloat4 l, VFloat4 h) {
            lo = min(lo, l);
            hi = max(hi, h);
        }
    };
    Raw box[3][kMaxBins];
    uint32_t count[3][kMaxBins];
    explicit Bins(int bins) {
        const Box empty;
        for (int a = 0; a < 3; ++a)
            for (int i = 0; i < bins; ++i) {
                box[a][i] = {empty.lo, empty.hi};
                count[a][i] = 0;
            }
    }
    void merge(const Bins& o, int bins) {
        for (int a = 0; a < 3; ++a)
            for (int i = 0; i < bins; ++i) {
                box[a][i].grow(o.box[a][i].lo, o.box[a][i].hi);
                count[a][i] += o.count[a][i];
            }
    }
};

/// Maps a (doubled) centroid to bin indices per axis.
struct BinMapping {
    VFloat4 base, scale;
    int bins = 0;
    int hiBin = 0;
    bool usable[3] = {};
    BinMapping(const Box& centroids, int binCount) : bins(binCount), hiBin(binCount - 1) {
        alignas(16) float lo[4], hi[4], sc[4] = {0, 0, 0, 0};
        centroids.lo.store(lo);
        centroids.hi.store(hi);
        for (int a = 0; a < 3; ++a) {
            const float extent = hi[a] - lo[a];
            usable[a] = extent > 0.0f && std::isfinite(extent);
            // Slightly below bins/extent so that the maximum maps inside the last bin.
            sc[a] = usable[a] ? float(bins) * 0.99999f / extent : 0.0f;
        }
        base = xyz(centroids.lo);
        scale = VFloat4::load(sc);
        for (int a = 0; a < 3; ++a) {
            baseS[a] = lo[a];
            scaleS[a] = sc[a];
        }
    }
    RAYS_FORCEINLINE void index(const PrimRef& r, int32_t out[4]) const {
        truncClamp((refCentroid2(r) - base) * scale, hiBin, out);
    }
    /// True when r's bin on `axis` is below `pos`; the same arithmetic as index(), one axis.
    RAYS_FORCEINLINE bool below(const PrimRef& r, int axis, int pos) const {
        return truncToInt((r.lo[axis] + r.hi[axis] - baseS[axis]) * scaleS[axis]) < pos;
    }
    float baseS[3], scaleS[3];
};

struct Split {
    int axis = -1;
    int pos = 0;       ///< first bin of the right side
    float cost = kInf; ///< sum of area * blocks of both sides
    Box left, right;
};

struct Task {
    uint32_t node, begin, end, depth;
    Box bounds, centroids;
    uint32_t size() const { return end - begin; }
};

class Builder {
public:
    Builder(HugeArray<PrimRef>& refs, const SahSettings& s, TaskPool& pool, BinaryBvh& out)
        : refs_(refs), s_(s), pool_(pool), out_(out) {}

    void build();

private:
    uint32_t blocks(uint32_t n) const { return (n + s_.blockSize - 1) / s_.blockSize; }
    uint32_t allocPair() { return nodeCount_.fetch_add(2, std::memory_order_relaxed); }
    void makeLeaf(const Task& t) {
        BinaryNode& n = out_.nodes[t.node];
        n.first = t.begin;
        n.count = t.size();
    }
    void setBox(uint32_t node, const Box& b) {
        alignas(16) float lo[4], hi[4];
        b.lo.store(lo);
        b.hi.store(hi);
        BinaryNode& n = out_.nodes[node];
        for (int a = 0; a < 3; ++a) {
            n.lo[a] = lo[a];
            n.hi[a] = hi[a];
        }
    }
    /// Splits t into l and r (returns true) or turns it into a leaf (false).
    bool split(const Task& t, Task& l, Task& r, bool parallel);
    void buildSubtree(const Task& t);
    void binRange(const BinMapping& m, uint32_t begin, uint32_t end, Bins& bins) const;
    Split bestSplit(const Bins& bins, const BinMapping& m) const;
    /// Partitions [begin, end) by pred; returns the first index of the right side and the
    /// centroid bounds of both sides.
    template <class Pred>
    uint32_t partition(uint32_t begin, uint32_t end, Pred pred, Box& lc, Box& rc, bool parallel);
    template <class Pred>
    uint32_t hoare(uint32_t begin, uint32_t end, Pred pred, Box& lc, Box& rc);
    void medianSplit(const Task& t, uint32_t& mid, Box& lb, Box& rb, Box& lc, Box& rc);
    template <class Body>
    void forChunks(uint32_t begin, uint32_t end, bool parallel, Body&& body);

    HugeArray<PrimRef>& refs_;
    const SahSettings& s_;
    TaskPool& pool_;
    BinaryBvh& out_;
    std::atomic<uint32_t> nodeCount_{1};
};

template <class Body>
void Builder::forChunks(uint32_t begin, uint32_t end, bool parallel, Body&& body) {
    const uint32_t chunks = (end - begin + kChunk - 1) / kChunk;
    auto run = [&](size_t c) {
        const uint32_t b = begin + uint32_t(c) * kChunk;
        body(c, b, std::min(end, b + kChunk));
    };
    if (parallel && chunks > 1) {
        pool_.run(chunks, run);
    } else {
        for (uint32_t c = 0; c < chunks; ++c) run(c);
    }
}

void Builder::binRange(const BinMapping& m, uint32_t begin, uint32_t end, Bins& bins) const {
    const PrimRef* refs = refs_.data();
    for (uint32_t i = begin; i < end; ++i) {
        alignas(16) int32_t idx[4];
        m.index(refs[i], idx);
        const VFloat4 lo = refLo(refs[i]), hi = refHi(refs[i]);
        for (int a = 0; a < 3; ++a) {
            bins.box[a][idx[a]].grow(lo, hi);
            ++bins.count[a][idx[a]];
        }
    }
}

Split Builder::bestSplit(const Bins& bins, const BinMapping& m) const {
    Split best;
    for (int a = 0; a < 3; ++a) {
        if (!m.usable[a]) continue;
        float rightCost[kMaxBins];
        uint32_t rightCount[kMaxBins];
        Box acc;
        uint32_t n = 0;
        for (int i = m.bins - 1; i > 0; --i) {
            acc.grow(bins.box[a][i]);
            n += bins.count[a][i];
            rightCount[i] = n;
            rightCost[i] = n ? acc.halfArea() * float(blocks(n)) : 0.0f;
        }
        acc = Box{};
        n = 0;
        for (int i = 1; i < m.bins; ++i) {
            acc.grow(bins.box[a][i - 1]);
            n += bins.count[a][i - 1];
            if (n == 0 || rightCount[i] == 0) continue;
            const float cost = acc.halfArea() * float(blocks(n)) + rightCost[i];
            if (cost < best.cost) {
                best.cost = cost;
                best.axis = a;
                best.pos = i;
            }
        }
    }
    if (best.axis >= 0) {
        for (int i = 0; i < m.bins; ++i)
            (i < best.pos ? best.left : best.right).grow(bins.box[best.axis][i]);
    }
    return best;
}

template <class Pred>
uint32_t Builder::hoare(uint32_t begin, uint32_t end, Pred pred, Box& lcOut, Box& rcOut) {
    PrimRef* refs = refs_.data();
    Box lc, rc;  // locals: kept in registers (the caller's boxes may alias the array)
    uint32_t i = begin, j = end;
    for (;;) {
        while (i < j && pred(refs[i])) lc.grow(refCentroid2(refs[i++]));
        while (i < j && !pred(refs[j - 1])) rc.grow(refCentroid2(refs[--j]));
        if (i >= j) break;
        std::swap(refs[i], refs[j - 1]);
    }
    lcOut.grow(lc);
    rcOut.grow(rc);
    return i;
}

template <class Pred>
uint32_t Builder::partition(uint32_t begin, uint32_t end, Pred pred, Box& lc, Box& rc, bool parallel) {
    if (end - begin <= kChunk) return hoare(begin, end, pred, lc, rc);
    // In place and chunked: each fixed-size chunk is partitioned on its own (in parallel), then
    // the right-side elements left of the split point are swapped with the left-side elements
    // right of it, k-th with k-th. Chunks depend only on the range, so the result is the same for
    // any number of threads.
    const uint32_t chunks = (end - begin + kChunk - 1) / kChunk;
    std::vector<uint32_t> split(chunks);
    std::vector<Box> lcs(chunks), rcs(chunks);
    forChunks(begin, end, parallel,
              [&](size_t c, uint32_t b, uint32_t e) { split[c] = hoare(b, e, pred, lcs[c], rcs[c]); });
    uint32_t totalLeft = 0;
    for (uint32_t c = 0; c < chunks; ++c) {
        totalLeft += split[c] - (begin + c * kChunk);
        lc.grow(lcs[c]);
        rc.grow(rcs[c]);
    }
    const uint32_t mid = begin + totalLeft;
    // Misplaced runs, in increasing position: right-side runs before mid, left-side runs after.
    struct Run {
        uint32_t at, size;
    };
    std::vector<Run> wrongRight, wrongLeft;
    for (uint32_t c = 0; c < chunks; ++c) {
        const uint32_t b = begin + c * kChunk, e = std::min(end, b + kChunk);
        if (split[c] < mid && split[c] < e) wrongRight.push_back({split[c], std::min(e, mid) - split[c]});
        if (split[c] > mid && b < split[c]) {
            const uint32_t from = std::max(b, mid);
            wrongLeft.push_back({from, split[c] - from});
        }
    }
    // Pair them into swap jobs of at most kChunk elements.
    struct Swap {
        uint32_t a, b, size;
    };
    std::vector<Swap> swaps;
    size_t ir = 0, il = 0;
    uint32_t offR = 0, offL = 0;
    while (ir < wrongRight.size() && il < wrongLeft.size()) {
        const uint32_t n = std::min({wrongRight[ir].size - offR, wrongLeft[il].size - offL, kChunk});
        swaps.push_back({wrongRight[ir].at + offR, wrongLeft[il].at + offL, n});
        offR += n;
        offL += n;
        if (offR == wrongRight[ir].size) {
            ++ir;
            offR = 0;
        }
        if (offL == wrongLeft[il].size) {
            ++il;
            offL = 0;
        }
    }
    auto doSwap = [&](size_t k) {
        const Swap& sw = swaps[k];
        std::swap_ranges(refs_.data() + sw.a, refs_.data() + sw.a + sw.size, refs_.data() + sw.b);
    };
    if (parallel && swaps.size() > 1) {
        pool_.run(swaps.size(), doSwap);
    } else {
        for (size_t k = 0; k < swaps.size(); ++k) doSwap(k);
    }
    return mid;
}

void Builder::medianSplit(const Task& t, uint32_t& mid, Box& lb, Box& rb, Box& lc, Box& rc) {
    alignas(16) float lo[4], hi[4];
    t.centroids.lo.store(lo);
    t.centroids.hi.store(hi);
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    mid = t.begin + t.size() / 2;
    std::nth_element(refs_.begin() + t.begin, refs_.begin() + mid, refs_.begin() + t.end,
                     [axis](const PrimRef& x, const PrimRef& y) {
                         const float cx = x.lo[axis] + x.hi[axis], cy = y.lo[axis] + y.hi[axis];
                         return cx < cy || (cx == cy && x.id < y.id);
                     });
    for (uint32_t i = t.begin; i < t.end; ++i) {
        Box& b = i < mid ? lb : rb;
        Box& c = i < mid ? lc : rc;
        b.grow(refLo(refs_[i]), refHi(refs_[i]));
        c.grow(refCentroid2(refs_[i]));
    }
}

bool Builder::split(const Task& t, Task& l, Task& r, bool parallel) {
    const uint32_t n = t.size();
    setBox(t.node, t.bounds);
    // A range that fits one block is a leaf whenever a node visit costs at least a block test:
    // splitting costs traversalCost + (A_l + A_r) / A >= 1 = leaf cost.
    if (n == 1 || (n <= s_.blockSize && n <= s_.maxLeafSize && s_.traversalCost >= 1.0f)) {
        makeLeaf(t);
        return false;
    }
    Box lb, rb, lc, rc;
    uint32_t mid = 0;
    bool done = false;
    if (t.depth < kMaxSahDepth) {
        const BinMapping m(t.centroids, binCount(n));
        Bins bins(m.bins);
        if (parallel && n >= 2 * kChunk) {
            const uint32_t chunks = (n + kChunk - 1) / kChunk;
            std::vector<Bins> partial(chunks, Bins(m.bins));
            forChunks(t.begin, t.end, true,
                      [&](size_t c, uint32_t b, uint32_t e) { binRange(m, b, e, partial[c]); });
            for (const Bins& p : partial) bins.merge(p, m.bins);
        } else {
            binRange(m, t.begin, t.end, bins);
        }
        const Split best = bestSplit(bins, m);
        const float leafCost = float(blocks(n));
        if (best.axis < 0) {
            // All centroids coincide: no plane separates them.
            if (n <= s_.maxLeafSize) {
                makeLeaf(t);
                return false;
            }
        } else {
            const float area = t.bounds.halfArea();
            const float splitCost = s_.traversalCost + (area > 0.0f ? best.cost / area : 0.0f);
            if (n <= s_.maxLeafSize && leafCost <= splitCost) {
                makeLeaf(t);
                return false;
            }
            const int axis = best.axis, pos = best.pos;
            mid = partition(
                t.begin, t.end,
                [&m, axis, pos](const PrimRef& p) { return m.below(p, axis, pos); },
                lc, rc, parallel);
            lb = best.left;
            rb = best.right;
            done = true;
        }
    }
    if (!done) medianSplit(t, mid, lb, rb, lc, rc);

    const uint32_t first = allocPair();
    BinaryNode& node = out_.nodes[t.node];
    node.first = first;
    node.count = 0;
    l = Task{first, t.begin, mid, t.depth + 1, lb, lc};
    r = Task{first + 1, mid, t.end, t.depth + 1, rb, rc};
    return true;
}

void Builder::buildSubtree(const Task& t) {
    Task l, r;
    if (!split(t, l, r, false)) return;
    buildSubtree(l);
    buildSubtree(r);
}

void Builder::build() {
    const uint32_t n = uint32_t(refs_.size());
    out_.nodes = HugeArray<BinaryNode>(size_t(2) * n);
    out_.root = 0;

    // Root bounds.
    Task root{0, 0, n, 0, Box{}, Box{}};
    {
        const uint32_t chunks = (n + kChunk - 1) / kChunk;
        std::vector<Box> b(chunks), c(chunks);
        forChunks(0, n, true, [&](size_t k, uint32_t lo, uint32_t hi) {
            for (uint32_t i = lo; i < hi; ++i) {
                b[k].grow(refLo(refs_[i]), refHi(refs_[i]));
                c[k].grow(refCentroid2(refs_[i]));
            }
        });
        for (uint32_t k = 0; k < chunks; ++k) {
            root.bounds.grow(b[k]);
            root.centroids.grow(c[k]);
        }
    }

    // Upper levels a level at a time: ranges of 2 kChunk and more one after the other, each split
    // data-parallel, smaller ones side by side (one split per thread); ranges below taskSize are
    // left as subtrees, built as parallel tasks, largest first.
    const int threads = pool_.threads();
    std::vector<Task> level{root}, subtrees;
    const uint32_t taskSize = threads > 1 ? std::max<uint32_t>(kMinTask, n / (8 * uint32_t(threads))) : ~0u;
    while (!level.empty()) {
        std::vector<Task> next, sideBySide;
        for (const Task& t : level) {
            Task l, r;
            if (t.size() < taskSize)
                subtrees.push_back(t);
            else if (t.size() < 2 * kChunk)
                sideBySide.push_back(t);
            else if (split(t, l, r, true))
                next.insert(next.end(), {l, r});
        }
        std::vector<Task> halves(2 * sideBySide.size());
        std::vector<uint8_t> halved(sideBySide.size());
        pool_.run(sideBySide.size(),
                  [&](size_t i) { halved[i] = split(sideBySide[i], halves[2 * i], halves[2 * i + 1], false); });
        for (size_t i = 0; i < sideBySide.size(); ++i)
            if (halved[i]) next.insert(next.end(), {halves[2 * i], halves[2 * i + 1]});
        level = std::move(next);
    }
    std::stable_sort(subtrees.begin(), subtrees.end(),
                     [](const Task& a, const Task& b) { return a.size() > b.size(); });
    pool_.run(subtrees.size(), [&](size_t i) { buildSubtree(subtrees[i]); });

    out_.nodes.truncate(nodeCount_.load());
}

}  // namespace

float BinaryNode::halfArea() const {
    const float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
    return dx * (dy + dz) + dy * dz;
}

BinaryBvh buildBinnedSah(HugeArray<PrimRef>& refs, const SahSettings& settings, TaskPool& pool) {
    BinaryBvh out;
    Builder(refs, settings, pool, out).build();
    return out;
}

}  // namespace rays::tribvh
