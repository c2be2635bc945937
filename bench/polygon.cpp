// One OBJ polygon of 10k, 100k and 1M corners: the time to triangulate it (polygon_triangulate.h)
// and to load it as an OBJ file (obj_loader.h), for a convex polygon (a circle), a star (every
// second corner concave) and a star-shaped polygon with wandering radii (runs of concave corners).
// Issue 27: tinyobjloader's ear clipping took 20 s at 100k corners and about half an hour at 1M.
// Usage: build/bench/polygon [MAX_CORNERS]   (figures: docs/limits.md)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "rays/io/obj_loader.h"
#include "rays/io/polygon_triangulate.h"

using namespace rays;

namespace {

std::vector<Vec3> shape(int kind, int n) {
    std::vector<Vec3> p(static_cast<size_t>(n));
    uint64_t h = 12345;
    double r = 1;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n;
        if (kind == 1) r = i % 2 ? 0.5 : 1.0;
        if (kind == 2) {
            h = h * 6364136223846793005ull + 1442695040888963407ull;
            r = std::clamp(r + (double(h >> 11) / 9007199254740992.0 - 0.5) * 0.05, 0.3, 1.0);
        }
        p[size_t(i)] = {r * std::cos(a), r * std::sin(a), 0};
    }
    return p;
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
    const int maxN = argc > 1 ? std::atoi(argv[1]) : 1000000;
    const char* names[] = {"convex", "star", "wobbly"};
    const std::filesystem::path obj = std::filesystem::temp_directory_path() / "rays_bench_polygon.obj";
    std::printf("%-8s %9s %14s %14s %12s\n", "shape", "corners", "triangulate s", "steps/corner", "load OBJ s");
    for (int n = 10000; n <= maxN; n *= 10)
        for (int kind = 0; kind < 3; ++kind) {
            const std::vector<Vec3> p = shape(kind, n);
            auto t0 = std::chrono::steady_clock::now();
            uint64_t work = 0;
            const auto tris = triangulatePolygon(p, &work);
            const double tri = secondsSince(t0);
            {
                std::ofstream out(obj);
                for (const Vec3& v : p) out << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
                out << 'f';
                for (int i = 1; i <= n; ++i) out << ' ' << i;
                out << '\n';
            }
            t0 = std::chrono::steady_clock::now();
            const ObjMesh m = loadObj(obj.string());
            const double load = secondsSince(t0);
            std::printf("%-8s %9d %14.4f %14.2f %12.3f%s\n", names[kind], n, tri, double(work) / n, load,
                        m.faces.size() == tris.size() ? "" : "  (face count differs!)");
        }
    std::filesystem::remove(obj);
    return 0;
}
