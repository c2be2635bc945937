// Internal functions that are periodic patterns or height fields: f_spikes_2d, f_hex_x,
// f_hex_y, f_mesh1, f_quantum, f_comma (reference 3.4.9.1.7.9). Recovered from POV-Ray 3.7's values.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "rays/fn/internal_impl.h"

namespace rays::fn::internal {
namespace {

constexpr double kSqrt3 = std::numbers::sqrt3;

// The hexagonal lattice with centres √3 apart: rows 1.5 apart along y, every other row shifted
// by √3/2 along x. Calls visit(dx, dy) with p minus each centre that can be nearest.
template <class F>
void nearHexCentres(double x, double y, F visit) {
    x = std::fmod(std::fabs(x), kSqrt3);
    y = std::fmod(std::fabs(y), 3.0);
    const double cx[] = {0, kSqrt3, kSqrt3 / 2, 0, kSqrt3};
    const double cy[] = {0, 0, 1.5, 3, 3};
    for (int i = 0; i < 5; ++i) visit(x - cx[i], y - cy[i]);
}

// (−1)^k for an integral k stored as a double (any size).
double parity(double k) { return std::fmod(k, 2.0) == 0 ? 1.0 : -1.0; }

}  // namespace

// A height field of damped waves: y − h·cos(a·x)·cos(b·z)·exp(−c·(x² + z²)), h = P0, a = P1,
// b = P2 (frequencies), c = P3 (decay).
double f_spikes_2d(const double* p) {
    const double x = p[0], z = p[2];
    return p[1] - p[3] * std::cos(p[4] * x) * std::cos(p[5] * z) * std::exp(-p[6] * (x * x + z * z));
}

// Hexagonal cylinders along z: the hexagon norm (largest projection on the directions 0°, ±60°)
// of the offset from the nearest lattice centre; P0 has no effect.
double f_hex_x(const double* p) {
    double best = INFINITY;
    nearHexCentres(p[0], p[1], [&](double dx, double dy) {
        const double a = std::fabs(dx), b = std::fabs(0.5 * dx + (kSqrt3 / 2) * dy),
                     c = std::fabs(0.5 * dx - (kSqrt3 / 2) * dy);
        best = std::min(best, std::max({a, b, c}));
    });
    return best;
}

// Slabs rotated 60° about the lattice centres: the smallest projection of the offset from any
// centre on the directions 90°, ±30°; P0 has no effect.
double f_hex_y(const double* p) {
    double best = INFINITY;
    nearHexCentres(p[0], p[1], [&](double dx, double dy) {
        const double a = std::fabs(dy), b = std::fabs((kSqrt3 / 2) * dx + 0.5 * dy),
                     c = std::fabs((kSqrt3 / 2) * dx - 0.5 * dy);
        best = std::min(best, std::min({a, b, c}));
    });
    return best;
}

// A 3d_z² orbital's density around y, 1.2 − 1.6·(3y² − r²)²·exp(−1.33333332·r) (r = |p|; the
// constant is POV-Ray's, measured: 4/3 to 8 digits): the hydrogen
// 3d density r⁴(3cos²θ − 1)²e^{−2r/3} at 2p, over 10, below 1.2; P0 has no effect.
double f_quantum(const double* p) {
    const double x2 = p[0] * p[0], y2 = p[1] * p[1], z2 = p[2] * p[2];
    const double r2 = x2 + y2 + z2, a = 3 * y2 - r2;
    return 1.2 - 1.6 * a * a * std::exp(-1.33333332 * std::sqrt(r2));
}

// A woven mesh: threads along x at z = k·P1 and along z at x = j·P0, weaving in y as
// ±P3·cos(πx/P0) and ∓P3·cos(πz/P1), alternately over and under; the distance to the nearest
// thread with horizontal offsets times P2 and vertical times P4. Adjacent threads of a family
// weave in opposite senses, so the two neighbours k = floor(z/P1), k+1 are the only candidates.
double f_mesh1(const double* p) {
    const double x = p[0], y = p[1], z = p[2], dx = p[3], dz = p[4], th = p[5], amp = p[6], tv = p[7];
    const double wx = amp * std::cos(std::numbers::pi * x / dx), wz = -amp * std::cos(std::numbers::pi * z / dz);
    double best = INFINITY;
    const double k0 = std::floor(z / dz), j0 = std::floor(x / dx);
    for (double k = k0; k <= k0 + 1; ++k) {
        const double h = (z - k * dz) * th, v = (y - parity(k) * wx) * tv;
        best = std::min(best, std::sqrt(h * h + v * v));
    }
    for (double j = j0; j <= j0 + 1; ++j) {
        const double h = (x - j * dx) * th, v = (y - parity(j) * wz) * tv;
        best = std::min(best, std::sqrt(h * h + v * v));
    }
    return best;
}

// A comma of size s = P0 (in units of s): the ball of radius 1/2 about (1/2, 0, 0) joined with a
// tail: a tube about the circle of radius 3/4 around (−1/4, 0, 0) in the xz plane whose radius
// is cos(θ/2)/2, θ = atan2(z, x) (1/2 at the ball, 0 at the tip (−1, 0, 0)), cut off below
// z = 0: s·min(ball, max(tube, −z)). On the y axis POV-Ray moves x to 1e-4 (measured).
double f_comma(const double* p) {
    const double s = p[3];
    const double x = (p[0] == 0 && p[2] == 0 ? 1e-4 : p[0]) / s, y = p[1] / s, z = p[2] / s;
    const double ball = std::sqrt((x - 0.5) * (x - 0.5) + y * y + z * z) - 0.5;
    const double a = std::sqrt((x + 0.25) * (x + 0.25) + z * z) - 0.75;
    const double tube = std::sqrt(a * a + y * y) - 0.5 * std::cos(std::atan2(z, x) / 2);
    return s * std::min(ball, std::max(tube, -z));
}

}  // namespace rays::fn::internal
