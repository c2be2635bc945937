#include "rays/accel/bvh.h"

#include <algorithm>
#include <array>
#include <functional>

namespace rays {
namespace {

constexpr int kBins = 16;
constexpr uint32_t kLeafMax = 4;
constexpr uint32_t kMaxSahDepth = 48;  // beyond this, median splits (traversal stack is 128 deep)

// Slab test against a box with a precomputed reciprocal direction; returns the entry distance or
// +inf when the box is missed within (tMin, tMax).
double boxEntry(const Bounds& b, const Vec3& org, const Vec3& inv, double tMin, double tMax) {
    double t0 = tMin, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
        double tn = (b.lo[a] - org[a]) * inv[a];
        double tf = (b.hi[a] - org[a]) * inv[a];
        if (tn > tf) std::swap(tn, tf);
        // NaN (0 · inf) comparisons fail, leaving the interval unchanged: the slab is ignored.
        t0 = tn > t0 ? tn : t0;
        t1 = tf < t1 ? tf : t1;
        if (t0 > t1) return kInfinity;
    }
    return t0;
}

}  // namespace

// Reorders [begin, end) so that the element at mid has the median centroid along axis.
void Bvh::medianPartition(std::vector<Bounds>& pb, std::vector<Vec3>& pc, uint32_t begin, uint32_t mid,
                          uint32_t end, int axis) {
    std::vector<uint32_t> order(end - begin);
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = begin + i;
    std::nth_element(order.begin(), order.begin() + (mid - begin), order.end(),
                     [&](uint32_t a, uint32_t b) { return pc[a][axis] < pc[b][axis]; });
    std::vector<Bounds> nb;
    std::vector<Vec3> nc;
    std::vector<uint32_t> np;
    for (uint32_t i : order) {
        nb.push_back(pb[i]);
        nc.push_back(pc[i]);
        np.push_back(prims_[i]);
    }
    std::copy(nb.begin(), nb.end(), pb.begin() + begin);
    std::copy(nc.begin(), nc.end(), pc.begin() + begin);
    std::copy(np.begin(), np.end(), prims_.begin() + begin);
}

Bvh::Bvh(const std::vector<Object>& objects) {
    std::vector<Bounds> bounds;
    std::vector<Vec3> centroids;
    for (uint32_t i = 0; i < objects.size(); ++i) {
        const Bounds b = worldBounds(objects[i]);
        if (b.empty()) {
            unbounded_.push_back(i);
            continue;
        }
        prims_.push_back(i);
        bounds.push_back(b);
        centroids.push_back(b.centroid());
    }
    if (prims_.empty()) return;
    nodes_.reserve(2 * prims_.size());
    nodes_.emplace_back();
    build(bounds, centroids, 0, uint32_t(prims_.size()));
}

// Builds the tree for prims_[begin, end) into node 0 (already allocated). Children are allocated
// as consecutive pairs.
void Bvh::build(std::vector<Bounds>& pb, std::vector<Vec3>& pc, uint32_t begin, uint32_t end) {
    struct Job { uint32_t node, begin, end, depth; };
    std::vector<Job> stack{{0, begin, end, 0}};
    while (!stack.empty()) {
        const Job job = stack.back();
        stack.pop_back();
        BvhNode& node = nodes_[job.node];
        Bounds nb, cb;
        for (uint32_t i = job.begin; i < job.end; ++i) {
            nb.extend(pb[i]);
            cb.extend(pc[i]);
        }
        node.bounds = nb;
        const uint32_t n = job.end - job.begin;
        auto makeLeaf = [&] {
            node.first = job.begin;
            node.count = n;
        };
        if (n <= 1) { makeLeaf(); continue; }

        // Binned SAH over all three axes.
        double bestCost = kInfinity;
        int bestAxis = -1, bestSplit = 0;
        const Vec3 ext = cb.extent();
        for (int axis = 0; axis < 3; ++axis) {
            if (ext[axis] <= 0) continue;
            const double scale = kBins / ext[axis];
            std::array<Bounds, kBins> binB;
            std::array<uint32_t, kBins> binN{};
            for (uint32_t i = job.begin; i < job.end; ++i) {
                int b = int((pc[i][axis] - cb.lo[axis]) * scale);
                b = std::clamp(b, 0, kBins - 1);
                binN[b]++;
                binB[b].extend(pb[i]);
            }
            std::array<double, kBins> rightArea{};
            std::array<uint32_t, kBins> rightN{};
            Bounds acc;
            uint32_t cnt = 0;
            for (int b = kBins - 1; b > 0; --b) {
                acc.extend(binB[b]);
                cnt += binN[b];
                rightArea[b] = acc.surfaceArea();
                rightN[b] = cnt;
            }
            acc = Bounds{};
            cnt = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                acc.extend(binB[b]);
                cnt += binN[b];
                if (cnt == 0 || rightN[b + 1] == 0) continue;
                const double cost = acc.surfaceArea() * cnt + rightArea[b + 1] * rightN[b + 1];
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestSplit = b;
                }
            }
        }
        // SAH with unit traversal and intersection costs: split = 1 + (A_L·N_L + A_R·N_R) / A.
        const double area = nb.surfaceArea();
        const double splitCost = area > 0 ? 1.0 + bestCost / area : double(n);
        if (n <= kLeafMax && (bestAxis < 0 || splitCost >= double(n))) {
            makeLeaf();
            continue;
        }
        if (bestAxis < 0 || job.depth >= kMaxSahDepth) {
            // Degenerate centroids or a very deep branch: median split on the widest axis keeps
            // the depth logarithmic from here on.
            int axis = 0;
            if (ext.y > ext[axis]) axis = 1;
            if (ext.z > ext[axis]) axis = 2;
            bestAxis = axis;
            bestSplit = -1;
        }
        uint32_t mid;
        if (bestSplit >= 0) {
            const double scale = kBins / ext[bestAxis];
            uint32_t i = job.begin, j = job.end;
            while (i < j) {
                int b = std::clamp(int((pc[i][bestAxis] - cb.lo[bestAxis]) * scale), 0, kBins - 1);
                if (b <= bestSplit) {
                    ++i;
                } else {
                    --j;
                    std::swap(pc[i], pc[j]);
                    std::swap(pb[i], pb[j]);
                    std::swap(prims_[i], prims_[j]);
                }
            }
            mid = i;
        } else {
            mid = job.begin + n / 2;
            medianPartition(pb, pc, job.begin, mid, job.end, bestAxis);
        }
        if (mid == job.begin || mid == job.end) mid = job.begin + n / 2;
        const uint32_t left = uint32_t(nodes_.size());
        nodes_.emplace_back();
        nodes_.emplace_back();
        nodes_[job.node].first = left;
        nodes_[job.node].count = 0;
        stack.push_back({left, job.begin, mid, job.depth + 1});
        stack.push_back({left + 1, mid, job.end, job.depth + 1});
    }
}

Hit Bvh::closest(const std::vector<Object>& objects, const Ray& ray, double tMin, double tMax) const {
    Hit best;
    best.t = tMax;
    ShapeHit sh;
    for (uint32_t id : unbounded_) {
        if (intersect(objects[id], ray, tMin, best.t, sh)) {
            best.t = sh.t;
            best.object = int(id);
            best.normal = sh.normal;
                    best.geomNormal = sh.geomNormal;
        }
    }
    if (nodes_.empty()) return best;
    const Vec3 inv{1.0 / ray.dir.x, 1.0 / ray.dir.y, 1.0 / ray.dir.z};
    uint32_t stack[128];
    int sp = 0;
    if (boxEntry(nodes_[0].bounds, ray.origin, inv, tMin, best.t) == kInfinity) return best;
    stack[sp++] = 0;
    while (sp > 0) {
        const BvhNode& node = nodes_[stack[--sp]];
        if (node.count > 0) {
            for (uint32_t i = node.first; i < node.first + node.count; ++i) {
                const uint32_t id = prims_[i];
                if (intersect(objects[id], ray, tMin, best.t, sh)) {
                    best.t = sh.t;
                    best.object = int(id);
                    best.normal = sh.normal;
                    best.geomNormal = sh.geomNormal;
                }
            }
            continue;
        }
        const uint32_t l = node.first, r = node.first + 1;
        const double tl = boxEntry(nodes_[l].bounds, ray.origin, inv, tMin, best.t);
        const double tr = boxEntry(nodes_[r].bounds, ray.origin, inv, tMin, best.t);
        // Push the far child first so the near one is visited next.
        if (tl <= tr) {
            if (tr != kInfinity) stack[sp++] = r;
            if (tl != kInfinity) stack[sp++] = l;
        } else {
            if (tl != kInfinity) stack[sp++] = l;
            stack[sp++] = r;
        }
    }
    return best;
}

bool Bvh::any(const std::vector<Object>& objects, const Ray& ray, double tMin, double tMax) const {
    for (uint32_t id : unbounded_)
        if (occludes(objects[id], ray, tMin, tMax)) return true;
    if (nodes_.empty()) return false;
    const Vec3 inv{1.0 / ray.dir.x, 1.0 / ray.dir.y, 1.0 / ray.dir.z};
    uint32_t stack[128];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const BvhNode& node = nodes_[stack[--sp]];
        if (boxEntry(node.bounds, ray.origin, inv, tMin, tMax) == kInfinity) continue;
        if (node.count > 0) {
            for (uint32_t i = node.first; i < node.first + node.count; ++i)
                if (occludes(objects[prims_[i]], ray, tMin, tMax)) return true;
            continue;
        }
        stack[sp++] = node.first + 1;
        stack[sp++] = node.first;
    }
    return false;
}

int Bvh::depth() const {
    if (nodes_.empty()) return 0;
    std::function<int(uint32_t)> rec = [&](uint32_t i) -> int {
        const BvhNode& n = nodes_[i];
        if (n.count > 0) return 1;
        return 1 + std::max(rec(n.first), rec(n.first + 1));
    };
    return rec(0);
}

}  // namespace rays
