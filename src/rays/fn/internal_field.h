// Shared pieces of the internal functions with a "field strength" (reference 3.4.9.1.7.3):
// POV-Ray multiplies the surface's polynomial by the strength and clamps the product to a
// field limit (±10 unless the function takes the limit as a parameter), measured with POV-Ray 3.7.
#pragma once
#include <algorithm>

namespace rays::fn::internal {

/// strength·value clamped to [-limit, limit]: min(max(v, −limit), limit), so a negative limit
/// gives the limit itself (measured: f_algbr_cyl2 with limit −2 is −2 everywhere).
inline double field(double strength, double value, double limit = 10.0) {
    return std::min(std::max(strength * value, -limit), limit);
}

inline double sq(double v) { return v * v; }

}  // namespace rays::fn::internal
