// Each segment, the convex hull of spheres (c0, r0) and (c1, r1), is the union of the two spheres
// and a frustum: the spheres between touch the envelope on circles at axial offset r·sin α from
// their centres (sin α = (r0 − r1)/L, L the centres' distance), of radius r·cos α. A ray's stretch
// inside the hull is one interval (the hull is convex): the union of its stretches in the two
// spheres and in the frustum. The sweep's surface is the first end of such an interval that lies
// inside no other segment.
#include "rays/scene/shapes/sphere_sweep.h"

#include <algorithm>
#include <cmath>

namespace rays {

namespace {

// c0 (3), r0, c1 (3), r1, the axis w (3), the frustum's z0 and z1 along w from c0, and its
// radius a + b·z.
constexpr size_t kStride = 15;

struct Stretch {
    double in = kInfinity, out = -kInfinity;
    Vec3 nIn, nOut;
    void add(double t0, Vec3 n0, double t1, Vec3 n1) {
        if (t0 < in) in = t0, nIn = n0;
        if (t1 > out) out = t1, nOut = n1;
    }
};

Vec3 vec(const double* v) { return Vec3{v[0], v[1], v[2]}; }

void sphereStretch(Vec3 c, double rad, const Ray& r, Stretch& s) {
    const Vec3 oc = r.origin - c;
    const double a = dot(r.dir, r.dir), b = dot(oc, r.dir), cc = dot(oc, oc) - rad * rad;
    const double disc = b * b - a * cc;
    if (rad <= 0 || disc <= 0) return;
    const double sq = std::sqrt(disc);
    const double t0 = (-b - sq) / a, t1 = (-b + sq) / a;
    s.add(t0, (r.at(t0) - c) / rad, t1, (r.at(t1) - c) / rad);
}

// The ray's stretch in {z0 ≤ z ≤ z1, ρ < a + b·z} (z along w from c0, ρ the distance to the axis).
void frustumStretch(const double* v, const Ray& r, Stretch& s) {
    const Vec3 c0 = vec(v), w = vec(v + 8);
    const double z0 = v[11], z1 = v[12], a = v[13], b = v[14];
    if (!(z1 > z0)) return;
    const Vec3 o = r.origin - c0;
    const double oz = dot(o, w), dz = dot(r.dir, w);
    double lo = -kInfinity, hi = kInfinity;  // the slab
    if (dz != 0) {
        lo = (z0 - oz) / dz, hi = (z1 - oz) / dz;
        if (lo > hi) std::swap(lo, hi);
    } else if (oz < z0 || oz > z1) {
        return;
    }
    // ρ² − (a + b z)² as A t² + B t + C.
    const Vec3 op = o - oz * w, dp = r.dir - dz * w;
    const double ra = a + b * oz, rb = b * dz;
    const double A = dot(dp, dp) - rb * rb, B = 2 * (dot(op, dp) - ra * rb), C = dot(op, op) - ra * ra;
    double t0 = lo, t1 = hi;
    if (std::fabs(A) < 1e-14 * (dot(r.dir, r.dir) + rb * rb)) {
        if (B == 0) {
            if (C >= 0) return;
        } else if (B > 0) {
            t1 = std::min(t1, -C / B);
        } else {
            t0 = std::max(t0, -C / B);
        }
    } else {
        const double disc = B * B - 4 * A * C;
        if (disc <= 0) {
            if (A > 0) return;  // never inside the cone; otherwise always (within the slab)
        } else {
            const double sq = std::sqrt(disc);
            double q0 = (-B - sq) / (2 * A), q1 = (-B + sq) / (2 * A);
            if (q0 > q1) std::swap(q0, q1);
            if (A > 0) {
                t0 = std::max(t0, q0), t1 = std::min(t1, q1);
            } else {  // inside outside the roots: the slab's part on one side (the region is convex)
                const bool left = t0 < q0, right = t1 > q1;
                if (left && !right) t1 = std::min(t1, q0);
                else if (right && !left) t0 = std::max(t0, q1);
                else if (!left && !right) return;
            }
        }
    }
    if (!(t0 < t1) || !std::isfinite(t0) || !std::isfinite(t1)) return;
    auto normal = [&](double t) {
        const Vec3 p = r.at(t) - c0;
        const Vec3 radial = p - dot(p, w) * w;
        const double rho = length(radial);
        const Vec3 n = (rho > 0 ? radial / rho : Vec3{}) - b * w;
        return normalize(n);
    };
    s.add(t0, normal(t0), t1, normal(t1));
}

// Whether p is inside segment v by more than eps.
bool insideSegment(const double* v, Vec3 p, double eps) {
    const Vec3 c0 = vec(v), c1 = vec(v + 4), w = vec(v + 8);
    if (length(p - c0) < v[3] - eps || length(p - c1) < v[7] - eps) return true;
    const double z = dot(p - c0, w);
    if (!(z > v[11] + eps && z < v[12] - eps)) return false;
    return length(p - c0 - z * w) < v[13] + v[14] * z - eps;
}

}  // namespace

bool makeSphereSweep(const std::vector<Vec3>& c, const std::vector<double>& rad, ShapeData& data) {
    for (size_t i = 0; i + 1 < c.size() && i + 1 < rad.size(); ++i) {
        const double r0 = std::fabs(rad[i]), r1 = std::fabs(rad[i + 1]);
        const Vec3 d = c[i + 1] - c[i];
        const double L = length(d);
        double seg[kStride] = {c[i].x, c[i].y, c[i].z, r0, c[i + 1].x, c[i + 1].y, c[i + 1].z, r1, 0, 0, 1, 0, 0, 0, 0};
        if (L > std::fabs(r0 - r1)) {  // otherwise one sphere holds the other: no frustum
            const Vec3 w = d / L;
            const double sinA = (r0 - r1) / L, cosA = std::sqrt(1 - sinA * sinA);
            const double z0 = r0 * sinA, z1 = L + r1 * sinA;
            const double b = (r1 - r0) * cosA / (z1 - z0);
            const double rest[7] = {w.x, w.y, w.z, z0, z1, r0 * cosA - b * z0, b};
            std::copy(rest, rest + 7, seg + 8);
        }
        data.values.insert(data.values.end(), seg, seg + kStride);
        for (const Vec3 p : {c[i], c[i + 1]}) {
            const double rr = p == c[i] ? r0 : r1;
            data.bounds.extend(p - Vec3(rr));
            data.bounds.extend(p + Vec3(rr));
        }
    }
    return !data.values.empty() && !data.bounds.empty() && data.bounds.extent().x + data.bounds.extent().y > 0;
}

bool makeSplineSphereSweep(const std::vector<Vec3>& c, const std::vector<double>& rad, bool bSpline, ShapeData& data) {
    const size_t n = std::min(c.size(), rad.size());
    if (n < 4) return false;
    std::vector<Vec3> centres;
    std::vector<double> radii;
    // Basis weights of P(i) ... P(i+3) at parameter u of a segment.
    auto weights = [&](double u, double w[4]) {
        const double u2 = u * u, u3 = u2 * u, m = 1 - u;
        if (bSpline) {
            w[0] = m * m * m / 6, w[1] = (3 * u3 - 6 * u2 + 4) / 6, w[2] = (-3 * u3 + 3 * u2 + 3 * u + 1) / 6, w[3] = u3 / 6;
        } else {  // Catmull-Rom
            w[0] = 0.5 * (-u3 + 2 * u2 - u), w[1] = 0.5 * (3 * u3 - 5 * u2 + 2), w[2] = 0.5 * (-3 * u3 + 4 * u2 + u),
            w[3] = 0.5 * (u3 - u2);
        }
    };
    for (size_t i = 0; i + 3 < n; ++i)
        for (int k = 0; k <= kSplineSweepSamples; ++k) {
            if (k == 0 && i > 0) continue;  // the previous segment's end
            double w[4];
            weights(double(k) / kSplineSweepSamples, w);
            Vec3 p;
            double r = 0;
            for (int j = 0; j < 4; ++j) p += w[j] * c[i + size_t(j)], r += w[j] * rad[i + size_t(j)];
            centres.push_back(p);
            radii.push_back(r);
        }
    return makeSphereSweep(centres, radii, data);
}

bool hitSphereSweep(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const std::vector<double>& v = o.data->values;
    const double eps = 1e-9 * (1 + length(o.data->bounds.extent()));
    double best = tMax;
    Vec3 bestN;
    for (size_t i = 0; i + kStride <= v.size(); i += kStride) {
        Stretch s;
        sphereStretch(vec(&v[i]), v[i + 3], r, s);
        sphereStretch(vec(&v[i + 4]), v[i + 7], r, s);
        frustumStretch(&v[i], r, s);
        if (!(s.in < s.out)) continue;
        for (int end = 0; end < 2; ++end) {
            const double t = end == 0 ? s.in : s.out;
            if (!(t > tMin && t < best)) continue;
            // On the sweep's surface only when no other segment holds the point.
            const Vec3 p = r.at(t);
            bool covered = false;
            for (size_t j = 0; j + kStride <= v.size() && !covered; j += kStride)
                covered = j != i && insideSegment(&v[j], p, eps);
            if (covered) continue;
            best = t;
            bestN = end == 0 ? s.nIn : s.nOut;
            break;
        }
    }
    if (best == tMax) return false;
    h.t = best;
    h.normal = normalize(bestN);
    return true;
}

bool insideSphereSweep(const Object& o, Vec3 p) {
    const std::vector<double>& v = o.data->values;
    for (size_t i = 0; i + kStride <= v.size(); i += kStride)
        if (insideSegment(&v[i], p, 0)) return true;
    return false;
}

}  // namespace rays
