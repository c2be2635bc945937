// Sampling warps: unit square → disc, cosine-weighted hemisphere; orthonormal bases.
#pragma once
#include <cmath>
#include <numbers>

#include "rays/math/vec3.h"

namespace rays {

/// Concentric map (Shirley & Chiu 1997) of (a, b) ∈ [0,1)² onto the unit disc; returns (x, y).
inline void concentricDisc(double a, double b, double& x, double& y) {
    const double sx = 2 * a - 1, sy = 2 * b - 1;
    if (sx == 0 && sy == 0) {
        x = y = 0;
        return;
    }
    double r, phi;
    if (std::fabs(sx) > std::fabs(sy)) {
        r = sx;
        phi = (std::numbers::pi / 4) * (sy / sx);
    } else {
        r = sy;
        phi = std::numbers::pi / 2 - (std::numbers::pi / 4) * (sx / sy);
    }
    x = r * std::cos(phi);
    y = r * std::sin(phi);
}

/// Two unit vectors t, b with (t, b, n) orthonormal; n must be unit length (Duff et al. 2017).
inline void orthonormalBasis(Vec3 n, Vec3& t, Vec3& b) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double c = n.x * n.y * a;
    t = Vec3{1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
    b = Vec3{c, sign + n.y * n.y * a, -n.y};
}

/// Cosine-weighted direction about unit n from (a, b) ∈ [0,1)² (Malley's method).
inline Vec3 cosineHemisphere(Vec3 n, double a, double b) {
    double x, y;
    concentricDisc(a, b, x, y);
    const double z = std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
    Vec3 t, bt;
    orthonormalBasis(n, t, bt);
    return normalize(x * t + y * bt + z * n);
}

/// cosineHemisphere() for many directions about one n: the basis is made once.
struct CosineHemisphere {
    Vec3 n, t, b;
    explicit CosineHemisphere(Vec3 normal) : n(normal) { orthonormalBasis(n, t, b); }
    /// The direction of (a, b) ∈ [0,1)²: unit up to rounding (not renormalised).
    Vec3 operator()(double a, double bb) const {
        double x, y;
        concentricDisc(a, bb, x, y);
        const double z = std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
        return x * t + y * b + z * n;
    }
};

}  // namespace rays
