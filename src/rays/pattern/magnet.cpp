#include "rays/pattern/magnet.h"

#include <algorithm>
#include <complex>
#include <limits>

namespace rays::pattern {
namespace {

using Complex = std::complex<double>;

// One step of magnet 1 or 2; a zero denominator leaves z at 0 (an orbit that stays inside).
Complex magnetStep(int formula, Complex z, Complex c) {
    Complex num, den;
    if (formula == 2) {
        const Complex c1 = c - 1.0, c2 = c - 2.0;
        num = z * z * z + 3.0 * c1 * z + c1 * c2;
        den = 3.0 * z * z + 3.0 * c2 * z + c1 * c2 + 1.0;
    } else {
        num = z * z + c - 1.0;
        den = 2.0 * z + c - 2.0;
    }
    if (den == Complex{}) return {};
    const Complex q = num / den;
    return q * q;
}

constexpr double kMagnetBailout = 10000;   // |z|² (measured)
constexpr double kMagnetSettled = 0.0001;  // |z − 1|² (measured)

}  // namespace

double magnetValue(const PatternParams& m, double x, double y) {
    const Complex point{x, y};
    Complex z = m.magnetJulia ? point : Complex{};
    const Complex c = m.magnetJulia ? Complex{m.juliaR, m.juliaI} : point;
    double minAbs2 = m.magnetJulia ? std::norm(z) : std::numeric_limits<double>::infinity();
    int n = 0;
    bool escaped = false;
    for (; n < m.iterations; ++n) {
        z = magnetStep(m.magnetFormula, z, c);
        const double a2 = std::norm(z);
        if (a2 > kMagnetBailout || std::norm(z - 1.0) < kMagnetSettled) {
            escaped = true;
            break;
        }
        minAbs2 = std::min(minAbs2, a2);
    }
    return escapeColouring(m, escaped, n, z.real(), z.imag(), minAbs2);
}

}  // namespace rays::pattern
