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

/// cos θ and sin θ for |θ| ≤ π/4 by their Taylor series to degree 12 and 11 (error < 1e-11).
inline void sinCosQuarter(double th, double& c, double& s) {
    const double x2 = th * th;
    c = 1 + x2 * (-1.0 / 2 +
                  x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 + x2 * (-1.0 / 3628800 + x2 * (1.0 / 479001600))))));
    s = th * (1 + x2 * (-1.0 / 6 + x2 * (1.0 / 120 + x2 * (-1.0 / 5040 + x2 * (1.0 / 362880 + x2 * (-1.0 / 39916800))))));
}

/// cosineHemisphere() for many directions about one n: the basis is made once, and the
/// concentric map's angle (within π/4 of an axis) goes through sinCosQuarter instead of libm.
struct CosineHemisphere {
    Vec3 n, t, b;
    explicit CosineHemisphere(Vec3 normal) : n(normal) { orthonormalBasis(n, t, b); }
    /// The direction of (a, b) ∈ [0,1)²: unit up to rounding (not renormalised).
    Vec3 operator()(double a, double bb) const {
        const double sx = 2 * a - 1, sy = 2 * bb - 1;
        // Branch-free (the two cases of the concentric map are equally likely, so a branch
        // mispredicts half the time): r is the coordinate of larger magnitude, q the other over
        // it; φ = (π/4)q measured from the x axis, or from the y axis towards x.
        const bool xMajor = std::fabs(sx) > std::fabs(sy);
        const double r = xMajor ? sx : sy, other = xMajor ? sy : sx;
        const double q = r != 0 ? other / r : 0.0;
        double c, s;
        sinCosQuarter((std::numbers::pi / 4) * q, c, s);
        const double x = r * (xMajor ? c : s);
        const double y = r * (xMajor ? s : c);
        const double z = std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
        return x * t + y * b + z * n;
    }
};

}  // namespace rays
