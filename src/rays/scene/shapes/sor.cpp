// Along the ray P = O + tD the squared distance to the axis is a quadratic in t and the height is
// linear, so each segment's r²(y) makes a cubic in t (no division by D's y, so level rays need no
// special case), solved by polyRoots within the heights of the segment; the caps are discs. The
// ray is clipped to the box and its origin moved to the middle of that stretch first.
#include "rays/scene/shapes/sor.h"

#include <algorithm>
#include <cmath>

#include "rays/math/poly_roots.h"
#include "rays/scene/shapes/box_clip.h"

namespace rays {

namespace {

constexpr size_t kStride = 6;

double radius2(const double* v, double y) {
    const double w = y - v[0];
    return v[2] + w * (v[3] + w * (v[4] + w * v[5]));
}

double slope2(const double* v, double y) {
    const double w = y - v[0];
    return v[3] + w * (2 * v[4] + w * 3 * v[5]);
}

}  // namespace

bool makeSor(const std::vector<Vec3>& p, ShapeData& data) {
    const size_t n = p.size();
    if (n < 4) return false;
    for (size_t i = 1; i + 2 < n; ++i)  // the curve's own points rise; the outer two may repeat a height
        if (!(p[i + 1].y > p[i].y) || !(p[i + 1].y > p[i - 1].y) || !(p[i + 2].y > p[i].y)) return false;
    double most = 0;
    for (size_t j = 1; j + 2 < n; ++j) {
        const double h0 = p[j].y, h1 = p[j + 1].y, L = h1 - h0;
        const double R0 = p[j].x * p[j].x, R1 = p[j + 1].x * p[j + 1].x;
        const double m0 = 2 * p[j].x * (p[j + 1].x - p[j - 1].x) / (p[j + 1].y - p[j - 1].y);
        const double m1 = 2 * p[j + 1].x * (p[j + 2].x - p[j].x) / (p[j + 2].y - p[j].y);
        const double c = (3 * (R1 - R0) / L - 2 * m0 - m1) / L, d = (m0 + m1 - 2 * (R1 - R0) / L) / (L * L);
        const double seg[kStride] = {h0, h1, R0, m0, c, d};
        data.values.insert(data.values.end(), seg, seg + kStride);
        // The largest r² on the segment: its ends and where its slope is 0.
        most = std::max({most, R0, R1});
        const double dc[3] = {m0, 2 * c, 3 * d};
        double roots[2];
        const int k = polyRoots(dc, 2, 0, L, roots);
        for (int i = 0; i < k; ++i) most = std::max(most, radius2(seg, h0 + roots[i]));
    }
    const double r = std::sqrt(most);
    data.bounds = Bounds{{-r, p[1].y, -r}, {r, p[n - 2].y, r}};
    return r > 0;
}

bool hitSor(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const std::vector<double>& v = o.data->values;
    const Bounds& box = o.data->bounds;
    double t0 = tMin, t1 = tMax;
    if (!clipRayToBox(box, r, t0, t1)) return false;
    const double s0 = 0.5 * (t0 + t1);
    const Vec3 O = r.at(s0), D = r.dir;
    const double A = D.x * D.x + D.z * D.z, B = 2 * (O.x * D.x + O.z * D.z), C = O.x * O.x + O.z * O.z;
    double best = tMax;
    Vec3 n;
    const double u0 = t0 - s0, u1 = t1 - s0;
    for (size_t i = 0; i + kStride <= v.size(); i += kStride) {
        const double* seg = &v[i];
        double ua = u0, ub = u1;
        if (D.y != 0) {
            double a = (seg[0] - O.y) / D.y, b = (seg[1] - O.y) / D.y;
            if (a > b) std::swap(a, b);
            const double pad = 1e-9 * (b - a);  // joints are searched from both sides
            ua = std::max(ua, a - pad), ub = std::min(ub, b + pad);
        } else if (O.y < seg[0] || O.y > seg[1]) {
            continue;
        }
        if (!(ua < ub) || ua + s0 >= best) continue;
        // r²(w) with w = w0 + u·Dy, expanded in u.
        const double w0 = O.y - seg[0], e = D.y;
        const double a = seg[2], b = seg[3], c = seg[4], d = seg[5];
        const double poly[4] = {C - (a + w0 * (b + w0 * (c + w0 * d))), B - e * (b + w0 * (2 * c + 3 * d * w0)),
                                A - e * e * (c + 3 * d * w0), -d * e * e * e};
        double roots[3];
        const int k = polyRoots(poly, 3, ua, ub, roots);
        for (int j = 0; j < k; ++j) {
            const double t = roots[j] + s0;
            if (!(t > tMin && t < best)) continue;
            const Vec3 p = O + roots[j] * D;
            best = t;
            n = Vec3{2 * p.x, -slope2(seg, std::clamp(p.y, seg[0], seg[1])), 2 * p.z};
            break;
        }
    }
    if (!o.open && D.y != 0 && !v.empty()) {
        const double* first = &v[0];
        const double* last = &v[v.size() - kStride];
        const double ys[2] = {first[0], last[1]};
        const double rr[2] = {first[2], radius2(last, last[1])};
        for (int c = 0; c < 2; ++c) {
            const double t = (ys[c] - r.origin.y) / D.y;
            if (!(t > tMin && t < best)) continue;
            const Vec3 p = r.at(t);
            if (p.x * p.x + p.z * p.z >= rr[c]) continue;
            best = t;
            n = Vec3{0, c == 0 ? -1.0 : 1.0, 0};
        }
    }
    if (best == tMax) return false;
    h.t = best;
    h.normal = normalize(n);
    return true;
}

bool insideSor(const Object& o, Vec3 p) {
    const std::vector<double>& v = o.data->values;
    for (size_t i = 0; i + kStride <= v.size(); i += kStride)
        if (p.y > v[i] && p.y <= v[i + 1]) return p.x * p.x + p.z * p.z < radius2(&v[i], p.y);
    return false;
}

}  // namespace rays
