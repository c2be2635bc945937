// Internal functions built from blob fields: f_blob, f_blob2, f_cross_ellipsoids,
// f_isect_ellipsoids (reference 3.4.9.1.7.9). The reference describes them only in words; the
// field shapes (POV-Ray's blob polynomial, Gaussians) and their parameters were recovered from
// POV-Ray 3.7's values.
#include <algorithm>
#include <cmath>

#include "rays/fn/internal_impl.h"

namespace rays::fn::internal {
namespace {

// POV-Ray's blob component: s·(1 − (d·inverseRadius)²)² inside its radius, 0 outside.
double blobComponent(double d2, double strength, double inverseRadius) {
    const double t = d2 * inverseRadius * inverseRadius;
    return t < 1 ? strength * (1 - t) * (1 - t) : 0.0;
}

// The three ellipsoids' quadratic forms: the axis' own square plus e times the others'.
struct EllipsoidForms {
    double x, y, z;
};
EllipsoidForms ellipsoidForms(const double* p, double e) {
    const double x2 = p[0] * p[0], y2 = p[1] * p[1], z2 = p[2] * p[2];
    return {x2 + e * (y2 + z2), y2 + e * (x2 + z2), z2 + e * (x2 + y2)};
}

}  // namespace

// Two blob components on the x axis at ∓P0/2, strengths P1 and P3, inverse radii P2 and P4:
// minus the sum of their fields (so the surface needs a negative threshold).
double f_blob(const double* p) {
    const double h = p[3] / 2;
    const double y2z2 = p[1] * p[1] + p[2] * p[2];
    const double a = p[0] + h, b = p[0] - h;
    return -(blobComponent(a * a + y2z2, p[4], p[5]) + blobComponent(b * b + y2z2, p[6], p[7]));
}

// Gaussian blobs at the origin and at (P0, 0, 0): P3 − P2·(exp(−P1·d1²) + exp(−P1·d2²)).
double f_blob2(const double* p) {
    const double y2z2 = p[1] * p[1] + p[2] * p[2];
    const double b = p[0] - p[3];
    const double d1 = p[0] * p[0] + y2z2, d2 = b * b + y2z2;
    return p[6] - p[5] * (std::exp(-p[4] * d1) + std::exp(-p[4] * d2));
}

// Union of three Gaussian ellipsoids along the axes (eccentricity e = P0): the strongest field,
// P3 − P2·exp(−P1·min(x² + e(y² + z²), y² + e(x² + z²), z² + e(x² + y²))).
double f_cross_ellipsoids(const double* p) {
    const EllipsoidForms q = ellipsoidForms(p, p[3]);
    return p[6] - p[5] * std::exp(-p[4] * std::min({q.x, q.y, q.z}));
}

// Intersection of the same three ellipsoids: the weakest field (the largest form).
double f_isect_ellipsoids(const double* p) {
    const EllipsoidForms q = ellipsoidForms(p, p[3]);
    return p[6] - p[5] * std::exp(-p[4] * std::max({q.x, q.y, q.z}));
}

// The sum of the three ellipsoids' Gaussian fields (spikiness e = P0, inverse size P1, flange P2,
// threshold P3): P3 − P2·Σ exp(−P1·form). With e = 1 the three coincide: a sphere.
double f_flange_cover(const double* p) {
    const EllipsoidForms q = ellipsoidForms(p, p[3]);
    return p[6] - p[5] * (std::exp(-p[4] * q.x) + std::exp(-p[4] * q.y) + std::exp(-p[4] * q.z));
}

// Spikes: the flange cover's three fields minus a round Gaussian, scaled:
// P2·(Σ exp(−P1·form) − P4·exp(−P3·(x² + y² + z²))), spikiness e = P0, hollowness P1, size P2,
// roundness P3, fatness P4.
double f_spikes(const double* p) {
    const EllipsoidForms q = ellipsoidForms(p, p[3]);
    const double r2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
    const double fields = std::exp(-p[4] * q.x) + std::exp(-p[4] * q.y) + std::exp(-p[4] * q.z);
    return p[5] * (fields - p[7] * std::exp(-p[6] * r2));
}

}  // namespace rays::fn::internal
