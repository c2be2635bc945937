// The torus as the quartic (|P|² + R² − r²)² − 4R²(x² + z²) = 0 (the implicit form in the POV-Ray
// reference's "Quartic" section, axis y), solved along the ray by polyRoots. For accuracy the
// ray is first normalised, clipped to the bounding sphere of radius R + r, and its origin moved
// to its point nearest the centre, so the quartic's coefficients stay of the size of the torus.
#include "rays/scene/shapes/torus.h"

#include <algorithm>
#include <cmath>

#include "rays/math/poly_roots.h"

namespace rays {

namespace {

// Narrows [sLo, sHi] (along the unit direction d from o) to the slab |y| ≤ r, widened a little as
// the bounding sphere is, and says false when the ray misses the torus' shell there: all of it
// within the hole (distance from the y axis below |R| − r) or all of it beyond |R| + r. Cheap
// tests that spare the quartic most rays through a thin ring's box.
bool clipToTorusShell(Vec3 o, Vec3 d, double R, double r, double& sLo, double& sHi) {
    const double half = 1.001 * r;
    if (d.y != 0) {
        double a = (-half - o.y) / d.y, b = (half - o.y) / d.y;
        if (a > b) std::swap(a, b);
        sLo = std::max(sLo, a);
        sHi = std::min(sHi, b);
        if (!(sLo < sHi)) return false;
    } else if (std::fabs(o.y) > half) {
        return false;
    }
    // ρ²(s) = |o_xz + s·d_xz|², a convex quadratic: its largest value on the interval is at an end,
    // its smallest at the vertex when that lies inside.
    auto rho2 = [&](double s) {
        const double x = o.x + s * d.x, z = o.z + s * d.z;
        return x * x + z * z;
    };
    const double aLo = rho2(sLo), aHi = rho2(sHi);
    const double inner = std::fabs(R) - half;
    if (inner > 0 && std::max(aLo, aHi) < inner * inner) return false;  // in the hole throughout
    const double flat = d.x * d.x + d.z * d.z;
    double least = std::min(aLo, aHi);
    if (flat > 0) {
        const double v = -(o.x * d.x + o.z * d.z) / flat;
        if (v > sLo && v < sHi) least = std::min(least, rho2(v));
    }
    const double outer = std::fabs(R) + half;
    return least <= outer * outer;
}

}  // namespace

bool hitTorus(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const double R = o.r0, rr = o.r1;
    // The bounding sphere, a little wider so that no root lies on its ends: first missed or not
    // with the direction as it is (no root, no division), then s along the unit direction.
    const double bound = 1.001 * (std::fabs(R) + rr);
    const double dd = dot(r.dir, r.dir), od = dot(r.origin, r.dir), oo = dot(r.origin, r.origin) - bound * bound;
    if (od * od - dd * oo <= 0) return false;
    const double len = std::sqrt(dd);
    const Vec3 d = r.dir / len;
    const double b = dot(r.origin, d);
    const double c = dot(r.origin, r.origin) - bound * bound;
    const double disc = b * b - c;
    if (disc <= 0) return false;
    const double sq = std::sqrt(disc);
    double sLo = std::max(-b - sq, tMin * len), sHi = std::min(-b + sq, tMax * len);
    if (!(sLo < sHi)) return false;
    if (!clipToTorusShell(r.origin, d, R, rr, sLo, sHi)) return false;
    const double s0 = -b;  // shifted origin: the ray's point nearest the centre
    const Vec3 O = r.origin + s0 * d;
    const double a1 = 2 * dot(O, d);
    const double b1 = dot(O, O) + R * R - rr * rr;
    const double k = 4 * R * R;
    const double coef[5] = {b1 * b1 - k * (O.x * O.x + O.z * O.z), 2 * a1 * b1 - 2 * k * (O.x * d.x + O.z * d.z),
                            a1 * a1 + 2 * b1 - k * (d.x * d.x + d.z * d.z), 2 * a1, 1};
    // The first root whose t, after the shift back and the rounding, is still in (tMin, tMax).
    auto inRange = [&](double root) { return (root + s0) / len > tMin && (root + s0) / len < tMax; };
    double root;
    if (!firstValidRoot(coef, 4, sLo - s0, sHi - s0, inRange, root)) return false;
    const double s = root + s0;
    h.t = s / len;
    const Vec3 p = r.origin + s * d;
    const double ring = std::sqrt(p.x * p.x + p.z * p.z);
    const Vec3 centre = ring > 0 ? Vec3{p.x * R / ring, 0, p.z * R / ring} : Vec3{};
    h.normal = normalize(p - centre);
    return true;
}

bool insideTorus(const Object& o, Vec3 p) {
    const double ring = std::sqrt(p.x * p.x + p.z * p.z) - o.r0;
    return ring * ring + p.y * p.y <= o.r1 * o.r1;  // closed, as POV-Ray's (csg.cpp insideShape)
}

Bounds torusBounds(const Object& o) {
    const double w = o.r0 + o.r1;
    return Bounds{{-w, -o.r1, -w}, {w, o.r1, w}};
}

}  // namespace rays
