#include "rays/render/photon_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "rays/scene/pov_photons.h"

namespace rays {
namespace {

// Photons are put in kd order in place: the median of [lo, hi) (split along the longest side of
// their box) sits at (lo + hi) / 2, those before it are on its low side, those after it on its high side.
struct Range {
    size_t lo, hi;
};

}  // namespace

PhotonMap::PhotonMap(std::vector<Photon> photons) : photons_(std::move(photons)) {
    if (!photons_.empty()) build(0, photons_.size());
}

void PhotonMap::build(size_t lo0, size_t hi0) {
    // An explicit stack: a map of millions of photons would recurse about 22 deep, but the
    // stack keeps the build's memory plain.
    std::vector<Range> todo{{lo0, hi0}};
    while (!todo.empty()) {
        const Range r = todo.back();
        todo.pop_back();
        if (r.hi - r.lo <= 1) continue;
        float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (size_t i = r.lo; i < r.hi; ++i)
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], photons_[i].position[a]);
                hi[a] = std::max(hi[a], photons_[i].position[a]);
            }
        int axis = 0;
        for (int a = 1; a < 3; ++a)
            if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
        const size_t mid = (r.lo + r.hi) / 2;
        std::nth_element(photons_.begin() + long(r.lo), photons_.begin() + long(mid), photons_.begin() + long(r.hi),
                         [axis](const Photon& a, const Photon& b) { return a.position[axis] < b.position[axis]; });
        photons_[mid].axis = uint8_t(axis);
        todo.push_back({r.lo, mid});
        todo.push_back({mid + 1, r.hi});
    }
}

int PhotonMap::nearest(Vec3 P, double maxD2, int k, Found* found) const {
    int n = 0;
    double limit = maxD2;  // the k-th distance once k are found
    auto less = [](const Found& a, const Found& b) { return a.d2 < b.d2; };
    // Depth-first over the implicit tree, the side holding P first; a range is skipped when its
    // splitting plane lies farther than the current limit.
    struct Item {
        uint32_t lo, hi;
        float planeD2;  // squared distance from P to the plane that led here (0: must visit)
    };
    std::array<Item, 128> stack;
    int top = 0;
    stack[top++] = Item{0, uint32_t(photons_.size()), 0.0f};
    while (top > 0) {
        const Item it = stack[--top];
        if (it.planeD2 > limit || it.lo >= it.hi) continue;
        const uint32_t mid = (it.lo + it.hi) / 2;
        const Photon& ph = photons_[mid];
        const Vec3 d = at(ph.position) - P;
        const double d2 = dot(d, d);
        if (d2 < limit) {
            if (n < k) {  // a plain list until k are found, then a max-heap on d2
                found[n++] = Found{float(d2), mid};
                if (n == k) {
                    std::make_heap(found, found + n, less);
                    limit = std::min(limit, double(found[0].d2));
                }
            } else {
                std::pop_heap(found, found + n, less);
                found[n - 1] = Found{float(d2), mid};
                std::push_heap(found, found + n, less);
                limit = found[0].d2;
            }
        }
        if (it.hi - it.lo == 1) continue;
        const int axis = ph.axis;
        const double off = P[axis] - double(ph.position[axis]);
        const Item nearSide = off < 0 ? Item{it.lo, mid, 0.0f} : Item{mid + 1, it.hi, 0.0f};
        const Item farSide = off < 0 ? Item{mid + 1, it.hi, float(off * off)} : Item{it.lo, mid, float(off * off)};
        if (top + 2 > int(stack.size())) continue;  // deeper than any balanced tree of 2^64 photons
        stack[top++] = farSide;   // visited after the near side
        stack[top++] = nearSide;
    }
    return n;
}

Vec3 PhotonMap::irradiance(Vec3 P, Vec3 N, const PhotonGather& g) const {
    if (photons_.empty() || !(g.radius > 0)) return {};
    const int k = std::clamp(g.max, 1, kMaxPhotonGather);
    std::array<Found, kMaxPhotonGather> found;
    // One search over the expanded radius: the nearest k within it, cut back to the radius,
    // are the nearest k within the radius; the expanded radius serves when fewer than
    // expandMin lie within the radius.
    double r = g.radius;
    const double wide = g.expandPercent > 0 ? r * (1 + g.expandPercent) : r;
    int n = nearest(P, wide * wide, k, found.data());
    int within = 0;
    for (int i = 0; i < n; ++i) within += double(found[size_t(i)].d2) <= r * r;
    if (within >= g.expandMin || wide == r) {
        if (within < n) {  // keep those within r (a max-heap no longer: the area needs the largest)
            int m = 0;
            for (int i = 0; i < n; ++i)
                if (double(found[size_t(i)].d2) <= r * r) found[size_t(m++)] = found[size_t(i)];
            n = m;
            std::make_heap(found.begin(), found.begin() + n, [](const Found& a, const Found& b) { return a.d2 < b.d2; });
        }
    } else {
        r = wide;
    }
    if (n == 0) return {};
    const double area = std::numbers::pi * (n == k ? double(found[0].d2) : r * r);
    if (!(area > 0)) return {};
    Vec3 sum;
    for (int i = 0; i < n; ++i) {
        const Photon& ph = photons_[found[size_t(i)].index];
        if (dot(at(ph.dir), N) >= 0) continue;  // arrived on the other side
        sum += at(ph.power);
    }
    return sum / area;
}

double PhotonMap::typicalRadius(int k) const {
    if (photons_.empty()) return 0;
    k = std::clamp(k, 1, kMaxPhotonGather);
    std::array<Found, kMaxPhotonGather> found;
    const size_t samples = std::min<size_t>(256, photons_.size());
    std::vector<double> radii;
    radii.reserve(samples);
    for (size_t s = 0; s < samples; ++s) {
        const size_t i = s * photons_.size() / samples;
        const int n = nearest(at(photons_[i].position), INFINITY, k, found.data());
        float farthest = 0;
        for (int j = 0; j < n; ++j) farthest = std::max(farthest, found[size_t(j)].d2);
        if (n > 0) radii.push_back(std::sqrt(double(farthest)));
    }
    if (radii.empty()) return 0;
    std::nth_element(radii.begin(), radii.begin() + long(radii.size() / 2), radii.end());
    return 2.0 * radii[radii.size() / 2];
}

}  // namespace rays
