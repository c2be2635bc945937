// How POV-Ray 3.7 turns a float into an integer parameter (seed, rand's stream number, chr, str's
// and vstr's L and P, vstr's N, substr's P and L), measured with the installed povray binary:
// truncation toward zero (seed(1.9999) = seed(1), seed(-1.5) = seed(-1), str(1.5,0,-0.5) has
// P = 0), and every value outside the 32-bit int range, NaN included, becomes −2147483648
// (seed(1e10) = seed(2^31) = seed(-2^31 - 1); str(1.5, 0, 1e10) uses the default precision;
// chr(1e10) reports "Value -2147483648 cannot be used"). That is the x86 truncating conversion;
// here it is spelled out, since a C++ cast of an out-of-range double is undefined.
#pragma once
#include <climits>

namespace rays::sdl {

/// POV-Ray's float → int: truncates toward zero; NaN and values outside int32 give INT_MIN.
constexpr int povInt(double v) {
    if (!(v > -2147483649.0 && v < 2147483648.0)) return INT_MIN;
    return static_cast<int>(v);
}

}  // namespace rays::sdl
