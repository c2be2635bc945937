// A random number per integer lattice cell, the same for every point of the cell: patterns and
// warps that give each unit cell its own value (cells, black_hole's jittered holes). splitmix64's
// finaliser over the cell's coordinates and a salt; not POV-Ray's random table, so the values are
// alike in distribution, not point for point.
#pragma once
#include <cstdint>

namespace rays::pattern {

/// 64 random bits for the cell (i, j, k); `salt` draws independent ones for one cell.
inline uint64_t cellHash(int64_t i, int64_t j, int64_t k, uint64_t salt = 0) {
    auto mix = [](uint64_t z) {
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    };
    uint64_t h = 0x9e3779b97f4a7c15ull ^ salt;
    for (const int64_t c : {i, j, k}) h = mix(h ^ uint64_t(c));
    return h;
}

/// Uniform in [0, 1) for the cell (i, j, k); `salt` draws independent numbers for one cell.
inline double cellUniform(int64_t i, int64_t j, int64_t k, uint64_t salt = 0) {
    return double(cellHash(i, j, k, salt) >> 11) * 0x1.0p-53;
}

}  // namespace rays::pattern
