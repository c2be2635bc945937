#include "rays/io/polygon_monotone.h"

#include <algorithm>
#include <cmath>
#include <memory_resource>
#include <set>
#include <utility>

namespace rays {
namespace monotone {  // named: the unity build compiles this folder's files as one (no clashes with their helpers)
namespace {

using Tri = std::array<int, 3>;

double cross(PlanePoint a, PlanePoint b, PlanePoint c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// The sweep's order of corners: higher y first, then lower x, then lower index (a total order, so
// repeated corners and equal heights are still ordered).
struct Above {
    const PlanePoint* p;
    uint64_t* work;
    bool operator()(int a, int b) const {
        ++*work;
        const PlanePoint A = p[a], B = p[b];
        if (A.y != B.y) return A.y > B.y;
        if (A.x != B.x) return A.x < B.x;
        return a < b;
    }
};

enum class Kind : uint8_t { Start, Split, End, Merge, Regular };

// ---- the sweep: diagonals that split the polygon into y-monotone pieces ----------------------------

// The edges the sweep line crosses with the polygon's inside to their right, left to right at the
// line's height; edge i runs from corner i to corner i + 1. Key -1 stands for the corner being
// swept (the search for the edge directly left of it).
struct EdgeLess {
    const PlanePoint* p;
    int n;
    const PlanePoint* at;  // the corner being swept
    uint64_t* work;
    double x(int e) const {
        if (e < 0) return at->x;
        const PlanePoint a = p[e], b = p[e + 1 == n ? 0 : e + 1];
        if (a.y == b.y) return std::clamp(at->x, std::min(a.x, b.x), std::max(a.x, b.x));
        return a.x + (b.x - a.x) * ((at->y - a.y) / (b.y - a.y));
    }
    bool operator()(int a, int b) const {
        ++*work;
        const double xa = x(a), xb = x(b);
        if (xa != xb) return xa < xb;
        if (a < 0) return false;  // an edge through the corner counts as left of it
        return b < 0 || a < b;
    }
};

// de Berg et al., ch. 3.2 (MakeMonotone). With input that is not a simple polygon the tree's order
// is not consistent; the tree stays a valid tree (each operation one descent), the diagonals are
// then wrong and the result's check fails.
class MonotoneSplitter {
public:
    MonotoneSplitter(std::span<const PlanePoint> p, uint64_t& work)
        : p_(p), n_(int(p.size())), work_(work), kind_(p.size()), helper_(p.size(), -1),
          status_(EdgeLess{p.data(), int(p.size()), &at_, &work}, &pool_), where_(p.size()), inTree_(p.size(), 0) {
        const Above above{p.data(), &work};
        for (int i = 0; i < n_; ++i) kind_[size_t(i)] = classify(i, above);
    }

    std::vector<std::pair<int, int>> run() {
        std::vector<int> order(p_.size());
        for (int i = 0; i < n_; ++i) order[size_t(i)] = i;
        std::sort(order.begin(), order.end(), Above{p_.data(), &work_});
        for (const int v : order) handle(v);
        return std::move(diagonals_);
    }

private:
    using Status = std::pmr::set<int, EdgeLess>;

    int prev(int i) const { return i == 0 ? n_ - 1 : i - 1; }
    int next(int i) const { return i + 1 == n_ ? 0 : i + 1; }

    Kind classify(int i, const Above& above) const {
        const bool prevBelow = above(i, prev(i)), nextBelow = above(i, next(i));
        const bool convex = cross(p_[size_t(prev(i))], p_[size_t(i)], p_[size_t(next(i))]) > 0;
        if (prevBelow && nextBelow) return convex ? Kind::Start : Kind::Split;
        if (!prevBelow && !nextBelow) return convex ? Kind::End : Kind::Merge;
        return Kind::Regular;
    }

    void handle(int v) {
        ++work_;
        at_ = p_[size_t(v)];
        switch (kind_[size_t(v)]) {
        case Kind::Start: insert(v); break;
        case Kind::End: closeEdge(v, prev(v)); break;
        case Kind::Split:
            if (const int j = edgeLeftOf(); j >= 0) {
                diagonal(v, helper_[size_t(j)]);
                helper_[size_t(j)] = v;
            }
            insert(v);
            break;
        case Kind::Merge:
            closeEdge(v, prev(v));
            joinLeft(v);
            break;
        case Kind::Regular:
            if (above(prev(v), v)) {  // on the left boundary: the inside lies to the right
                closeEdge(v, prev(v));
                insert(v);
            } else {
                joinLeft(v);
            }
            break;
        }
    }

    bool above(int a, int b) const { return Above{p_.data(), &work_}(a, b); }

    void insert(int v) {
        where_[size_t(v)] = status_.insert(v).first;
        inTree_[size_t(v)] = 1;
        helper_[size_t(v)] = v;
    }

    // Edge e ends at v: a diagonal to its helper if that is a merge corner; then e leaves the tree.
    void closeEdge(int v, int e) {
        if (!inTree_[size_t(e)]) return;
        if (isMerge(helper_[size_t(e)])) diagonal(v, helper_[size_t(e)]);
        status_.erase(where_[size_t(e)]);
        inTree_[size_t(e)] = 0;
    }

    // v on the right boundary or a merge corner: the edge left of it gets v as its helper.
    void joinLeft(int v) {
        const int j = edgeLeftOf();
        if (j < 0) return;
        if (isMerge(helper_[size_t(j)])) diagonal(v, helper_[size_t(j)]);
        helper_[size_t(j)] = v;
    }

    int edgeLeftOf() {
        auto it = status_.lower_bound(-1);
        if (it == status_.begin()) return -1;
        return *--it;
    }

    bool isMerge(int v) const { return v >= 0 && kind_[size_t(v)] == Kind::Merge; }

    void diagonal(int a, int b) {
        if (a == b || b == next(a) || a == next(b)) return;  // only with input that is not simple
        diagonals_.emplace_back(a, b);
    }

    std::span<const PlanePoint> p_;
    int n_;
    uint64_t& work_;
    std::vector<Kind> kind_;
    std::vector<int> helper_;
    PlanePoint at_{0, 0};
    std::pmr::monotonic_buffer_resource pool_;
    Status status_;
    std::vector<Status::iterator> where_;
    std::vector<uint8_t> inTree_;
    std::vector<std::pair<int, int>> diagonals_;
};

// ---- the pieces: faces of the polygon's edges and the diagonals ------------------------------------

// Every edge (polygon edge i from i to i + 1, then the diagonals) as two directed entries, grouped by
// the corner they leave and sorted counter-clockwise around it. Walking from an entry u→v to the
// entry around v just clockwise of v→u goes round the piece on the entry's left. The walk
// is a permutation of the entries, so every walk returns to its start.
class Pieces {
public:
    Pieces(std::span<const PlanePoint> p, const std::vector<std::pair<int, int>>& diagonals, uint64_t& work)
        : n_(int(p.size())) {
        const size_t edges = p.size() + diagonals.size();
        ends_.resize(edges);
        for (int i = 0; i < n_; ++i) ends_[size_t(i)] = {i, i + 1 == n_ ? 0 : i + 1};
        for (size_t d = 0; d < diagonals.size(); ++d) ends_[p.size() + d] = diagonals[d];
        start_.assign(p.size() + 1, 0);
        for (const auto& [a, b] : ends_) ++start_[size_t(a) + 1], ++start_[size_t(b) + 1];
        for (size_t v = 1; v < start_.size(); ++v) start_[v] += start_[v - 1];
        entries_.resize(2 * edges);
        std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
        for (size_t e = 0; e < edges; ++e) {
            const auto [a, b] = ends_[e];
            entries_[fill[size_t(a)]++] = {b, int(e), std::atan2(p[size_t(b)].y - p[size_t(a)].y, p[size_t(b)].x - p[size_t(a)].x)};
            entries_[fill[size_t(b)]++] = {a, int(e), std::atan2(p[size_t(a)].y - p[size_t(b)].y, p[size_t(a)].x - p[size_t(b)].x)};
        }
        slot_.resize(2 * edges);
        for (int v = 0; v < n_; ++v) {
            auto* first = entries_.data() + start_[size_t(v)];
            auto* last = entries_.data() + start_[size_t(v) + 1];
            std::sort(first, last, [&work](const Entry& a, const Entry& b) {
                ++work;
                return a.angle != b.angle ? a.angle < b.angle : a.edge < b.edge;
            });
            for (uint32_t k = start_[size_t(v)]; k < start_[size_t(v) + 1]; ++k) {
                const int e = entries_[k].edge;
                slot_[2 * size_t(e) + (ends_[size_t(e)].first == v ? 0 : 1)] = k;
            }
        }
    }

    /// Calls piece(corners) for each piece, corners counter-clockwise; false when a walk meets the
    /// polygon's outside (only with input that is not simple).
    template <class F>
    bool each(F piece, uint64_t& work) {
        std::vector<uint8_t> seen(entries_.size(), 0);
        std::vector<int> corners;
        for (int v = 0; v < n_; ++v)
            for (uint32_t k = start_[size_t(v)]; k < start_[size_t(v) + 1]; ++k) {
                if (seen[k] || outside(v, k)) continue;
                corners.clear();
                int at = v;
                uint32_t cur = k;
                do {
                    ++work;
                    if (outside(at, cur)) return false;
                    seen[cur] = 1;
                    corners.push_back(at);
                    const int to = entries_[cur].to;
                    const uint32_t back = twin(cur, at);
                    cur = back == start_[size_t(to)] ? start_[size_t(to) + 1] - 1 : back - 1;
                    at = to;
                } while (cur != k);
                if (!piece(corners)) return false;
            }
        return true;
    }

private:
    struct Entry {
        int to, edge;
        double angle;
    };

    // The entry from `at` along polygon edge at − 1 → at, backwards: the outside's.
    bool outside(int at, uint32_t k) const {
        const int e = entries_[k].edge;
        return e < n_ && ends_[size_t(e)].first != at;
    }

    // The entry of the same edge leaving the other end.
    uint32_t twin(uint32_t k, int from) const {
        const int e = entries_[k].edge;
        return slot_[2 * size_t(e) + (ends_[size_t(e)].first == from ? 1 : 0)];
    }

    int n_;
    std::vector<std::pair<int, int>> ends_;
    std::vector<uint32_t> start_;
    std::vector<Entry> entries_;
    std::vector<uint32_t> slot_;  // per edge: its entry at the first end, then at the second
};

// ---- one y-monotone piece: the stack walk ----------------------------------------------------------

// Appends a triangle, turned counter-clockwise.
void emit(std::span<const PlanePoint> p, int a, int b, int c, std::vector<Tri>& out) {
    if (cross(p[size_t(a)], p[size_t(b)], p[size_t(c)]) < 0) std::swap(b, c);
    out.push_back({a, b, c});
}

// de Berg et al., ch. 3.3 (TriangulateMonotonePolygon): the corners merged top to bottom from the
// two chains, a stack of the corners still waiting. Every triangle removes one corner, so a piece
// of k corners gives k − 2 triangles whatever its shape.
bool triangulatePiece(std::span<const PlanePoint> p, const std::vector<int>& piece, std::vector<Tri>& out, uint64_t& work) {
    const int k = int(piece.size());
    if (k < 3) return false;
    const Above above{p.data(), &work};
    int top = 0, bottom = 0;
    for (int i = 1; i < k; ++i) {
        if (above(piece[size_t(i)], piece[size_t(top)])) top = i;
        if (above(piece[size_t(bottom)], piece[size_t(i)])) bottom = i;
    }
    // Merge the left chain (top → bottom, counter-clockwise) and the right chain (top → bottom, clockwise).
    std::vector<std::pair<int, bool>> sorted;  // corner, on the left chain
    sorted.reserve(size_t(k));
    sorted.emplace_back(piece[size_t(top)], true);
    int l = (top + 1) % k, r = (top + k - 1) % k;
    while (l != bottom || r != bottom) {
        const bool takeLeft = r == bottom || (l != bottom && above(piece[size_t(l)], piece[size_t(r)]));
        if (takeLeft) sorted.emplace_back(piece[size_t(l)], true), l = (l + 1) % k;
        else sorted.emplace_back(piece[size_t(r)], false), r = (r + k - 1) % k;
    }
    sorted.emplace_back(piece[size_t(bottom)], false);

    std::vector<std::pair<int, bool>> stack = {sorted[0], sorted[1]};
    for (int j = 2; j + 1 < k; ++j) {
        ++work;
        const auto [u, left] = sorted[size_t(j)];
        if (left != stack.back().second) {
            for (size_t s = 0; s + 1 < stack.size(); ++s) emit(p, u, stack[s].first, stack[s + 1].first, out);
            stack = {sorted[size_t(j - 1)], sorted[size_t(j)]};
            continue;
        }
        auto last = stack.back();
        stack.pop_back();
        while (!stack.empty()) {
            ++work;
            const PlanePoint a = p[size_t(stack.back().first)], b = p[size_t(last.first)], c = p[size_t(u)];
            if ((left ? cross(a, b, c) : cross(c, b, a)) <= 0) break;
            emit(p, u, last.first, stack.back().first, out);
            last = stack.back();
            stack.pop_back();
        }
        stack.push_back(last);
        stack.emplace_back(u, left);
    }
    const int u = sorted.back().first;
    for (size_t s = 0; s + 1 < stack.size(); ++s) emit(p, u, stack[s].first, stack[s + 1].first, out);
    return true;
}

// The result checks: n − 2 triangles whose areas (all counted positive) add up to the polygon's.
bool covers(std::span<const PlanePoint> p, const std::vector<Tri>& tris) {
    if (tris.size() + 2 != p.size()) return false;
    double area = 0, sum = 0;
    for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) area += p[j].x * p[i].y - p[i].x * p[j].y;
    for (const Tri& t : tris) sum += cross(p[size_t(t[0])], p[size_t(t[1])], p[size_t(t[2])]);
    return area > 0 && std::fabs(sum - area) <= 1e-9 * area;
}

}  // namespace
}  // namespace monotone

bool triangulateMonotone(std::span<const PlanePoint> p, std::vector<std::array<int, 3>>& out, uint64_t& work) {
    using namespace monotone;
    out.clear();
    if (p.size() < 3) return false;
    out.reserve(p.size() - 2);
    const std::vector<std::pair<int, int>> diagonals = MonotoneSplitter(p, work).run();
    Pieces pieces(p, diagonals, work);
    const bool ok = pieces.each([&](const std::vector<int>& piece) { return triangulatePiece(p, piece, out, work); }, work);
    return ok && covers(p, out);
}

}  // namespace rays
