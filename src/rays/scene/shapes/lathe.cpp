// A point of the curve (x(s), y(s)) lies on the ray P = O + tD when y(s) = O.y + t·D.y and
// x(s)² = ρ²(t), the ray's squared distance to the axis (a quadratic in t). Eliminating t (times
// D.y²) leaves D.y²·x(s)² − A(y(s) − O.y)² − B·D.y·(y(s) − O.y) − C·D.y² = 0, of degree 6 at most in
// s, solved by polyRoots on [0, 1]; a level ray (D.y ≈ 0) solves y(s) = O.y and then the
// quadratic in t. The ray is clipped to the box and its origin moved to the middle of that stretch.
#include "rays/scene/shapes/lathe.h"

#include <algorithm>
#include <cmath>

#include "rays/math/poly_roots.h"
#include "rays/scene/shapes/box_clip.h"

namespace rays {

namespace {

constexpr size_t kStride = 12;  // x0..x3, y0..y3, then the segment's y range and ρ² range
constexpr double kPad = 1e-9;  // joints are searched from both segments

// c = a · b for polynomials of degrees na and nb.
void polyMul(const double* a, int na, const double* b, int nb, double* c) {
    std::fill(c, c + na + nb + 1, 0.0);
    for (int i = 0; i <= na; ++i)
        for (int j = 0; j <= nb; ++j) c[i + j] += a[i] * b[j];
}

// The outward normal at the curve's parameter s of segment seg, the hit at p.
Vec3 latheNormal(const Object& o, const double* seg, double s, Vec3 p) {
    const double dx = cubicSlope(seg, s), dy = cubicSlope(seg + 4, s);
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    const Vec3 radial = rho > 0 ? Vec3{p.x / rho, 0, p.z / rho} : Vec3{1, 0, 0};
    const double side = cubicAt(seg, s) < 0 ? -1.0 : 1.0;  // a curve left of the axis is mirrored
    return o.r0 * (side * dy * radial + Vec3{0, -dx, 0});
}


// Whether the ray's stretch u ∈ [u0, u1] can meet the segment: it passes the segment's heights
// with its squared distance to the axis (Au² + Bu + C) within the segment's.
bool mayMeet(const double* seg, Vec3 O, Vec3 D, double A, double B, double C, double u0, double u1) {
    const double pad = 1e-9 * (1 + seg[9] - seg[8]);
    if (D.y != 0) {
        double a = (seg[8] - pad - O.y) / D.y, b = (seg[9] + pad - O.y) / D.y;
        if (a > b) std::swap(a, b);
        u0 = std::max(u0, a), u1 = std::min(u1, b);
        if (u0 > u1) return false;
    } else if (O.y < seg[8] - pad || O.y > seg[9] + pad) {
        return false;
    }
    const double f0 = C + u0 * (B + u0 * A), f1 = C + u1 * (B + u1 * A);
    double lo = std::min(f0, f1), hi = std::max(f0, f1);
    if (A > 0) {
        const double v = -B / (2 * A);
        if (v > u0 && v < u1) lo = std::min(lo, C + v * (B + v * A));
    }
    const double r2pad = 1e-9 * (1 + seg[11]);
    return hi >= seg[10] - r2pad && lo <= seg[11] + r2pad;
}

}  // namespace

bool makeLathe(const std::vector<Vec3>& p, LatheSpline spline, Object& o, ShapeData& data) {
    const size_t n = p.size();
    auto add = [&](Vec3 c0, Vec3 c1, Vec3 c2, Vec3 c3) {
        data.values.insert(data.values.end(), {c0.x, c1.x, c2.x, c3.x, c0.y, c1.y, c2.y, c3.y, 0, 0, 0, 0});
        double* seg = &data.values[data.values.size() - kStride];
        double xlo = kInfinity, xhi = -kInfinity;
        seg[8] = kInfinity, seg[9] = -kInfinity;
        cubicRange(seg, xlo, xhi);
        cubicRange(seg + 4, seg[8], seg[9]);
        seg[10] = xlo > 0 ? xlo * xlo : xhi < 0 ? xhi * xhi : 0.0;
        seg[11] = std::max(xlo * xlo, xhi * xhi);
    };
    switch (spline) {
        case LatheSpline::Linear:
            for (size_t i = 0; i + 1 < n; ++i) add(p[i], p[i + 1] - p[i], Vec3{}, Vec3{});
            break;
        case LatheSpline::Quadratic:  // the parabola through p[i], p[i+1], p[i+2] at s = −1, 0, 1
            for (size_t i = 0; i + 2 < n; ++i)
                add(p[i + 1], 0.5 * (p[i + 2] - p[i]), 0.5 * (p[i] - 2 * p[i + 1] + p[i + 2]), Vec3{});
            break;
        case LatheSpline::Cubic:  // Catmull-Rom
            for (size_t i = 0; i + 3 < n; ++i) {
                const Vec3 m0 = 0.5 * (p[i + 2] - p[i]), m1 = 0.5 * (p[i + 3] - p[i + 1]);
                add(p[i + 1], m0, 3 * (p[i + 2] - p[i + 1]) - 2 * m0 - m1, 2 * (p[i + 1] - p[i + 2]) + m0 + m1);
            }
            break;
        case LatheSpline::Bezier:
            for (size_t i = 0; i + 3 < n; i += 4)
                add(p[i], 3 * (p[i + 1] - p[i]), 3 * (p[i] - 2 * p[i + 1] + p[i + 2]),
                    p[i + 3] - p[i] + 3 * (p[i + 1] - p[i + 2]));
            break;
    }
    if (data.values.empty()) return false;
    // Bounds and the turning sense: the shoelace sum over the curve sampled, closed through the axis
    // (last point → the axis at its height → the axis at the first point's height → the first
    // point), so an open profile such as a vase counts the solid between it and the axis; for a
    // closed curve the closing adds nothing.
    double xlo = kInfinity, xhi = -kInfinity, ylo = kInfinity, yhi = -kInfinity, area = 0;
    for (size_t i = 0; i < data.values.size(); i += kStride) {
        const double* seg = &data.values[i];
        cubicRange(seg, xlo, xhi);
        cubicRange(seg + 4, ylo, yhi);
        for (int k = 0; k < 16; ++k) {
            const double a = k / 16.0, b = (k + 1) / 16.0;
            area += cubicAt(seg, a) * cubicAt(seg + 4, b) - cubicAt(seg, b) * cubicAt(seg + 4, a);
        }
    }
    const double* last = &data.values[data.values.size() - kStride];
    area += cubicAt(last, 1) * cubicAt(last + 4, 1) - data.values[0] * data.values[4];
    o.r0 = area >= 0 ? 1.0 : -1.0;
    const double r = std::max(std::fabs(xlo), std::fabs(xhi));
    data.bounds = Bounds{{-r, ylo, -r}, {r, yhi, r}};
    return r > 0 && yhi > ylo;
}

bool hitLathe(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const std::vector<double>& v = o.data->values;
    double t0 = tMin, t1 = tMax;
    if (!clipRayToBox(o.data->bounds, r, t0, t1)) return false;
    const double s0 = 0.5 * (t0 + t1);
    const Vec3 O = r.at(s0), D = r.dir;
    const double A = D.x * D.x + D.z * D.z, B = 2 * (O.x * D.x + O.z * D.z), C = O.x * O.x + O.z * O.z;
    const bool level = std::fabs(D.y) < 1e-9 * length(D);
    double best = tMax;
    Vec3 n;
    auto consider = [&](double u, const double* seg, double s) {
        const double t = u + s0;
        if (!(t > tMin && t < best)) return;
        best = t;
        n = latheNormal(o, seg, s, O + u * D);
    };
    const double u0 = t0 - s0, u1 = t1 - s0;
    for (size_t i = 0; i + kStride <= v.size(); i += kStride) {
        const double* seg = &v[i];
        if (!mayMeet(seg, O, D, A, B, C, u0, std::min(u1, best - s0))) continue;
        double ys[4] = {seg[4] - O.y, seg[5], seg[6], seg[7]};  // y(s) − O.y
        double roots[6];
        if (level) {
            const int k = polyRoots(ys, 3, -kPad, 1 + kPad, roots);
            for (int j = 0; j < k; ++j) {
                const double x = cubicAt(seg, roots[j]);
                // A u² + B u + C = x²
                const double disc = B * B - 4 * A * (C - x * x);
                if (A == 0 || disc < 0) continue;
                const double sq = std::sqrt(disc);
                consider((-B - sq) / (2 * A), seg, roots[j]);
                consider((-B + sq) / (2 * A), seg, roots[j]);
            }
            continue;
        }
        double xx[7], yy[7], p[7];
        polyMul(seg, 3, seg, 3, xx);
        polyMul(ys, 3, ys, 3, yy);
        const double e = D.y;
        for (int k = 0; k <= 6; ++k) p[k] = e * e * xx[k] - A * yy[k] - (k <= 3 ? B * e * ys[k] : 0.0);
        p[0] -= C * e * e;
        const int k = polyRoots(p, 6, -kPad, 1 + kPad, roots);
        for (int j = 0; j < k; ++j) consider(cubicAt(ys, roots[j]) / e, seg, roots[j]);
    }
    if (best == tMax) return false;
    h.t = best;
    h.normal = normalize(n);
    return true;
}

bool insideLathe(const Object& o, Vec3 p) {
    const std::vector<double>& v = o.data->values;
    const double rho = std::sqrt(p.x * p.x + p.z * p.z);
    bool in = false;
    for (size_t i = 0; i + kStride <= v.size(); i += kStride) {
        const double* seg = &v[i];
        const double ys[4] = {seg[4] - p.y, seg[5], seg[6], seg[7]};
        double roots[3];
        const int k = polyRoots(ys, 3, 0, 1, roots);
        for (int j = 0; j < k; ++j)
            if (std::fabs(cubicAt(seg, roots[j])) >= rho) in = !in;  // closed, as POV-Ray's inside()
    }
    return in;
}

}  // namespace rays
