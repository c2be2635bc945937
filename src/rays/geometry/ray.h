// Ray and bounding box value types.
#pragma once
#include <limits>

#include "rays/math/vec3.h"

namespace rays {

struct Ray {
    Vec3 origin;
    Vec3 dir;  ///< unit length for world rays; object-space rays keep the transformed length
    Vec3 at(double t) const { return origin + t * dir; }
};

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Bounds {
    Vec3 lo{kInfinity, kInfinity, kInfinity};
    Vec3 hi{-kInfinity, -kInfinity, -kInfinity};

    void extend(Vec3 p) { lo = vmin(lo, p); hi = vmax(hi, p); }
    void extend(const Bounds& b) { lo = vmin(lo, b.lo); hi = vmax(hi, b.hi); }
    Vec3 centroid() const { return 0.5 * (lo + hi); }
    Vec3 extent() const { return hi - lo; }
    bool empty() const { return lo.x > hi.x; }
    double surfaceArea() const {
        if (empty()) return 0;
        const Vec3 e = extent();
        return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
};

}  // namespace rays
