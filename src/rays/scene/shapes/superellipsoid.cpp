// The ray is clipped to the unit box and cut where it crosses the planes x = 0, y = 0, z = 0 and
// |x| = |y| (where the absolute values make the function non-smooth), as in Franklin & Barr's
// "Faster calculation of superquadric shapes" (IEEE CG&A 1981); each piece is sampled for a sign
// change of f − 1, which regula falsi (Illinois) then pins down. A ray grazing the surface between two samples
// may miss it.
#include "rays/scene/shapes/superellipsoid.h"

#include <algorithm>
#include <cmath>

#include "rays/math/abs_power.h"
#include "rays/math/regula_falsi.h"

namespace rays {

namespace {

constexpr int kSamples = 12;  // per piece of the ray

// The superellipsoid's three powers.
struct SuperPowers {
    AbsPower u, v, ratio;  ///< 2/e, 2/n, e/n
    SuperPowers(double e, double n) : u(2 / e), v(2 / n), ratio(e / n) {}
};

// f(p) − 1 for f = (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n).
double superF(const SuperPowers& w, Vec3 p) { return w.ratio(w.u(p.x) + w.u(p.y)) + w.v(p.z) - 1; }

// Slab test against the box [-w, w]³: the ray's t range inside it.
bool clipToBox(const Ray& r, double w, double& t0, double& t1) {
    for (int a = 0; a < 3; ++a) {
        if (r.dir[a] == 0) {
            if (std::fabs(r.origin[a]) > w) return false;
            continue;
        }
        double n = (-w - r.origin[a]) / r.dir[a], f = (w - r.origin[a]) / r.dir[a];
        if (n > f) std::swap(n, f);
        t0 = std::max(t0, n);
        t1 = std::min(t1, f);
        if (t0 > t1) return false;
    }
    return true;
}

// The crossing of f − 1 = 0 between lo and hi (values flo and fhi of opposite signs), narrowed by
// regula falsi (math/regula_falsi.h; f is smooth within a piece) on 1 − f, whose sign is positive
// inside as the samples count it (f − 1 < 0).
double refineCrossing(const SuperPowers& w, const Ray& r, double lo, double flo, double hi, double fhi) {
    auto inward = [&](double t) { return -superF(w, r.at(t)); };
    illinoisBracket(inward, lo, -flo, hi, -fhi, [](double a, double b) { return b - a > 1e-13 * (1 + std::fabs(a)); }, 100);
    return 0.5 * (lo + hi);
}

// The hit at t: the outward normal is the gradient of f.
bool hitAt(double e, double n, const Ray& r, double t, double tMin, double tMax, ShapeHit& h) {
    if (!(t > tMin && t < tMax)) return false;
    h.t = t;
    const Vec3 p = r.at(t);
    const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
    const double A = std::pow(ax, 2 / e) + std::pow(ay, 2 / e);
    const double k = A > 0 ? std::pow(A, e / n - 1) : 0.0;
    Vec3 g{std::copysign(k * std::pow(ax, 2 / e - 1), p.x), std::copysign(k * std::pow(ay, 2 / e - 1), p.y),
           std::copysign(std::pow(az, 2 / n - 1), p.z)};
    if (!(length(g) > 0) || !std::isfinite(length(g))) g = p;
    h.normal = normalize(g);
    return true;
}

}  // namespace

bool hitSuperellipsoid(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const double e = o.r0, n = o.r1;
    const SuperPowers w(e, n);
    double t0 = tMin, t1 = tMax;
    if (!clipToBox(r, 1 + 1e-9, t0, t1)) return false;
    // Cut points: the coordinate planes and the planes x = ±y.
    double cuts[8];
    int m = 0;
    cuts[m++] = t0;
    for (int a = 0; a < 3; ++a)
        if (r.dir[a] != 0) cuts[m++] = -r.origin[a] / r.dir[a];
    if (r.dir.x != r.dir.y) cuts[m++] = (r.origin.y - r.origin.x) / (r.dir.x - r.dir.y);
    if (r.dir.x != -r.dir.y) cuts[m++] = -(r.origin.y + r.origin.x) / (r.dir.x + r.dir.y);
    cuts[m++] = t1;
    for (int i = 2; i < m - 1; ++i)  // insertion sort of the inner cuts
        for (int j = i; j > 1 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);
    double a = t0, fa = superF(w, r.at(t0));
    // With e and n at most 2 the solid is convex (f^(n/2) is then a norm), so a ray starting inside
    // it crosses its surface once, on the way out: if the box's far side (or tMax) is outside, that
    // stretch brackets the crossing, and no sampling is needed. (Secondary rays inside a glass
    // superellipsoid: three quarters of advanced/glasschess.pov's calls, 30 samples each.)
    if (fa < 0 && e <= 2 && n <= 2) {
        const double fb = superF(w, r.at(t1));
        return !(fb < 0) && hitAt(e, n, r, refineCrossing(w, r, t0, fa, t1, fb), tMin, tMax, h);
    }
    for (int i = 1; i < m; ++i) {
        const double end = std::clamp(cuts[i], t0, t1);
        if (end <= a) continue;
        for (int s = 1; s <= kSamples; ++s) {
            const double b = s == kSamples ? end : a + (end - a) / (kSamples - s + 1);
            const double fb = superF(w, r.at(b));
            if ((fa < 0) != (fb < 0)) return hitAt(e, n, r, refineCrossing(w, r, a, fa, b, fb), tMin, tMax, h);
            a = b;
            fa = fb;
        }
    }
    return false;
}

// Inside where f^(n/2) − 1, a measure of distance along the axes, is below 1e-10: POV-Ray 3.7's
// inside() measured 10^-4 … 10^-16 beyond the surface, the same for e, n = 0.5, 1 and 2 (scene/csg.cpp
// insideShape says why boundaries matter).
bool insideSuperellipsoid(const Object& o, Vec3 p) {
    const double n = o.r1;
    return superF(SuperPowers(o.r0, n), p) < std::expm1((2 / n) * std::log1p(1e-10));
}

}  // namespace rays
