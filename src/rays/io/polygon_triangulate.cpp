#include "rays/io/polygon_triangulate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "rays/io/polygon_monotone.h"

namespace rays {
namespace {

using P2 = PlanePoint;
using Tri = std::array<int, 3>;

double cross(P2 a, P2 b, P2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// Quads as tinyobjloader 2.0 splits them (in float, as it computes): along the shorter diagonal,
// the 1-3 one when both are equal.
std::vector<std::array<int, 3>> splitQuad(std::span<const Vec3> c) {
    auto sq = [&](int i, int j) {
        const float dx = float(c[size_t(j)].x) - float(c[size_t(i)].x), dy = float(c[size_t(j)].y) - float(c[size_t(i)].y),
                    dz = float(c[size_t(j)].z) - float(c[size_t(i)].z);
        return dx * dx + dy * dy + dz * dz;
    };
    if (sq(0, 2) < sq(1, 3)) return {{0, 1, 2}, {0, 2, 3}};
    return {{0, 1, 3}, {1, 2, 3}};
}

// The ring of corners still to clip, projected to 2D and oriented counter-clockwise, with a grid
// of the corners that are not strictly convex (only those can lie inside an ear).
constexpr uint64_t kEarStepsPerCorner = 32;  // ear clipping's budget before the sweep takes over

class EarClipper {
public:
    EarClipper(std::vector<P2> pts) : p_(std::move(pts)), n_(int(p_.size())), next_(size_t(n_)), prev_(size_t(n_)),
                                      concave_(size_t(n_)), removed_(size_t(n_), 0) {
        for (int i = 0; i < n_; ++i) {
            next_[size_t(i)] = (i + 1) % n_;
            prev_[size_t(i)] = (i + n_ - 1) % n_;
        }
        for (int i = 0; i < n_; ++i) concave_[size_t(i)] = !convex(i);
        buildGrid();
    }

    /// Clips ears into `out` until done (true) or until more than `budget` steps are spent (false:
    /// fanRest or another method finishes the polygon).
    bool clip(uint64_t budget, std::vector<Tri>& out) {
        out.reserve(size_t(n_ - 2));
        if (concaveLeft_ == 0) {  // convex: the fan from corner 0, as tinyobjloader's ear walk gives it
            for (int i = 1; i + 1 < n_; ++i) out.push_back({0, i, i + 1});
            return true;
        }
        int stalled = 0;
        while (left_ > 3) {
            if (work_ > budget) return false;
            const int b = next_[size_t(cur_)], c = next_[size_t(b)];
            ++work_;
            if (!concave_[size_t(b)] && !blocked(cur_, b, c)) {
                out.push_back({cur_, b, c});
                remove(b);
                --left_;
                stalled = 0;
                cur_ = c;  // walk on (as Mapbox's earcut does): ears stay small, so grid queries stay local
                continue;
            }
            cur_ = b;
            if (++stalled > left_) {  // no ear in a whole turn: degenerate; fan the rest
                fanRest(out);
                return true;
            }
        }
        Tri t{cur_, next_[size_t(cur_)], next_[size_t(next_[size_t(cur_)])]};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());  // lowest corner first, same winding
        out.push_back(t);
        return true;
    }

    /// The corners still in the ring as a fan from the current one.
    void fanRest(std::vector<Tri>& out) const {
        for (int x = next_[size_t(cur_)]; next_[size_t(x)] != cur_; x = next_[size_t(x)])
            out.push_back({cur_, x, next_[size_t(x)]});
    }

    uint64_t work() const { return work_; }

private:
    bool convex(int i) const { return cross(p_[size_t(prev_[size_t(i)])], p_[size_t(i)], p_[size_t(next_[size_t(i)])]) > 0; }

    void remove(int b) {
        const int a = prev_[size_t(b)], c = next_[size_t(b)];
        next_[size_t(a)] = c;
        prev_[size_t(c)] = a;
        removed_[size_t(b)] = 1;
        if (concave_[size_t(b)]) --concaveLeft_;
        // A corner that was convex stays convex when a neighbouring ear is cut; a concave one may turn.
        for (int x : {a, c})
            if (concave_[size_t(x)] && convex(x)) {
                concave_[size_t(x)] = 0;
                --concaveLeft_;
            }
    }

    int cellX(double x) const { return std::clamp(int((x - x0_) * sx_), 0, gw_ - 1); }
    int cellY(double y) const { return std::clamp(int((y - y0_) * sy_), 0, gh_ - 1); }

    // The grid over the corners still in the ring; rebuilt, coarser, each time half its concave
    // corners have gone (O(n) in all).
    void buildGrid() {
        double x1 = p_[0].x, y1 = p_[0].y;
        x0_ = x1, y0_ = y1;
        for (const P2& q : p_) {
            x0_ = std::min(x0_, q.x), x1 = std::max(x1, q.x);
            y0_ = std::min(y0_, q.y), y1 = std::max(y1, q.y);
        }
        std::vector<int> members;
        for (int i = 0; i < n_; ++i)
            if (concave_[size_t(i)] && !removed_[size_t(i)]) members.push_back(i);
        concaveLeft_ = int(members.size());
        gridMembers_ = concaveLeft_;
        // About one concave corner per cell.
        const int side = std::clamp(int(std::sqrt(double(members.size()))), 1, 4096);
        gw_ = gh_ = side;
        sx_ = x1 > x0_ ? gw_ / (x1 - x0_) : 0.0;
        sy_ = y1 > y0_ ? gh_ / (y1 - y0_) : 0.0;
        start_.assign(size_t(gw_) * size_t(gh_) + 1, 0);
        for (int i : members) ++start_[size_t(cellY(p_[size_t(i)].y) * gw_ + cellX(p_[size_t(i)].x)) + 1];
        for (size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
        cells_.resize(members.size());
        std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
        for (int i : members) cells_[fill[size_t(cellY(p_[size_t(i)].y) * gw_ + cellX(p_[size_t(i)].x))]++] = i;
    }

    // True when a concave corner other than a, b, c lies in triangle abc or on its edges. Only the
    // grid cells the triangle crosses are visited: row by row, the x-range of its edges in the row.
    bool blocked(int a, int b, int c) {
        if (concaveLeft_ == 0) return false;
        if (concaveLeft_ * 2 < gridMembers_ && gridMembers_ > 64) buildGrid();  // coarser as corners go
        const P2 A = p_[size_t(a)], B = p_[size_t(b)], C = p_[size_t(c)];
        const int gy0 = cellY(std::min({A.y, B.y, C.y})), gy1 = cellY(std::max({A.y, B.y, C.y}));
        const P2 edges[3][2] = {{A, B}, {B, C}, {C, A}};
        for (int gy = gy0; gy <= gy1; ++gy) {
            // The triangle's x-range within the row's band of y (its edges clipped to the band).
            const double lo = gy == gy0 ? -INFINITY : y0_ + gy / sy_, hi = gy == gy1 ? INFINITY : y0_ + (gy + 1) / sy_;
            double xmin = INFINITY, xmax = -INFINITY;
            for (const auto& e : edges) {
                const P2 P = e[0], Q = e[1];
                const double ya = std::max(lo, std::min(P.y, Q.y)), yb = std::min(hi, std::max(P.y, Q.y));
                if (ya > yb) continue;
                for (const double y : {ya, yb}) {
                    const double x = P.y == Q.y ? (y == ya ? std::min(P.x, Q.x) : std::max(P.x, Q.x))
                                                : P.x + (Q.x - P.x) * ((y - P.y) / (Q.y - P.y));
                    xmin = std::min(xmin, x), xmax = std::max(xmax, x);
                }
            }
            if (xmin > xmax) continue;
            // Widened by a rounding's worth: a corner on the triangle's edge must not be missed.
            const double slack = 1e-9 * (std::fabs(xmin) + std::fabs(xmax) + 1.0);
            const int gx0 = cellX(xmin - slack), gx1 = cellX(xmax + slack);
            for (int gx = gx0; gx <= gx1; ++gx) {
                const size_t cell = size_t(gy * gw_ + gx);
                ++work_;
                for (uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
                    const int i = cells_[k];
                    ++work_;
                    if (removed_[size_t(i)] || !concave_[size_t(i)] || i == a || i == b || i == c) continue;
                    const P2 q = p_[size_t(i)];
                    if ((q.x == A.x && q.y == A.y) || (q.x == C.x && q.y == C.y)) continue;
                    if (cross(A, B, q) >= 0 && cross(B, C, q) >= 0 && cross(C, A, q) >= 0) return true;
                }
            }
        }
        return false;
    }

    std::vector<P2> p_;
    int n_;
    std::vector<int> next_, prev_;
    std::vector<uint8_t> concave_, removed_;
    int concaveLeft_ = 0, gridMembers_ = 0;
    int left_ = n_, cur_ = 0;  // corners still in the ring, the corner the walk is at
    double x0_ = 0, y0_ = 0, sx_ = 0, sy_ = 0;
    int gw_ = 1, gh_ = 1;
    std::vector<uint32_t> start_;
    std::vector<int> cells_;
    uint64_t work_ = 0;
};

// Coordinates whose products stay finite (the grid and the sweep compute with them).
bool finiteAndModest(const std::vector<P2>& pts) {
    for (const P2& q : pts)
        if (!(std::fabs(q.x) < 1e100 && std::fabs(q.y) < 1e100)) return false;
    return true;
}

}  // namespace

std::vector<std::array<int, 3>> triangulatePolygon(std::span<const Vec3> corners, uint64_t* work) {
    const size_t n = corners.size();
    if (n < 3) return {};
    if (n == 3) return {{0, 1, 2}};
    if (n == 4) return splitQuad(corners);
    // Newell's normal picks the plane to work in: drop its largest axis.
    Vec3 nrm;
    for (size_t i = 0; i < n; ++i) {
        const Vec3& a = corners[i];
        const Vec3& b = corners[(i + 1) % n];
        nrm += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    const double ax = std::fabs(nrm.x), ay = std::fabs(nrm.y), az = std::fabs(nrm.z);
    const int drop = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    // Project so that the polygon runs counter-clockwise: (u, v) right-handed about the dropped axis.
    const double sign = nrm[drop] < 0 ? -1.0 : 1.0;
    std::vector<P2> pts(n);
    for (size_t i = 0; i < n; ++i) {
        const Vec3& q = corners[i];
        if (drop == 0) pts[i] = {q.y, sign * q.z};
        else if (drop == 1) pts[i] = {q.z, sign * q.x};
        else pts[i] = {q.x, sign * q.y};
    }
    if (nrm[drop] == 0 || !finiteAndModest(pts)) {  // no area at all (or no sane numbers): a fan keeps the count and the corners
        std::vector<std::array<int, 3>> fan;
        for (int i = 1; i + 1 < int(n); ++i) fan.push_back({0, i, i + 1});
        return fan;
    }
    // Ear clipping is linear for ordinary polygons; past a budget of steps (long thin spikes: a
    // star) the O(n log n) sweep takes over; a polygon that is not simple, and too hard for ear
    // clipping, has the rest of its ring fanned.
    EarClipper clipper(pts);
    std::vector<Tri> out;
    const uint64_t budget = kEarStepsPerCorner * n + 1024;
    uint64_t steps = 0;
    if (!clipper.clip(budget, out)) {
        steps = clipper.work();
        std::vector<Tri> sweep;
        if (triangulateMonotone(pts, sweep, steps)) out = std::move(sweep);
        else clipper.fanRest(out);
    } else {
        steps = clipper.work();
    }
    if (work) *work = steps;
    return out;
}

}  // namespace rays
