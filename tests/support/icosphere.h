// A unit icosphere for tests and benchmarks that need a closed triangle mesh without a model file.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace rays::test {

struct Icosphere {
    std::vector<std::array<double, 3>> vertices;  ///< unit length
    std::vector<std::array<uint32_t, 3>> faces;   ///< 20 · 4^levels, counter-clockwise from outside
};

/// The icosahedron subdivided `levels` times, new vertices pushed out to the unit sphere.
inline Icosphere unitIcosphere(int levels) {
    auto unit = [](std::array<double, 3> p) {
        const double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (double& x : p) x /= l;
        return p;
    };
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    Icosphere s;
    s.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                  {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    s.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9},  {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6},  {3, 6, 8},
               {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (auto& p : s.vertices) p = unit(p);
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            if (const auto it = mid.find(key); it != mid.end()) return it->second;
            std::array<double, 3> m;
            for (int k = 0; k < 3; ++k) m[k] = (s.vertices[a][k] + s.vertices[b][k]) / 2;
            s.vertices.push_back(unit(m));
            return mid[key] = uint32_t(s.vertices.size() - 1);
        };
        std::vector<std::array<uint32_t, 3>> finer;
        finer.reserve(s.faces.size() * 4);
        for (const auto& f : s.faces) {
            const uint32_t a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
            finer.push_back({f[0], a, c});
            finer.push_back({f[1], b, a});
            finer.push_back({f[2], c, b});
            finer.push_back({a, b, c});
        }
        s.faces.swap(finer);
    }
    return s;
}

}  // namespace rays::test
