#include "rays/scene/shapes/prism.h"

#include <algorithm>
#include <cmath>

#include "rays/math/poly_roots.h"
#include "rays/scene/shapes/box_clip.h"

namespace rays {

namespace {

constexpr int kStride = 5;
// A curved segment: x0..x3, z0..z3 (the cubics x(u), z(u)), side, xlo, xhi, zlo, zhi (its box),
// then the pieces on which z(u) is monotone: the count of cuts k (0–2), the cuts, and z at the
// k + 2 piece ends 0, cuts…, 1 (kPieceZ…).
constexpr size_t kCurveHead = 13;  // the cubics, side and box, as addCurve writes them
constexpr size_t kCurveStride = 20;
constexpr size_t kCuts = 13, kPieceZ = 16;
constexpr double kJointPad = 1e-9;   // segment ends are searched from both neighbours

// Even-odd rule by crossings along +x (as in polygon.cpp).
bool insideOutline(const std::vector<double>& e, double px, double pz) {
    bool in = false;
    for (size_t i = 0; i + kStride - 1 < e.size(); i += kStride) {
        const double x0 = e[i], z0 = e[i + 1], x1 = e[i + 2], z1 = e[i + 3];
        if ((z0 > pz) != (z1 > pz) && px < x0 + (pz - z0) * (x1 - x0) / (z1 - z0)) in = !in;
    }
    return in;
}

// Even-odd rule over curved segments: crossings of the ray from (px, pz) along +x. Each segment is
// cut where z(u) turns into pieces monotone in z; a piece crosses when (z > pz) differs at its two
// ends (the half-open rule of polygons, so a joint or a turning point on the ray counts right), and
// the crossing, found by bisection, counts when it lies at x > px.
// Where the cubic z(u) (c) takes the value pz on [lo, hi], a piece on which it is monotone and
// crosses pz: a straight segment's by division, else Newton's steps kept within the bracket,
// which shrinks with each step (bisection where a step would leave it).
double crossingOf(const double* c, double pz, double lo, double hi) {
    if (c[2] == 0 && c[3] == 0) return std::clamp((pz - c[0]) / c[1], lo, hi);
    const bool rising = cubicAt(c, hi) > cubicAt(c, lo);
    double u = 0.5 * (lo + hi);
    for (int n = 0; n < 60 && hi - lo > 1e-15; ++n) {
        const double f = cubicAt(c, u) - pz;
        if (f == 0) return u;
        ((f < 0) == rising ? lo : hi) = u;
        const double slope = cubicSlope(c, u);
        const double next = slope != 0 ? u - f / slope : lo - 1;
        if (std::fabs(next - u) < 1e-15 && next >= lo && next <= hi) return next;
        u = next > lo && next < hi ? next : 0.5 * (lo + hi);
    }
    return u;
}

bool insideCurves(const std::vector<double>& v, double px, double pz) {
    bool in = false;
    for (size_t i = 0; i + kCurveStride <= v.size(); i += kCurveStride) {
        const double* seg = &v[i];
        if (pz < seg[11] || pz > seg[12] || px >= seg[10]) continue;
        const int k = int(seg[kCuts]);
        const double* z = seg + kPieceZ;
        for (int j = 0; j <= k; ++j) {
            if ((z[j] > pz) == (z[j + 1] > pz)) continue;
            // Wholly right of the point, the segment's crossing counts without finding it.
            if (px < seg[9]) {
                in = !in;
                continue;
            }
            const double lo = j == 0 ? 0.0 : seg[kCuts + j], hi = j == k ? 1.0 : seg[kCuts + j + 1];
            if (cubicAt(seg, crossingOf(seg + 4, pz, lo, hi)) > px) in = !in;
        }
    }
    return in;
}

// A segment's monotone pieces of z(u) (see kCuts).
void setPieces(double* seg) {
    const double dz[3] = {seg[5], 2 * seg[6], 3 * seg[7]};
    double cuts[2] = {0, 0};
    const int k = polyRoots(dz, 2, 0, 1, cuts);
    seg[kCuts] = k;
    seg[kCuts + 1] = cuts[0];
    seg[kCuts + 2] = cuts[1];
    seg[kPieceZ] = cubicAt(seg + 4, 0);
    for (int j = 0; j < k; ++j) seg[kPieceZ + 1 + j] = cubicAt(seg + 4, cuts[j]);
    seg[kPieceZ + 1 + k] = cubicAt(seg + 4, 1);
}

// A segment (x(u), z(u) cubics) with its box; its side is set later.
void addCurve(std::vector<double>& v, Vec3 c0, Vec3 c1, Vec3 c2, Vec3 c3) {
    v.insert(v.end(), {c0.x, c1.x, c2.x, c3.x, c0.z, c1.z, c2.z, c3.z, 1.0, kInfinity, -kInfinity, kInfinity, -kInfinity});
    v.resize(v.size() + kCurveStride - kCurveHead);
    double* seg = &v[v.size() - kCurveStride];
    cubicRange(seg, seg[9], seg[10]);
    cubicRange(seg + 4, seg[11], seg[12]);
    setPieces(seg);
}

// The sub-prisms' segments by the reference's reading of each spline type; each closed outline's
// first segment index is pushed onto loops.
void readSegments(const std::vector<Vec3>& p, PrismSpline spline, std::vector<double>& v, std::vector<size_t>& loops) {
    const size_t n = p.size();
    size_t st = 0;
    switch (spline) {
        case PrismSpline::Linear:
            for (size_t i = 0; i < n; ++i) {
                const bool closes = i > st && p[i] == p[st];
                const bool last = i + 1 == n && i > st;
                if (!closes && !last) continue;
                loops.push_back(v.size());
                for (size_t k = st; k < i; ++k)
                    if (p[k] != p[k + 1]) addCurve(v, p[k], p[k + 1] - p[k], Vec3{}, Vec3{});
                if (!closes && p[i] != p[st]) addCurve(v, p[i], p[st] - p[i], Vec3{}, Vec3{});
                st = i + 1;
            }
            break;
        case PrismSpline::Quadratic:  // the parabola through p[i], p[i+1], p[i+2] at u = −1, 0, 1, drawn over [0, 1]
            while (st + 3 < n) {
                size_t k = st + 3;
                while (k < n && p[k] != p[st + 1]) ++k;
                if (k == n) break;
                loops.push_back(v.size());
                for (size_t i = st; i + 2 <= k; ++i)
                    addCurve(v, p[i + 1], 0.5 * (p[i + 2] - p[i]), 0.5 * (p[i] - 2 * p[i + 1] + p[i + 2]), Vec3{});
                st = k + 1;
            }
            break;
        case PrismSpline::Cubic:  // Catmull-Rom from p[i+1] to p[i+2]
            while (st + 4 < n) {
                size_t k = st + 3;
                while (k + 1 < n && p[k] != p[st + 1]) ++k;
                if (k + 1 >= n) break;
                loops.push_back(v.size());
                for (size_t i = st; i + 3 <= k + 1; ++i) {
                    const Vec3 m0 = 0.5 * (p[i + 2] - p[i]), m1 = 0.5 * (p[i + 3] - p[i + 1]);
                    addCurve(v, p[i + 1], m0, 3 * (p[i + 2] - p[i + 1]) - 2 * m0 - m1, 2 * (p[i + 1] - p[i + 2]) + m0 + m1);
                }
                st = k + 2;
            }
            break;
        case PrismSpline::Bezier:
            while (st + 3 < n) {
                size_t i = st;
                const size_t first = v.size();
                bool closed = false;
                for (; i + 3 < n && !closed; i += 4) {
                    addCurve(v, p[i], 3 * (p[i + 1] - p[i]), 3 * (p[i] - 2 * p[i + 1] + p[i + 2]),
                             p[i + 3] - p[i] + 3 * (p[i + 1] - p[i + 2]));
                    closed = p[i + 3] == p[st];
                }
                if (!closed) {
                    v.resize(first);
                    break;
                }
                loops.push_back(first);
                st = i;
            }
            break;
    }
    loops.push_back(v.size());
}

// The outward side of segment i: a point just off its middle, on the side (z', −x'), is outside.
double curveSide(const std::vector<double>& v, size_t i) {
    const double* seg = &v[i];
    for (double u : {0.5, 0.25, 0.75}) {
        const double dx = cubicSlope(seg, u), dz = cubicSlope(seg + 4, u);
        const double len = std::sqrt(dx * dx + dz * dz);
        if (!(len > 0)) continue;
        const double size = seg[10] - seg[9] + seg[12] - seg[11];
        const double eps = 1e-7 * (1 + size);
        return insideCurves(v, cubicAt(seg, u) + eps * dz / len, cubicAt(seg + 4, u) - eps * dx / len) ? -1.0 : 1.0;
    }
    return 1.0;
}

// Walls of a curved prism: each segment's crossings with the ray, nearest in (tMin, best) kept.
// Linear sweep: the ray's x-z projection meets (x(u), z(u)): (x − Ox)·Dz − (z − Oz)·Dx = 0.
// Conic sweep: the wall's line through the origin and (x(u), 1, z(u)) lies in the plane of the
// origin and the ray: (O × D)·(x(u), 1, z(u)) = 0. Either is a cubic in u.
void curvedWalls(const Object& o, Vec3 O, Vec3 D, double shift, double tMin, double& best, Vec3& n) {
    const std::vector<double>& v = o.data->values;
    const bool conic = o.data->conic;
    const Vec3 N = cross(O, D);
    const double a = conic ? N.x : D.z, b = conic ? N.z : -D.x, c = conic ? N.y : O.z * D.x - O.x * D.z;
    if (!conic && D.x == 0 && D.z == 0) return;
    const double flat = D.x * D.x + D.z * D.z;
    for (size_t i = 0; i + kCurveStride <= v.size(); i += kCurveStride) {
        const double* seg = &v[i];
        // The line (or plane) a·x + b·z + c = 0 must pass through the segment's box.
        const double f0 = a * seg[9] + b * seg[11], f1 = a * seg[10] + b * seg[11];
        const double f2 = a * seg[9] + b * seg[12], f3 = a * seg[10] + b * seg[12];
        const double lo = std::min(std::min(f0, f1), std::min(f2, f3)) + c, hi = std::max(std::max(f0, f1), std::max(f2, f3)) + c;
        const double pad = 1e-9 * (std::fabs(lo) + std::fabs(hi));
        if (lo > pad || hi < -pad) continue;
        const double p[4] = {a * seg[0] + b * seg[4] + c, a * seg[1] + b * seg[5], a * seg[2] + b * seg[6], a * seg[3] + b * seg[7]};
        // The cubic's Bernstein coefficients on [0, 1] bound it (the convex hull property): all of
        // one sign, by more than the joints' padding can change it, and it has no root there.
        const double b1 = p[0] + p[1] / 3, b2 = b1 + (p[1] + p[2]) / 3, b3 = p[0] + p[1] + p[2] + p[3];
        const double hull = 1e-8 * (std::fabs(p[0]) + std::fabs(b1) + std::fabs(b2) + std::fabs(b3));
        if ((p[0] > hull && b1 > hull && b2 > hull && b3 > hull) || (p[0] < -hull && b1 < -hull && b2 < -hull && b3 < -hull))
            continue;
        double roots[3];
        const int k = polyRoots(p, 3, -kJointPad, 1 + kJointPad, roots);
        for (int j = 0; j < k; ++j) {
            const double x = cubicAt(seg, roots[j]), z = cubicAt(seg + 4, roots[j]);
            double u;
            if (!conic) {
                u = ((x - O.x) * D.x + (z - O.z) * D.z) / flat;
            } else {
                const double dx = D.x - x * D.y, dz = D.z - z * D.y;
                if (dx == 0 && dz == 0) continue;
                u = std::fabs(dx) > std::fabs(dz) ? (x * O.y - O.x) / dx : (z * O.y - O.z) / dz;
            }
            const double t = u + shift;
            if (!(t > tMin && t < best)) continue;
            const double y = O.y + u * D.y;
            if (y < o.r0 || y > o.r1) continue;
            const double xs = cubicSlope(seg, roots[j]), zs = cubicSlope(seg + 4, roots[j]);
            best = t;
            n = conic ? (seg[8] * (y < 0 ? -1.0 : 1.0)) * Vec3{zs, z * xs - x * zs, -xs} : seg[8] * Vec3{zs, 0, -xs};
        }
    }
}

bool hitCurvedPrism(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    double t0 = tMin, t1 = tMax;
    if (!clipRayToBox(o.data->bounds, r, t0, t1)) return false;
    const double shift = 0.5 * (t0 + t1);  // the ray from near the prism (precision for far cameras)
    const Vec3 O = r.at(shift), D = r.dir;
    const std::vector<double>& v = o.data->values;
    double best = tMax;
    Vec3 n;
    if (!o.open && D.y != 0) {
        const double ys[2] = {o.r0, o.r1};
        for (int c = 0; c < 2; ++c) {
            const double u = (ys[c] - O.y) / D.y, t = u + shift;
            const double scale = o.data->conic ? ys[c] : 1.0;
            if (!(t > tMin && t < best) || scale == 0) continue;
            const Vec3 p = O + u * D;
            if (!insideCurves(v, p.x / scale, p.z / scale)) continue;
            best = t;
            n = Vec3{0, c == 0 ? -1.0 : 1.0, 0};
        }
    }
    curvedWalls(o, O, D, shift, tMin, best, n);
    if (best == tMax) return false;
    h.t = best;
    h.normal = normalize(n);
    return true;
}

}  // namespace

bool makeSplinePrism(const std::vector<Vec3>& pts, PrismSpline spline, bool conic, double y0, double y1,
                     ShapeData& data) {
    if (!(y1 > y0)) return false;
    std::vector<double>& v = data.values;
    std::vector<size_t> loops;
    readSegments(pts, spline, v, loops);
    if (v.empty()) return false;
    data.order = 3;
    data.conic = conic;
    // Outward sides; as makePrism, a long outline is decided by its first segment.
    constexpr size_t kSegmentBySegment = 256;
    for (size_t l = 0; l + 1 < loops.size(); ++l) {
        const size_t b = loops[l], end = loops[l + 1];
        if (b == end) continue;
        const bool each = (end - b) / kCurveStride <= kSegmentBySegment;
        const double first = curveSide(v, b);
        for (size_t i = b; i < end; i += kCurveStride) v[i + 8] = each ? curveSide(v, i) : first;
    }
    double xlo = kInfinity, xhi = -kInfinity, zlo = kInfinity, zhi = -kInfinity;
    for (size_t i = 0; i < v.size(); i += kCurveStride) {
        xlo = std::min(xlo, v[i + 9]), xhi = std::max(xhi, v[i + 10]);
        zlo = std::min(zlo, v[i + 11]), zhi = std::max(zhi, v[i + 12]);
    }
    for (double y : {y0, y1}) {
        const double s = conic ? y : 1.0;
        data.bounds.extend(Vec3{s * xlo, y, s * zlo});
        data.bounds.extend(Vec3{s * xhi, y, s * zhi});
    }
    return true;
}

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
    if (o.data->order == 3) return hitCurvedPrism(o, r, tMin, tMax, h);
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
    if (!(p.y >= o.r0 && p.y < o.r1)) return false;  // POV-Ray 3.7's inside(): bottom closed, top open
    if (o.data->order != 3) return insideOutline(o.data->values, p.x, p.z);
    const double s = o.data->conic ? p.y : 1.0;
    return s != 0 && insideCurves(o.data->values, p.x / s, p.z / s);
}

}  // namespace rays
