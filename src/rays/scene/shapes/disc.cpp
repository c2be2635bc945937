#include "rays/scene/shapes/disc.h"

#include <cmath>

namespace rays {

bool hitDisc(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const double denom = dot(o.p1, r.dir);
    if (denom == 0) return false;
    const double t = dot(o.p1, o.p0 - r.origin) / denom;
    if (!(t > tMin && t < tMax)) return false;
    const Vec3 q = r.at(t) - o.p0;
    const double d2 = dot(q, q);
    if (d2 > o.r0 * o.r0 || d2 < o.r1 * o.r1) return false;
    h.t = t;
    h.normal = o.p1;
    return true;
}

Bounds discBounds(const Object& o) {
    // A circle of radius r with unit normal n reaches r·sqrt(1 − n_i²) along axis i.
    Vec3 half;
    for (int i = 0; i < 3; ++i) half[i] = o.r0 * std::sqrt(std::max(0.0, 1 - o.p1[i] * o.p1[i]));
    return Bounds{o.p0 - half, o.p0 + half};
}

}  // namespace rays
