#include "rays/pattern/slope.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rays::pattern {
namespace {

// (v − lo)/(hi − lo), or v itself for an empty range.
double rescaled(double v, double lo, double hi) { return hi != lo ? (v - lo) / (hi - lo) : v; }

}  // namespace

Slope makeSlope(Vec3 direction, double lo, double hi, Vec3 altitude, double loAlt, double hiAlt) {
    Slope s;
    const double dl = length(direction), al = length(altitude);
    if (dl > 0) s.direction = direction / dl;
    s.lo = lo, s.hi = hi;
    if (al > 0) {
        s.altitude = altitude / al;
        s.slopeWeight = dl > 0 ? dl / (dl + al) : 0;
    }
    s.loAlt = loAlt, s.hiAlt = hiAlt;
    return s;
}

double slopeValue(const Slope& s, Vec3 p, Vec3 N) {
    const double len = length(N);
    const double c = len > 0 ? std::clamp(dot(N, s.direction) / len, -1.0, 1.0) : 0.0;
    const double slope = rescaled(1 - std::acos(c) / std::numbers::pi, s.lo, s.hi);
    if (s.slopeWeight >= 1) return slope;
    const double alt = rescaled(dot(p, s.altitude), s.loAlt, s.hiAlt);
    return s.slopeWeight * slope + (1 - s.slopeWeight) * alt;
}

}  // namespace rays::pattern
