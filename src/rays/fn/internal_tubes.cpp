// Internal functions of surfaces of revolution and tubes around the y axis: f_poly4 and
// f_polytubes (reference 3.4.9.1.7.9). Checked against POV-Ray 3.7's values.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "rays/fn/internal_impl.h"

namespace rays::fn::internal {
namespace {

// A + By + Cy² + Dy³ + Ey⁴ with the coefficients at c[0..4].
double quartic(const double* c, double y) { return c[0] + y * (c[1] + y * (c[2] + y * (c[3] + y * c[4]))); }

}  // namespace

// The surface of revolution of x = A + By + Cy² + Dy³ + Ey⁴ about y: sqrt(x² + z²) − poly(y).
double f_poly4(const double* p) { return std::sqrt(p[0] * p[0] + p[2] * p[2]) - quartic(p + 3, p[1]); }

// int(P0) tubes whose centres lie at distance poly(y) from the y axis (coefficients P1-P5), the
// k-th in direction k·360°/P0 measured from +z towards +x: the horizontal distance to the
// nearest centre (measured: with P0 = 2.5 only the tubes at 0° and 144° exist).
double f_polytubes(const double* p) {
    const double n = p[3];
    const double r = quartic(p + 4, p[1]);
    const int tubes = n >= 1 ? static_cast<int>(std::min(n, 10000.0)) : 0;  // capped: NaN and huge counts
    double best = INFINITY;
    for (int k = 0; k < tubes; ++k) {
        const double a = k * (2 * std::numbers::pi / n);
        const double dx = p[0] - r * std::sin(a), dz = p[2] - r * std::cos(a);
        best = std::min(best, dx * dx + dz * dz);
    }
    return std::sqrt(best);
}

}  // namespace rays::fn::internal
