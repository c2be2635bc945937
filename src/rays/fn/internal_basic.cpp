// Distance-like internal functions: f_sphere, f_r, f_th, f_ph, f_torus, f_ellipsoid,
// f_rounded_box, f_superellipsoid. Formulas from the reference's descriptions, checked against
// POV-Ray 3.7 (bit-identical on the measured points, tests/fn_internal_test.cpp).
#include <algorithm>
#include <cmath>

#include "rays/fn/internal_impl.h"

namespace rays::fn::internal {

// Distance from the origin minus the radius P0.
double f_sphere(const double* p) { return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - p[3]; }

// Distance from the origin (the spherical coordinate r).
double f_r(const double* p) { return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]); }

// The longitude θ about the y axis: atan2(x, z).
double f_th(const double* p) { return std::atan2(p[0], p[2]); }

// The angle φ from the +y axis: atan2(sqrt(x² + z²), y).
double f_ph(const double* p) { return std::atan2(std::sqrt(p[0] * p[0] + p[2] * p[2]), p[1]); }

// Distance from the circle of radius P0 in the xz plane, minus the minor radius P1.
double f_torus(const double* p) {
    const double ring = std::sqrt(p[0] * p[0] + p[2] * p[2]) - p[3];
    return std::sqrt(ring * ring + p[1] * p[1]) - p[4];
}

// sqrt((P0 x)² + (P1 y)² + (P2 z)²): 1 on the ellipsoid with semi-axes 1/P0, 1/P1, 1/P2.
double f_ellipsoid(const double* p) {
    const double a = p[3] * p[0], b = p[4] * p[1], c = p[5] * p[2];
    return std::sqrt(a * a + b * b + c * c);
}

// Distance outside the box |x| <= P1, |y| <= P2, |z| <= P3 with edges rounded to radius P0,
// minus 1e-6 (measured: POV-Ray's value is the exact distance less 1e-6 everywhere).
double f_rounded_box(const double* p) {
    const double r = p[3];
    const double qx = std::max(std::fabs(p[0]) - (p[4] - r), 0.0);
    const double qy = std::max(std::fabs(p[1]) - (p[5] - r), 0.0);
    const double qz = std::max(std::fabs(p[2]) - (p[6] - r), 0.0);
    return std::sqrt(qx * qx + qy * qy + qz * qz) - r - 1e-6;
}

// 1 - ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n))^(n/2) with e = P0 (east-west), n = P1
// (north-south): POV-Ray's superellipsoid, positive inside.
double f_superellipsoid(const double* p) {
    const double e = p[3], n = p[4];
    const double xy = std::pow(std::fabs(p[0]), 2 / e) + std::pow(std::fabs(p[1]), 2 / e);
    return 1 - std::pow(std::pow(xy, e / n) + std::pow(std::fabs(p[2]), 2 / n), n / 2);
}

}  // namespace rays::fn::internal
