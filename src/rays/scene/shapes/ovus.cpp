// The lemon is the part of the spindle torus (|P − Y|² + a² − ρ²)² − 4a²(x² + z²) = 0 (Y = (0, yc,
// 0); the torus implicit form of the reference's "Quartic" section) whose profile point (r, y)
// lies on the circle centred at (−a, yc): (r + a)² + (y − yc)² = ρ². Its roots along the ray come
// from polyRoots, the spheres' from quadratics; each piece counts only in its own height range.
#include "rays/scene/shapes/ovus.h"

#include <algorithm>
#include <cmath>

#include "rays/math/poly_roots.h"
#include "rays/scene/shapes/box_clip.h"

namespace rays {

namespace {

enum OvusSlot { kOvusA, kOvusYc, kOvusRho, kOvusYb, kOvusYt, kOvusSphereOnly, kOvusSlots };

struct OvusBest {
    double t;
    Vec3 n;
    void consider(double tMin, double t2, Vec3 n2) {
        if (t2 > tMin && t2 < t) t = t2, n = n2;
    }
};

// The sphere (centre c, radius rad)'s crossings, kept where keep(y) holds.
template <class Keep>
void ovusSphere(const Ray& r, Vec3 c, double rad, double tMin, OvusBest& best, Keep keep) {
    const Vec3 oc = r.origin - c;
    const double a = dot(r.dir, r.dir), b = dot(oc, r.dir), cc = dot(oc, oc) - rad * rad;
    const double disc = b * b - a * cc;
    if (disc <= 0) return;
    const double sq = std::sqrt(disc);
    for (double t : {(-b - sq) / a, (-b + sq) / a}) {
        const Vec3 p = r.at(t);
        if (keep(p.y)) best.consider(tMin, t, (p - c) / rad);
    }
}

}  // namespace

bool makeOvus(const Object& o, ShapeData& data) {
    const double rb = o.r0, rt = o.r1;
    if (!(rb > 0 && rt > 0)) return false;
    std::vector<double>& v = data.values;
    v.assign(kOvusSlots, 0.0);
    const double rho = 2 * std::max(rb, rt);
    // Tube centre (−a, yc): at ρ − rb from the bottom centre and ρ − rt from the top centre (0, rb).
    const double yc = ((rho - rb) * (rho - rb) - (rho - rt) * (rho - rt) + rb * rb) / (2 * rb);
    const double a2 = (rho - rb) * (rho - rb) - yc * yc;
    if (rt >= 2 * rb || !(a2 > 0)) {
        v[kOvusSphereOnly] = 1;
        data.bounds = Bounds{{-rt, rb - rt, -rt}, {rt, rb + rt, rt}};
        return true;
    }
    const double a = std::sqrt(a2);
    v[kOvusA] = a, v[kOvusYc] = yc, v[kOvusRho] = rho;
    v[kOvusYb] = yc - rho * yc / (rho - rb);         // where the tube circle touches the bottom sphere
    v[kOvusYt] = yc + rho * (rb - yc) / (rho - rt);  // ... and the top sphere
    const double lemon = (yc > v[kOvusYb] && yc < v[kOvusYt]) ? rho - a : 0.0;
    const double w = std::max({rb, rt, lemon});
    data.bounds = Bounds{{-w, -rb, -w}, {w, rb + rt, w}};
    return true;
}

bool hitOvus(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const double* v = o.data->values.data();
    const double rb = o.r0, rt = o.r1;
    OvusBest best{tMax, {}};
    if (v[kOvusSphereOnly] != 0) {
        ovusSphere(r, Vec3{0, rb, 0}, rt, tMin, best, [](double) { return true; });
    } else {
        const double yb = v[kOvusYb], yt = v[kOvusYt], a = v[kOvusA], yc = v[kOvusYc], rho = v[kOvusRho];
        ovusSphere(r, Vec3{}, rb, tMin, best, [&](double y) { return y <= yb; });
        ovusSphere(r, Vec3{0, rb, 0}, rt, tMin, best, [&](double y) { return y >= yt; });
        double t0 = tMin, t1 = best.t;
        if (clipRayToBox(o.data->bounds, r, t0, t1)) {
            // The quartic along the unit direction from the stretch's middle (coefficients of the
            // shape's size), centred on the tube centres' plane.
            const double len = length(r.dir);
            const Vec3 d = r.dir / len;
            const double s0 = 0.5 * (t0 + t1) * len;
            const Vec3 O = r.origin + s0 * d - Vec3{0, yc, 0};
            const double a1 = 2 * dot(O, d), b1 = dot(O, O) + a * a - rho * rho, k = 4 * a * a;
            const double coef[5] = {b1 * b1 - k * (O.x * O.x + O.z * O.z), 2 * a1 * b1 - 2 * k * (O.x * d.x + O.z * d.z),
                                    a1 * a1 + 2 * b1 - k * (d.x * d.x + d.z * d.z), 2 * a1, 1};
            double roots[4];
            const int n = polyRoots(coef, 4, t0 * len - s0 - 1e-9, t1 * len - s0 + 1e-9, roots);
            for (int i = 0; i < n; ++i) {
                const Vec3 p = O + roots[i] * d;  // relative to (0, yc, 0)
                const double y = p.y + yc;
                if (y < yb || y > yt) continue;
                const double rr = std::sqrt(p.x * p.x + p.z * p.z);
                const double inner = (rr + a) * (rr + a) + p.y * p.y, outer = (rr - a) * (rr - a) + p.y * p.y;
                if (std::fabs(inner - rho * rho) > std::fabs(outer - rho * rho)) continue;  // the outer (apple) sheet
                const Vec3 radial = rr > 0 ? Vec3{p.x / rr, 0, p.z / rr} : Vec3{};
                best.consider(tMin, (roots[i] + s0) / len, ((rr + a) * radial + Vec3{0, p.y, 0}) / rho);
            }
        }
    }
    if (!(best.t < tMax)) return false;
    h.t = best.t;
    h.normal = normalize(best.n);
    return true;
}

bool insideOvus(const Object& o, Vec3 p) {
    const double* v = o.data->values.data();
    const double rb = o.r0, rt = o.r1;
    const Vec3 top = p - Vec3{0, rb, 0};
    if (dot(top, top) < rt * rt) return true;
    if (v[kOvusSphereOnly] != 0) return false;
    if (dot(p, p) < rb * rb) return true;
    if (p.y <= v[kOvusYb] || p.y >= v[kOvusYt]) return false;
    const double rr = std::sqrt(p.x * p.x + p.z * p.z) + v[kOvusA], dy = p.y - v[kOvusYc];
    return rr * rr + dy * dy < v[kOvusRho] * v[kOvusRho];
}

}  // namespace rays
