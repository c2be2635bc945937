// The torus as the quartic (|P|² + R² − r²)² − 4R²(x² + z²) = 0 (the implicit form in the POV-Ray
// reference's "Quartic" section, axis y), solved along the ray by polyRoots. For accuracy the
// ray is first normalised, clipped to the bounding sphere of radius R + r, and its origin moved
// to its point nearest the centre, so the quartic's coefficients stay of the size of the torus.
#include "rays/scene/shapes/torus.h"

#include <cmath>

#include "rays/math/poly_roots.h"

namespace rays {

bool hitTorus(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const double R = o.r0, rr = o.r1;
    const double len = length(r.dir);
    const Vec3 d = r.dir / len;
    // The bounding sphere, a little wider so that no root lies on its ends: s along the unit direction.
    const double bound = 1.001 * (std::fabs(R) + rr);
    const double b = dot(r.origin, d);
    const double c = dot(r.origin, r.origin) - bound * bound;
    const double disc = b * b - c;
    if (disc <= 0) return false;
    const double sq = std::sqrt(disc);
    const double sLo = std::max(-b - sq, tMin * len), sHi = std::min(-b + sq, tMax * len);
    if (!(sLo < sHi)) return false;
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
    return ring * ring + p.y * p.y < o.r1 * o.r1;
}

Bounds torusBounds(const Object& o) {
    const double w = o.r0 + o.r1;
    return Bounds{{-w, -o.r1, -w}, {w, o.r1, w}};
}

}  // namespace rays
