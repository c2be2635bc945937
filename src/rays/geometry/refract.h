// Snell's law for a ray crossing an interface.
#pragma once
#include <cmath>

#include "rays/math/vec3.h"

namespace rays {

/// Refraction of unit d through unit normal n facing d's origin side (dot(d, n) < 0) with
/// relative index eta = n1/n2. Returns false on total internal reflection.
inline bool refractDir(Vec3 d, Vec3 n, double eta, Vec3& out) {
    const double cosi = -dot(d, n);
    const double k = 1.0 - eta * eta * (1.0 - cosi * cosi);
    if (k < 0) return false;
    out = normalize(eta * d + (eta * cosi - std::sqrt(k)) * n);
    return true;
}

}  // namespace rays
