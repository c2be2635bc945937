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

// Dot product of (x, y, z) with one of the 12 cube-edge gradients chosen by the hash.
inline double grad(int hash, double x, double y, double z) {
    const int h = hash & 15;
    const double u = h < 8 ? x : y;
    const double v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
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
