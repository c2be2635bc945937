#include "rays/scene/shapes/prism.h"

#include <cmath>

namespace rays {

namespace {

constexpr int kStride = 5;

// Even-odd rule by crossings along +x (as in polygon.cpp).
bool insideOutline(const std::vector<double>& e, double px, double pz) {
    bool in = false;
    for (size_t i = 0; i + kStride - 1 < e.size(); i += kStride) {
        const double x0 = e[i], z0 = e[i + 1], x1 = e[i + 2], z1 = e[i + 3];
        if ((z0 > pz) != (z1 > pz) && px < x0 + (pz - z0) * (x1 - x0) / (z1 - z0)) in = !in;
    }
    return in;
}

}  // namespace

bool makePrism(const std::vector<Vec3>& pts, double y0, double y1, ShapeData& data) {
    std::vector<double>& e = data.values;
    std::vector<size_t> loops;  // where each closed outline's edges start in e
    auto add = [&](Vec3 a, Vec3 b) {
        if (a == b) return;
        e.insert(e.end(), {a.x, a.z, b.x, b.z, 1.0});
    };
    size_t start = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        data.bounds.extend(Vec3{pts[i].x, y0, pts[i].z});
        data.bounds.extend(Vec3{pts[i].x, y1, pts[i].z});
        if (i > start && pts[i] == pts[start]) {
            loops.push_back(e.size());
            for (size_t k = start; k < i; ++k) add(pts[k], pts[k + 1]);
            start = i + 1;
        }
    }
    if (pts.size() - start >= 2) {  // an unclosed last sub-prism is closed
        loops.push_back(e.size());
        for (size_t k = start; k + 1 < pts.size(); ++k) add(pts[k], pts[k + 1]);
        add(pts.back(), pts[start]);
    }
    loops.push_back(e.size());
    // Each edge's outward side: a point just off its middle on that side is outside.
    auto outward = [&](size_t i) {
        const double dx = e[i + 2] - e[i], dz = e[i + 3] - e[i + 1];
        const double len = std::sqrt(dx * dx + dz * dz);
        const double eps = 1e-7 * (1 + len);
        const double mx = 0.5 * (e[i] + e[i + 2]) + eps * dz / len, mz = 0.5 * (e[i + 1] + e[i + 3]) - eps * dx / len;
        return insideOutline(e, mx, mz) ? -1.0 : 1.0;
    };
    // Testing every edge against the whole outline is quadratic (issue 27: 100k points took 20 s).
    // The edges of one simple closed outline all have the outside on the same hand, so a long one
    // is decided by its first edge; short ones (and so self-crossing small outlines) edge by edge.
    constexpr size_t kEdgeByEdge = 256;
    for (size_t l = 0; l + 1 < loops.size(); ++l) {
        const size_t b = loops[l], end = loops[l + 1];
        if (b == end) continue;
        if ((end - b) / kStride <= kEdgeByEdge) {
            for (size_t i = b; i < end; i += kStride) e[i + 4] = outward(i);
        } else {
            const double side = outward(b);
            for (size_t i = b; i < end; i += kStride) e[i + 4] = side;
        }
    }
    return !e.empty();
}

bool hitPrism(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const std::vector<double>& e = o.data->values;
    double best = tMax;
    Vec3 n;
    // Caps.
    if (!o.open && r.dir.y != 0) {
        const double ys[2] = {o.r0, o.r1};
        for (int c = 0; c < 2; ++c) {
            const double t = (ys[c] - r.origin.y) / r.dir.y;
            if (!(t > tMin && t < best)) continue;
            const Vec3 p = r.at(t);
            if (!insideOutline(e, p.x, p.z)) continue;
            best = t;
            n = Vec3{0, c == 0 ? -1.0 : 1.0, 0};
        }
    }
    // Sides: the ray's x-z projection against each edge.
    for (size_t i = 0; i + kStride - 1 < e.size(); i += kStride) {
        const double ex = e[i + 2] - e[i], ez = e[i + 3] - e[i + 1];
        const double den = r.dir.x * ez - r.dir.z * ex;
        if (den == 0) continue;
        const double wx = e[i] - r.origin.x, wz = e[i + 1] - r.origin.z;
        const double t = (wx * ez - wz * ex) / den;
        if (!(t > tMin && t < best)) continue;
        const double s = (wx * r.dir.z - wz * r.dir.x) / den;
        if (s < 0 || s > 1) continue;
        const double y = r.origin.y + t * r.dir.y;
        if (y < o.r0 || y > o.r1) continue;
        best = t;
        n = e[i + 4] * Vec3{ez, 0, -ex};
    }
    if (best == tMax) return false;
    h.t = best;
    h.normal = normalize(n);
    return true;
}

bool insidePrism(const Object& o, Vec3 p) {
    return p.y > o.r0 && p.y < o.r1 && insideOutline(o.data->values, p.x, p.z);
}

}  // namespace rays
