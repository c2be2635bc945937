// The ray-sphere test shared by Object (object.cpp) and the BVH's compact sphere path (bvh.cpp):
// one formula, one operation order, so both give bit-identical distances and normals.
#pragma once
#include <cmath>

#include "rays/geometry/ray.h"

namespace rays {

/// Nearest t in (tMin, tMax) where r meets the sphere (centre, radius); false when none.
inline bool sphereHitT(const Vec3& centre, double radius, const Ray& r, double tMin, double tMax, double& t) {
    const Vec3 oc = r.origin - centre;
    const double a = dot(r.dir, r.dir);
    const double b = dot(oc, r.dir);
    const double c = dot(oc, oc) - radius * radius;
    // Starting outside and moving away: both roots are <= 0 (also as computed: b² - a c rounds to
    // at most fl(b²), whose square root is |b|), so nothing in (tMin, tMax) when tMin >= 0.
    if (c > 0 && b > 0 && tMin >= 0) return false;
    const double disc = b * b - a * c;
    if (disc < 0) return false;
    const double sq = std::sqrt(disc);
    // The nearer root first; the farther one is computed only when the nearer is out of range.
    const double t0 = (-b - sq) / a;
    if (t0 > tMin && t0 < tMax) {
        t = t0;
        return true;
    }
    const double t1 = (-b + sq) / a;
    if (t1 > tMin && t1 < tMax) {
        t = t1;
        return true;
    }
    return false;
}

/// Outward unit normal of the sphere (centre, radius) where r meets it at t.
inline Vec3 sphereNormal(const Vec3& centre, double radius, const Ray& r, double t) {
    return (r.at(t) - centre) / radius;
}

}  // namespace rays
