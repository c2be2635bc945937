#include "rays/pattern/crackle.h"

#include <algorithm>
#include <cmath>

#include "rays/pattern/cell_hash.h"
#include "rays/pattern/noise.h"

namespace rays::pattern {

namespace {

// A solid cell's value is the noise at its seed, widened about 0.5 to POV-Ray's spread of solid
// cells (0.122 over 4,000 points; Rays' noise has 0.101).
constexpr double kSolidSpread = 1.2;

// The seed of the unit cube (i, j, k): uniform in the cube.
Vec3 seedOf(int64_t i, int64_t j, int64_t k) {
    return {double(i) + cellUniform(i, j, k, 1), double(j) + cellUniform(i, j, k, 2), double(k) + cellUniform(i, j, k, 3)};
}

double distanceOf(Vec3 d, const Crackle& c) {
    const double m = c.metric;
    if (m == 2) return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z + c.offset * c.offset);
    if (m == 1) return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z) + std::fabs(c.offset);
    return std::pow(std::pow(std::fabs(d.x), m) + std::pow(std::fabs(d.y), m) + std::pow(std::fabs(d.z), m) +
                        std::pow(std::fabs(c.offset), m),
                    1 / m);
}

// The three nearest seeds' distances (ascending) among the cubes within `reach` cubes of p's, and
// the nearest seed.
struct Nearest {
    double d[3] = {INFINITY, INFINITY, INFINITY};
    Vec3 seed;
};

Nearest nearestSeeds(Vec3 p, const Crackle& c, int reach) {
    const int64_t cx = int64_t(std::floor(p.x)), cy = int64_t(std::floor(p.y)), cz = int64_t(std::floor(p.z));
    Nearest n;
    for (int k = -reach; k <= reach; ++k)
        for (int j = -reach; j <= reach; ++j)
            for (int i = -reach; i <= reach; ++i) {
                const Vec3 s = seedOf(cx + i, cy + j, cz + k);
                const double d = distanceOf(s - p, c);
                if (d >= n.d[2]) continue;
                if (d < n.d[0]) {
                    n.d[2] = n.d[1], n.d[1] = n.d[0], n.d[0] = d;
                    n.seed = s;
                } else if (d < n.d[1]) {
                    n.d[2] = n.d[1], n.d[1] = d;
                } else {
                    n.d[2] = d;
                }
            }
    return n;
}

}  // namespace

double crackleValue(Vec3 p, const Crackle& c) {
    // Every distance (any metric: it is at least the largest coordinate difference) is at least 1
    // to a seed beyond the 3×3×3 cubes round p, so the distances the form uses are exact once the
    // farthest of them is below 1; else the 5×5×5 cubes make them exact up to 2.
    const int needed = c.solid ? 1 : (c.form.z != 0 ? 3 : c.form.y != 0 ? 2 : 1);
    Nearest n = nearestSeeds(p, c, 1);
    if (!(n.d[needed - 1] < 1)) n = nearestSeeds(p, c, 2);
    if (c.solid) return std::clamp(0.5 + kSolidSpread * (noise(n.seed) - 0.5), 0.0, 1.0);
    double v = 0;
    for (int i = 0; i < needed; ++i) v += c.form[i] * n.d[i];
    return std::clamp(v, 0.0, 1.0);
}

}  // namespace rays::pattern
