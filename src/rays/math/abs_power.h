// |x|^k for an exponent k fixed ahead of many evaluations (a shape's or a pattern's parameter),
// cheaper than std::pow for the exponents scenes use most.
#pragma once
#include <cmath>

namespace rays {

/// |x|^k, k >= 0: by repeated squaring when k is a whole number up to 64, times √|x| when k is a
/// whole number and a half (crackle's `metric 2.5`), else as exp2 of the scaled log2 (a zero x:
/// log2 0 = −∞ and exp2 −∞ = 0, as powers with positive exponents give).
struct AbsPower {
    double k = 1;
    int whole = -1;     ///< k, or k − ½ when half, when that is a whole number in [0, 64]; else −1
    bool half = false;  ///< k is whole + ½
    explicit AbsPower(double exponent) : k(exponent) {
        for (const bool h : {false, true}) {
            const double w = h ? exponent - 0.5 : exponent;
            const double r = std::nearbyint(w);
            if (r >= 0 && r <= 64 && std::fabs(w - r) <= 1e-12 * (r + 1)) {
                whole = int(r), half = h;
                return;
            }
        }
    }
    double operator()(double x) const {
        x = std::fabs(x);
        if (whole < 0) return std::exp2(k * std::log2(x));
        double out = half ? std::sqrt(x) : 1.0, base = x;
        for (int m = whole; m > 0; m >>= 1, base *= base)
            if (m & 1) out *= base;
        return out;
    }
};

}  // namespace rays
