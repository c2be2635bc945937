// Internal functions of helixes and spirals: f_helix1, f_helix2, f_spiral, f_helical_torus
// (reference 3.4.9.1.7.2 "cross section type" and 3.4.9.1.7.9). The reference describes the
// parameters in words; the constructions were recovered from POV-Ray 3.7's values.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "rays/fn/internal_impl.h"
#include "rays/fn/ops.h"

namespace rays::fn::internal {
namespace {

constexpr double kPi = std::numbers::pi;

// The size of (u, v) in the cross-section norm of `type` (0 square, 1 circle, 2 diamond,
// 3 concave diamond, in between rounded): (|u|^q + |v|^q)^(1/q) with q = 2/type, after turning
// (u, v) by `degrees`.
double crossSection(double u, double v, double type, double degrees) {
    if (degrees != 0) {
        const double a = degrees * ops::kRadiansPerDegree, c = std::cos(a), s = std::sin(a);
        const double ru = u * c + v * s, rv = v * c - u * s;
        u = ru;
        v = rv;
    }
    u = std::fabs(u);
    v = std::fabs(v);
    if (type == 0) return std::max(u, v);
    if (type == 1) return std::sqrt(u * u + v * v);
    if (type == 2) return u + v;
    const double q = 2 / type;
    return std::pow(std::pow(u, q) + std::pow(v, q), 1 / q);
}

// v less a whole number of turns, in [−π, π].
double wrapAngle(double v) {
    double d = std::fmod(v, 2 * kPi);
    if (d > kPi) d -= 2 * kPi;
    if (d < -kPi) d += 2 * kPi;
    return d;
}

// The angle from a point's direction to the nearest of n strands that wind about y (n strands
// at phase n·(θ + ω·y) ≡ π, θ = atan2(z, x)), in radians of θ, signed.
double strandOffset(double x, double y, double z, double n, double omega) {
    const double phase = n * (std::atan2(z, x) + omega * y) - kPi;
    return wrapAngle(phase) / n;
}

}  // namespace

// P0 helixes of major radius P3 winding about y with angular rate P1 (radians per unit of y):
// the cross-section norm (type P5, turned by P6 degrees) of (r − R, Δθ/(P1·P4)), where Δθ is
// the angle to the nearest strand and P4 stretches the tube along y, at most r + R, minus the
// minor radius P2.
double f_helix1(const double* p) {
    const double r = std::sqrt(p[0] * p[0] + p[2] * p[2]);
    const double n = p[3], omega = p[4], minor = p[5], major = p[6], shape = p[7];
    const double v = -strandOffset(p[0], p[1], p[2], n, omega) / (omega * shape);
    const double d = crossSection(r - major, v, p[8], p[9]);
    return std::min(d, r + major) - minor;
}

// One helix of radius P3 winding about y at P1 radians per unit of y (its point at height y is
// P3·(cos P1y, 0, sin P1y)): the cross-section norm (type P5) of the horizontal offset from that
// point, split into radial and tangential parts, minus P2. P0, P4 and, measured, the rotation
// P6 have no effect.
double f_helix2(const double* p) {
    const double a = p[4] * p[1], c = std::cos(a), s = std::sin(a);
    const double dx = p[0] - p[6] * c, dz = p[2] - p[6] * s;
    return crossSection(dx * c + dz * s, dz * c - dx * s, p[8], 0) - p[5];
}

// A flat spiral in the xz plane, arms P0 apart (the arm through direction ψ = atan2(z, x) at
// radius P0·(π − ψ)/(2π) + k·P0, k ≥ 0): the cross-section norm (type P5) of (distance to the
// nearest arm, y), at most the distance to the centre, minus the thickness P1, cut by the sphere
// of radius P2 (the larger of the two). P3 and P4 have no effect. On the axis POV-Ray's radial
// distance is 1e-6 (measured).
double f_spiral(const double* p) {
    const double s = p[3];
    const double r = std::max(std::sqrt(p[0] * p[0] + p[2] * p[2]), 1e-6);
    const double t = r - s * (kPi - std::atan2(p[2], p[0])) / (2 * kPi);
    double radial = -t;
    if (t >= 0) {
        const double m = std::fmod(t, s);
        radial = std::min(m, s - m);
    }
    const double centre = std::sqrt(r * r + p[1] * p[1]);
    const double tube = std::min(crossSection(radial, p[1], p[8], 0), centre) - p[4];
    return std::max(tube, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - p[5]);
}

// A torus of major radius R = P0 wound by a helical tube, with grooves (all measured against
// POV-Ray 3.7; the reference only names the parameters). With r = sqrt(x² + z²), the distance
// ρ from the central circle, θ = atan2(x, z) around y and σ = atan2(r − R, y) around the tube,
// the winding lies where u = P1·θ + P2·σ ≡ π (P1 loops, P2 twist); D is u − π wrapped to
// (−π, π]. With a = ρ − P5 and the groove term G = P3·cos(P7·atan2(P8·D, a) + P9·θ):
//   min(ρ + P5 − G, sqrt(P6·D² + a²) − G, r + R − P5) − P4
// (central torus, winding, axial column; P3 fatness, P4 threshold, P5 "negative minor
// radius", P6 winding fatness, P7 groove period, P8 groove amplitude, P9 groove phase).
double f_helical_torus(const double* p) {
    const double x = p[0], y = p[1], z = p[2];
    const double R = p[3], loops = p[4], twist = p[5], fat = p[6], threshold = p[7], inner = p[8], stretch = p[9];
    const double r = std::sqrt(x * x + z * z);
    const double rho = std::sqrt((r - R) * (r - R) + y * y);
    const double theta = std::atan2(x, z), sigma = std::atan2(r - R, y);
    const double d = wrapAngle(loops * theta + twist * sigma - kPi);
    const double a = rho - inner;
    const double groove = fat * std::cos(p[10] * std::atan2(d * p[11], a) + p[12] * theta);
    const double winding = std::sqrt(stretch * d * d + a * a) - groove;
    return std::min({rho + inner - groove, winding, r + R - inner}) - threshold;
}

}  // namespace rays::fn::internal
