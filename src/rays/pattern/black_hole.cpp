#include "rays/pattern/black_hole.h"

#include <algorithm>
#include <cmath>

namespace rays::pattern {

Vec3 applyBlackHole(const BlackHole& h, Vec3 p) {
    if (h.radius <= 0) return p;
    Vec3 c = h.center;
    for (int i = 0; i < 3; ++i)
        if (h.repeat[i] != 0) c[i] = std::floor(p[i] / h.repeat[i]) * h.repeat[i] + h.radius;
    const Vec3 v = p - c;
    const double d = length(v);
    if (d >= h.radius) return p;
    const double pull = std::min(1.0, h.strength * std::pow(1 - d / h.radius, h.falloff));
    return c + v * (h.inverse ? 1 - pull : 1 + pull);
}

}  // namespace rays::pattern
