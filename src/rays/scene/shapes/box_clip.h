// The stretch of a ray inside a box (slab test, Kay & Kajiya 1986), for shapes that bound their
// root search by their box.
#pragma once
#include <algorithm>

#include "rays/geometry/ray.h"

namespace rays {

/// Narrows [t0, t1] to the ray's stretch inside box b (a little widened); false when none is left.
inline bool clipRayToBox(const Bounds& b, const Ray& r, double& t0, double& t1) {
    for (int a = 0; a < 3; ++a) {
        const double pad = 1e-9 * (1 + b.hi[a] - b.lo[a]);
        if (r.dir[a] == 0) {
            if (r.origin[a] < b.lo[a] - pad || r.origin[a] > b.hi[a] + pad) return false;
            continue;
        }
        double n = (b.lo[a] - pad - r.origin[a]) / r.dir[a], f = (b.hi[a] + pad - r.origin[a]) / r.dir[a];
        if (n > f) std::swap(n, f);
        t0 = std::max(t0, n);
        t1 = std::min(t1, f);
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace rays
