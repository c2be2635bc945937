// Perlin's improved noise (Ken Perlin, "Improving Noise", SIGGRAPH 2002): a permutation of
// 0..255 hashes the lattice corners, each picks one of 12 edge gradients, and the quintic fade
// 6t⁵ − 15t⁴ + 10t³ blends the eight corner contributions. The permutation here is generated
// (a fixed linear congruential shuffle), not Perlin's table.
#include "rays/fn/noise.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace rays::fn {
namespace {

constexpr std::array<uint8_t, 512> makePermutation() {
    std::array<uint8_t, 256> p{};
    for (int i = 0; i < 256; ++i) p[i] = static_cast<uint8_t>(i);
    uint32_t s = 0x2545F491u;
    for (int i = 255; i > 0; --i) {  // Fisher-Yates with a fixed LCG
        s = s * 1664525u + 1013904223u;
        const int j = static_cast<int>((s >> 8) % static_cast<uint32_t>(i + 1));
        const uint8_t t = p[i];
        p[i] = p[j];
        p[j] = t;
    }
    std::array<uint8_t, 512> q{};
    for (int i = 0; i < 512; ++i) q[i] = p[i & 255];
    return q;
}

constexpr std::array<uint8_t, 512> kPerm = makePermutation();

inline double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
inline double lerp(double t, double a, double b) { return a + t * (b - a); }

// The 12 cube-edge gradients (and 4 repeats) indexed by the hash's low four bits: for h, ±u ± v
// with u = x (h < 8) or y, v = y (h < 4), x (h = 12, 14) or z, the signs from bits 0 and 1.
struct Gradient {
    double x, y, z;
};
constexpr std::array<Gradient, 16> makeGradients() {
    std::array<Gradient, 16> g{};
    for (int h = 0; h < 16; ++h) {
        const double su = (h & 1) ? -1 : 1, sv = (h & 2) ? -1 : 1;
        Gradient& e = g[size_t(h)];
        if (h < 8) e.x = su;
        else e.y = su;
        if (h < 4) e.y = sv;
        else if (h == 12 || h == 14) e.x = sv;
        else e.z = sv;
    }
    return g;
}
constexpr std::array<Gradient, 16> kGradients = makeGradients();

// Dot product of (x, y, z) with the gradient the hash picks: a table look-up instead of branches
// on the hash, which random hashes mispredicted. The products are exact (±1 or 0 times a
// coordinate), so the sum is the same number as ±u ± v.
inline double grad(int hash, double x, double y, double z) {
    const Gradient& g = kGradients[size_t(hash & 15)];
    return g.x * x + g.y * y + g.z * z;
}

// Perlin's noise in about [-1, 1].
double improvedNoise(double x, double y, double z) {
    const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const int X = static_cast<int>(static_cast<int64_t>(fx) & 255);
    const int Y = static_cast<int>(static_cast<int64_t>(fy) & 255);
    const int Z = static_cast<int>(static_cast<int64_t>(fz) & 255);
    x -= fx;
    y -= fy;
    z -= fz;
    const double u = fade(x), v = fade(y), w = fade(z);
    const int A = kPerm[X] + Y, AA = kPerm[A] + Z, AB = kPerm[A + 1] + Z;
    const int B = kPerm[X + 1] + Y, BA = kPerm[B] + Z, BB = kPerm[B + 1] + Z;
    return lerp(w,
                lerp(v, lerp(u, grad(kPerm[AA], x, y, z), grad(kPerm[BA], x - 1, y, z)),
                     lerp(u, grad(kPerm[AB], x, y - 1, z), grad(kPerm[BB], x - 1, y - 1, z))),
                lerp(v, lerp(u, grad(kPerm[AA + 1], x, y, z - 1), grad(kPerm[BA + 1], x - 1, y, z - 1)),
                     lerp(u, grad(kPerm[AB + 1], x, y - 1, z - 1), grad(kPerm[BB + 1], x - 1, y - 1, z - 1))));
}

}  // namespace

double noise3d(double x, double y, double z, int /*generator*/) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return 0.5;
    const double n = 0.5 + 0.5 * improvedNoise(x, y, z);
    return n < 0 ? 0 : (n > 1 ? 1 : n);
}

}  // namespace rays::fn
