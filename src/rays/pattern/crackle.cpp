#include "rays/pattern/crackle.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>

#include "rays/math/abs_power.h"
#include "rays/pattern/cell_hash.h"
#include "rays/pattern/noise.h"

namespace rays::pattern {

namespace {

// A solid cell's value is the noise at its seed (POV-Ray's solid cells: 0.508 ± 0.122 over 4,000
// points, bozo's spread).

// The pattern's metric m, its power and |offset|^m, set once per evaluation.
struct Metric {
    AbsPower power;
    double offsetTerm;
    explicit Metric(const Crackle& c) : power(c.metric), offsetTerm(power(c.offset)) {}
};

// A key that orders distances as the metric does: Σ|dᵢ|^m + |offset|^m, the distance being its
// m-th root (distanceOf), so that the search takes no root per seed. kSquares: metric 2.
template <bool kSquares>
inline double keyOf(Vec3 d, const Metric& m) {
    if (kSquares) return d.x * d.x + d.y * d.y + d.z * d.z + m.offsetTerm;
    return m.power(d.x) + m.power(d.y) + m.power(d.z) + m.offsetTerm;
}

double distanceOf(double key, const Crackle& c) {
    if (c.metric == 2) return std::sqrt(key);
    if (c.metric == 1) return key;
    return std::pow(key, 1 / c.metric);
}

// The three nearest seeds' keys (ascending: keyOf) among the cubes within `reach` cubes of p's,
// and the nearest seed. Only the first `needed` keys are kept exact: a cube whose nearest point is
// already as far as the needed-th seed found is skipped (that gap bounds its seed's distance). The
// 3×3×3 cubes are visited from the middle out, so that the bound soon prunes.
struct Nearest {
    double d[3] = {INFINITY, INFINITY, INFINITY};
    Vec3 seed;
};

struct Offset {
    int8_t i, j, k;
};

// The cubes round the middle one, nearest first: the middle, 6 faces, 12 edges, 8 corners.
constexpr std::array<Offset, 27> middleOut() {
    std::array<Offset, 27> out{};
    int n = 0;
    for (int ring = 0; ring <= 3; ++ring)
        for (int k = -1; k <= 1; ++k)
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i)
                    if ((i != 0) + (j != 0) + (k != 0) == ring) out[size_t(n++)] = Offset{int8_t(i), int8_t(j), int8_t(k)};
    return out;
}
constexpr std::array<Offset, 27> kMiddleOut = middleOut();

inline void consider(Nearest& n, Vec3 s, double d) {
    if (d >= n.d[2]) return;
    if (d < n.d[0]) {
        n.d[2] = n.d[1], n.d[1] = n.d[0], n.d[0] = d;
        n.seed = s;
    } else if (d < n.d[1]) {
        n.d[2] = n.d[1], n.d[1] = d;
    } else {
        n.d[2] = d;
    }
}

// The cube (i, j, k): skipped when its gap's key reaches the needed-th key, else its seed considered.
// p's own cube (its lowest corner) and p's place in it.
struct Around {
    Vec3 p, f;
    int64_t base[3];
};

// The cube (i, j, k) from p's: skipped when its gap's key reaches the needed-th key, else its seed considered.
template <bool kSquares>
inline void visit(Nearest& n, const Around& at, int64_t i, int64_t j, int64_t k, const Metric& c, int needed) {
    const Vec3 o{double(i), double(j), double(k)};
    Vec3 g;  // the gap to the cube along each axis
    for (int a = 0; a < 3; ++a) g[a] = o[a] > 0 ? o[a] - at.f[a] : (o[a] < 0 ? at.f[a] - o[a] - 1 : 0.0);
    if (keyOf<kSquares>(g, c) >= n.d[needed - 1]) return;
    const Vec3 s = crackleSeed(at.base[0] + i, at.base[1] + j, at.base[2] + k);
    consider(n, s, keyOf<kSquares>(s - at.p, c));
}

// The seeds of the 3×3×3 cubes round one cube, kept per thread for the last cubes looked at (16,
// by a hash of the cube): neighbouring points (a pixel's samples, the next pixel, the few rays a
// sample traces) mostly fall in cubes looked at just before, and each seed costs a hash. Seeds do
// not depend on the pattern's modifiers, so the blocks serve every crackle.
struct CubeSeeds {
    int64_t base[3] = {INT64_MIN, INT64_MIN, INT64_MIN};
    double x[27], y[27], z[27];
};

const CubeSeeds& seedsAround(const int64_t base[3]) {
    constexpr int kBlocks = 16;
    thread_local CubeSeeds cache[kBlocks];
    CubeSeeds& c = cache[(base[0] * 3 + base[1] * 5 + base[2] * 7) & (kBlocks - 1)];
    if (c.base[0] != base[0] || c.base[1] != base[1] || c.base[2] != base[2]) {
        for (int l = 0; l < 27; ++l) {
            const Vec3 s = crackleSeed(base[0] + l % 3 - 1, base[1] + (l / 3) % 3 - 1, base[2] + l / 9 - 1);
            c.x[l] = s.x, c.y[l] = s.y, c.z[l] = s.z;
        }
        for (int a = 0; a < 3; ++a) c.base[a] = base[a];
    }
    return c;
}

// Metric 2 over the 3×3×3 cubes: every key at once (vectorised), then the three smallest kept
// without branches (a key's place among them depends on the data: branches on it mispredict).
Nearest nearestSquares27(const Around& at, const Metric& c) {
    const CubeSeeds& s = seedsAround(at.base);
    double key[27];
    for (int l = 0; l < 27; ++l) {
        const double dx = s.x[l] - at.p.x, dy = s.y[l] - at.p.y, dz = s.z[l] - at.p.z;
        key[l] = dx * dx + dy * dy + dz * dz + c.offsetTerm;
    }
    double d0 = INFINITY, d1 = INFINITY, d2 = INFINITY;
    int nearest = 0;
    for (int l = 0; l < 27; ++l) {
        double v = key[l];
        nearest = v < d0 ? l : nearest;
        const double a = std::min(d0, v);
        v = std::max(d0, v), d0 = a;
        const double b = std::min(d1, v);
        v = std::max(d1, v), d1 = b;
        d2 = std::min(d2, v);
    }
    Nearest n;
    n.d[0] = d0, n.d[1] = d1, n.d[2] = d2;
    n.seed = Vec3{s.x[nearest], s.y[nearest], s.z[nearest]};
    return n;
}

template <bool kSquares>
Nearest nearestSeeds(Vec3 p, const Metric& c, int needed, int reach) {
    const Vec3 lo{std::floor(p.x), std::floor(p.y), std::floor(p.z)};
    const Around at{p, p - lo, {int64_t(lo.x), int64_t(lo.y), int64_t(lo.z)}};
    Nearest n;
    if (reach == 1 && kSquares) return nearestSquares27(at, c);
    if (reach == 1) {
        for (const Offset& o : kMiddleOut) visit<kSquares>(n, at, o.i, o.j, o.k, c, needed);
        return n;
    }
    for (int k = -reach; k <= reach; ++k)
        for (int j = -reach; j <= reach; ++j)
            for (int i = -reach; i <= reach; ++i) visit<kSquares>(n, at, i, j, k, c, needed);
    return n;
}

template <bool kSquares>
Nearest nearest(Vec3 p, const Crackle& c, int needed) {
    const Metric m(c);
    Nearest n = nearestSeeds<kSquares>(p, m, needed, 1);
    if (!(distanceOf(n.d[needed - 1], c) < 1)) n = nearestSeeds<kSquares>(p, m, needed, 2);
    return n;
}

}  // namespace

Vec3 crackleSeed(int64_t i, int64_t j, int64_t k) {
    // One hash of the cube (cell_hash.h), its 63 high bits cut into three 21-bit fractions.
    const uint64_t h = cellHash(i, j, k, 1);
    constexpr double kUnit = 1.0 / double(1 << 21);
    return {double(i) + double((h >> 43) & 0x1FFFFF) * kUnit + 0.5 * kUnit,
            double(j) + double((h >> 22) & 0x1FFFFF) * kUnit + 0.5 * kUnit,
            double(k) + double((h >> 1) & 0x1FFFFF) * kUnit + 0.5 * kUnit};
}

double crackleValue(Vec3 p, const Crackle& c) {
    // Every distance (any metric: it is at least the largest coordinate difference) is at least 1
    // to a seed beyond the 3×3×3 cubes round p, so the distances the form uses are exact once the
    // farthest of them is below 1; else the 5×5×5 cubes make them exact up to 2.
    const int needed = c.solid ? 1 : (c.form.z != 0 ? 3 : c.form.y != 0 ? 2 : 1);
    const Nearest n = c.metric == 2 ? nearest<true>(p, c, needed) : nearest<false>(p, c, needed);
    if (c.solid) return std::clamp(noise(n.seed), 0.0, 1.0);
    double v = 0;
    for (int i = 0; i < needed; ++i) v += c.form[i] * distanceOf(n.d[i], c);
    return std::clamp(v, 0.0, 1.0);
}

}  // namespace rays::pattern
