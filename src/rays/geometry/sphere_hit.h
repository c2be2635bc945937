// The ray-sphere test shared by Object (object.cpp) and the BVH's compact sphere path (bvh.cpp):
// one formula, one operation order, so both give bit-identical distances.
#pragma once
#include <cmath>

#include "rays/geometry/ray.h"

namespace rays {

/// Chooses the nearest of two sorted roots inside (tMin, tMax).
inline bool pickRoot(double t0, double t1, double tMin, double tMax, double& t) {
    if (t0 > tMin && t0 < tMax) {
        t = t0;
        return true;
    }
    if (t1 > tMin && t1 < tMax) {
        t = t1;
        return true;
    }
    return false;
}

/// Nearest t in (tMin, tMax) where r meets the sphere (centre, radius); false when none.
inline bool sphereHitT(const Vec3& centre, double radius, const Ray& r, double tMin, double tMax, double& t) {
    const Vec3 oc = r.origin - centre;
    const double a = dot(r.dir, r.dir);
    const double b = dot(oc, r.dir);
    const double c = dot(oc, oc) - radius * radius;
    const double disc = b * b - a * c;
    if (disc < 0) return false;
    const double sq = std::sqrt(disc);
    return pickRoot((-b - sq) / a, (-b + sq) / a, tMin, tMax, t);
}

}  // namespace rays
