#include "rays/pattern/black_hole.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "rays/pattern/cell_hash.h"

namespace rays::pattern {

Vec3 blackHoleCentre(const BlackHole& h, Vec3 p) {
    Vec3 c = h.center;
    if (h.repeat == Vec3{}) return c;
    int64_t cell[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i)
        if (h.repeat[i] != 0) cell[i] = int64_t(std::floor(p[i] / h.repeat[i]));
    for (int i = 0; i < 3; ++i) {
        if (h.repeat[i] == 0) continue;
        c[i] = double(cell[i]) * h.repeat[i] + h.radius;
        if (h.jitter[i] != 0) c[i] += h.jitter[i] * cellUniform(cell[0], cell[1], cell[2], uint64_t(i + 1));
    }
    return c;
}

Vec3 applyBlackHole(const BlackHole& h, Vec3 p) {
    if (h.radius <= 0) return p;
    const Vec3 c = blackHoleCentre(h, p);
    const Vec3 v = p - c;
    const double d = length(v);
    if (d >= h.radius) return p;
    const double pull = std::min(1.0, h.strength * std::pow(1 - d / h.radius, h.falloff));
    return c + v * (h.inverse ? 1 - pull : 1 + pull);
}

}  // namespace rays::pattern
