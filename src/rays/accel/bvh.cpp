#include "rays/accel/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>

namespace rays {
namespace {

constexpr int kBins = 16;
constexpr uint32_t kLeafMax = 4;
constexpr uint32_t kMaxSahDepth = 48;  // beyond this, median splits (traversal stack is 128 deep)

// Ray prepared for float slab tests: t = box·inv + offset (offset = −origin·inv).
struct SlabRay {
    float inv[3];
    float off[3];
    explicit SlabRay(const Ray& r) {
        for (int a = 0; a < 3; ++a) {
            // A zero component would give 0·inf = NaN below; a huge finite inverse keeps the
            // slab test exact in sign (the ray is parallel to that slab).
            const double d = r.dir[a];
            const double i = std::fabs(d) > 1e-30 ? 1.0 / d : std::copysign(1e30, d);
            inv[a] = float(i);
            off[a] = float(-r.origin[a] * i);
        }
    }
};

// Entry distance of the ray into node n within [tMin, tMax], or +inf when it misses.
// NaN from 0·inf (ray in a slab plane) fails the comparisons and leaves the interval as is.
inline float boxEntry(const FlatNode& n, const SlabRay& r, float tMin, float tMax) {
    float x0 = n.lo[0] * r.inv[0] + r.off[0], x1 = n.hi[0] * r.inv[0] + r.off[0];
    float y0 = n.lo[1] * r.inv[1] + r.off[1], y1 = n.hi[1] * r.inv[1] + r.off[1];
    float z0 = n.lo[2] * r.inv[2] + r.off[2], z1 = n.hi[2] * r.inv[2] + r.off[2];
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    if (z0 > z1) std::swap(z0, z1);
    const float t0 = std::max(std::max(x0, y0), std::max(z0, tMin));
    const float t1 = std::min(std::min(x1, y1), std::min(z1, tMax));
    return t0 <= t1 ? t0 : std::numeric_limits<float>::infinity();
}

// Float box containing b with a margin for float rounding of the ray (origin and inverse).
void toFlat(const BvhNode& n, FlatNode& f) {
    const Vec3 ext = n.bounds.extent();
    for (int a = 0; a < 3; ++a) {
        const double pad = 1e-6 * (ext[a] + std::max(std::fabs(n.bounds.lo[a]), std::fabs(n.bounds.hi[a]))) + 1e-30;
        f.lo[a] = std::nextafter(float(n.bounds.lo[a] - pad), -std::numeric_limits<float>::infinity());
        f.hi[a] = std::nextafter(float(n.bounds.hi[a] + pad), std::numeric_limits<float>::infinity());
    }
    f.first = n.first;
    f.count = n.count;
}

constexpr float kFloatInf = std::numeric_limits<float>::infinity();

// Float versions of the ray interval, widened so float rounding never cuts a real hit.
inline float lowerT(double t) { return float(t) - 1e-6f * std::fabs(float(t)); }
inline float upperT(double t) { return std::isinf(t) ? kFloatInf : float(t) * (1 + 1e-6f) + 1e-30f; }

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
    std::vector<float> positions;
    std::vector<uint32_t> indices;
    for (uint32_t i = 0; i < objects.size(); ++i) {
        const Object& o = objects[i];
        if (o.type == ShapeType::Triangle && !o.localSpace) {
            for (Vec3 p : {o.p0, o.p1, o.p2}) {
                indices.push_back(uint32_t(positions.size() / 3));
                positions.insert(positions.end(), {float(p.x), float(p.y), float(p.z)});
            }
            triObject_.push_back(i);
            continue;
        }
        const Bounds b = worldBounds(o);
        if (b.empty()) {
            unbounded_.push_back(i);
            continue;
        }
        prims_.push_back(i);
        bounds.push_back(b);
        centroids.push_back(b.centroid());
    }
    if (!triObject_.empty())
        triangles_.build(positions.data(), positions.size() / 3, indices.data(), triObject_.size());
    if (prims_.empty()) return;
    nodes_.reserve(2 * prims_.size());
    nodes_.emplace_back();
    build(bounds, centroids, 0, uint32_t(prims_.size()));
    flat_.resize(nodes_.size());
    for (size_t i = 0; i < nodes_.size(); ++i) toFlat(nodes_[i], flat_[i]);
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
    if (!triangles_.empty()) {
        const TriRay tr{{float(ray.origin.x), float(ray.origin.y), float(ray.origin.z)},
                        {float(ray.dir.x), float(ray.dir.y), float(ray.dir.z)}};
        TriHit th;
        if (triangles_.intersect(tr, float(tMin), upperT(best.t), th)) {
            // Refine in double precision on the triangle found (exact t and normal for the
            // course's printouts); fall back to the float hit at a grazing edge.
            const uint32_t id = triObject_[th.prim];
            if (intersect(objects[id], ray, tMin, kInfinity, sh) && sh.t < best.t) {
                best.t = sh.t;
                best.object = int(id);
                best.normal = sh.normal;
                best.geomNormal = sh.geomNormal;
            } else if (double(th.t) < best.t && double(th.t) > tMin) {
                const Object& o = objects[id];
                best.t = th.t;
                best.object = int(id);
                best.geomNormal = normalize(cross(o.p1 - o.p0, o.p2 - o.p0));
                best.normal = o.smooth ? normalize((1 - th.u - th.v) * o.n0 + th.u * o.n1 + th.v * o.n2) : best.geomNormal;
                if (dot(best.normal, best.geomNormal) < 0) best.normal = -best.normal;
            }
        }
    }
    if (flat_.empty()) return best;
    const SlabRay sr(ray);
    const float fMin = lowerT(tMin);
    uint32_t stack[128];
    int sp = 0;
    if (boxEntry(flat_[0], sr, fMin, upperT(best.t)) == kFloatInf) return best;
    stack[sp++] = 0;
    while (sp > 0) {
        const FlatNode& node = flat_[stack[--sp]];
        if (node.count > 0) {
            for (uint32_t i = node.first; i < node.first + node.count; ++i) {
                const uint32_t id = prims_[i];
                if (intersect(objects[id], ray, tMin, best.t, sh)) {
                    best.t = sh.t;
                    best.object = int(id);
                    best.normal = sh.normal;
                    best.geomNormal = sh.geomNormal;
                    best.hasUV = sh.hasUV;
                    best.u = sh.u;
                    best.v = sh.v;
                    best.dpdu = sh.dpdu;
                }
            }
            continue;
        }
        const uint32_t l = node.first, r = node.first + 1;
        const float fMax = upperT(best.t);
        const float tl = boxEntry(flat_[l], sr, fMin, fMax);
        const float tr = boxEntry(flat_[r], sr, fMin, fMax);
        // Push the far child first so the near one is visited next.
        if (tl <= tr) {
            if (tr != kFloatInf) stack[sp++] = r;
            if (tl != kFloatInf) stack[sp++] = l;
        } else {
            if (tl != kFloatInf) stack[sp++] = l;
            stack[sp++] = r;
        }
    }
    return best;
}

int Bvh::anyBlocker(const std::vector<Object>& objects, const Ray& ray, double tMin, double tMax) const {
    for (uint32_t id : unbounded_)
        if (occludes(objects[id], ray, tMin, tMax)) return int(id);
    if (!triangles_.empty()) {
        const TriRay tr{{float(ray.origin.x), float(ray.origin.y), float(ray.origin.z)},
                        {float(ray.dir.x), float(ray.dir.y), float(ray.dir.z)}};
        // Float origins are rounded by up to half an ulp of their largest coordinate: widen the
        // interval's end by that much so that a blocker right at tMax is still found.
        const double slack = 1e-6 * (std::max({std::fabs(ray.origin.x), std::fabs(ray.origin.y), std::fabs(ray.origin.z)}) + 1.0);
        if (triangles_.occluded(tr, float(tMin), upperT(tMax + slack))) return kSomeTriangle;
    }
    if (flat_.empty()) return -1;
    const SlabRay sr(ray);
    const float fMin = lowerT(tMin), fMax = upperT(tMax);
    uint32_t stack[128];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const FlatNode& node = flat_[stack[--sp]];
        if (boxEntry(node, sr, fMin, fMax) == kFloatInf) continue;
        if (node.count > 0) {
            for (uint32_t i = node.first; i < node.first + node.count; ++i)
                if (occludes(objects[prims_[i]], ray, tMin, tMax)) return int(prims_[i]);
            continue;
        }
        stack[sp++] = node.first + 1;
        stack[sp++] = node.first;
    }
    return -1;
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
