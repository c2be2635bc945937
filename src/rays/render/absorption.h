// Exponential absorption (Beer–Lambert) along a path inside a medium, shared by the course's
// Beer's law (tracer.cpp) and POV-Ray's exponential interior fade (pov_lighting.cpp).
#pragma once
#include <cmath>

#include "rays/math/vec3.h"

namespace rays {

/// Share of light left after a path of length d through a medium absorbing k per unit length,
/// per channel: exp(−k·d); 1 where k is 0 (also for an infinite d), 0 where it is not and d is
/// infinite.
inline Vec3 beerAbsorption(Vec3 k, double d) {
    Vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = k[i] == 0 ? 1.0 : (std::isinf(d) ? 0.0 : std::exp(-k[i] * d));
    return out;
}

}  // namespace rays
