// Issue 27, "Hardening II": linear-time polygon triangulation, recursion that stops at the stack's
// end, 8-bit textures. The command-line limits and the input ceilings are rows of docs/errors.md
// (errors_test.cpp).
#include <gtest/gtest.h>
#include <pthread.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/io/file_text.h"
#include "rays/io/obj_loader.h"
#include "rays/io/polygon_triangulate.h"
#include "rays/io/scene_parser.h"
#include "rays/render/tracer.h"
#include "rays/scene/shapes/prism.h"
#include "support/files.h"
#include "support/process.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

// A star-shaped polygon of n corners in the plane z = 0, counter-clockwise: radius 1 and `inner`
// alternately (every second corner concave when inner < cos(π/n)).
std::vector<Vec3> star(int n, double inner) {
    std::vector<Vec3> p(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n, r = i % 2 ? inner : 1.0;
        p[size_t(i)] = {r * std::cos(a), r * std::sin(a), 0};
    }
    return p;
}

// A star-shaped polygon whose radii wander at random (deterministic): concave corners in runs.
std::vector<Vec3> wobbly(int n) {
    std::vector<Vec3> p(static_cast<size_t>(n));
    uint64_t h = 12345;
    double r = 1;
    for (int i = 0; i < n; ++i) {
        h = h * 6364136223846793005ull + 1442695040888963407ull;
        r = std::clamp(r + (double(h >> 11) / 9007199254740992.0 - 0.5) * 0.05, 0.3, 1.0);
        const double a = 2 * std::numbers::pi * i / n;
        p[size_t(i)] = {r * std::cos(a), 0, -r * std::sin(a)};  // in the xz plane, seen from +y counter-clockwise
    }
    return p;
}

double signedArea(Vec3 a, Vec3 b, Vec3 c, Vec3 n) { return 0.5 * dot(cross(b - a, c - a), n); }

double polygonArea(const std::vector<Vec3>& p, Vec3 n) {
    double s = 0;
    for (size_t i = 1; i + 1 < p.size(); ++i) s += signedArea(p[0], p[i], p[i + 1], n);
    return s;
}

// Every triangle turns as the polygon does and the triangles cover exactly its area.
void expectCovers(const std::vector<Vec3>& p, const std::vector<std::array<int, 3>>& tris, Vec3 n) {
    ASSERT_EQ(tris.size(), p.size() - 2);
    double sum = 0;
    size_t inverted = 0;
    for (const auto& t : tris) {
        const double a = signedArea(p[size_t(t[0])], p[size_t(t[1])], p[size_t(t[2])], n);
        if (a < -1e-15) ++inverted;
        sum += std::fabs(a);
    }
    EXPECT_EQ(inverted, 0u);
    EXPECT_NEAR(sum, polygonArea(p, n), 1e-9 * std::fabs(polygonArea(p, n)));
}

TEST(HardeningPolygon, ConvexPolygonIsTheFanFromCornerZeroAsBefore) {
    const std::vector<Vec3> hexagon = star(6, 1.0);
    const std::vector<std::array<int, 3>> want = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};
    EXPECT_EQ(triangulatePolygon(hexagon), want);
}

TEST(HardeningPolygon, QuadSplitsAlongTheShorterDiagonal) {
    const std::vector<Vec3> kite = {{0, 0, 0}, {1, -0.2, 0}, {3, 0, 0}, {1, 0.2, 0}};  // 1-3 is shorter
    const std::vector<std::array<int, 3>> want = {{0, 1, 3}, {1, 2, 3}};
    EXPECT_EQ(triangulatePolygon(kite), want);
    const std::vector<Vec3> wide = {{0, 0, 0}, {1, -2, 0}, {1.5, 0, 0}, {1, 2, 0}};  // 0-2 is shorter
    const std::vector<std::array<int, 3>> want2 = {{0, 1, 2}, {0, 2, 3}};
    EXPECT_EQ(triangulatePolygon(wide), want2);
}

TEST(HardeningPolygon, ConcavePolygonsAreCoveredWithoutOverlap) {
    const std::vector<Vec3> l = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    expectCovers(l, triangulatePolygon(l), {0, 0, 1});
    const std::vector<Vec3> s = star(10, 0.4);
    expectCovers(s, triangulatePolygon(s), {0, 0, 1});
    std::vector<Vec3> cw(s.rbegin(), s.rend());  // clockwise: triangles keep the polygon's winding
    expectCovers(cw, triangulatePolygon(cw), {0, 0, -1});
}

TEST(HardeningPolygon, WorkGrowsNearlyLinearlyWithTheCorners) {
    // The case: a polygon of 100k corners took 20 s (quadratic: 10 times the corners, 100
    // times the work). The steps taken are the time's measure: from 10k to 100k corners the steps
    // per corner may grow a little (the grid's cells are sized for an even spread), far from tenfold.
    auto stepsPerCorner = [](const std::vector<Vec3>& p, Vec3 normal) {
        uint64_t work = 0;
        expectCovers(p, triangulatePolygon(p, &work), normal);
        return double(work) / double(p.size());
    };
    EXPECT_EQ(stepsPerCorner(star(100000, 1.0), {0, 0, 1}), 0.0);  // convex: the fan, no search at all
    const double wobbly10k = stepsPerCorner(wobbly(10000), {0, 1, 0}), wobbly100k = stepsPerCorner(wobbly(100000), {0, 1, 0});
    EXPECT_LT(wobbly100k, 2.5 * wobbly10k);
    EXPECT_LT(wobbly100k, 40.0);
    // A star's spikes are long thin ears across many cells: past ear clipping's budget the sweep
    // takes over (polygon_monotone_test.cpp bounds it by n log n).
    const double star10k = stepsPerCorner(star(10000, 0.5), {0, 0, 1}), star100k = stepsPerCorner(star(100000, 0.5), {0, 0, 1});
    EXPECT_LT(star100k, 4.0 * star10k);
}

TEST(HardeningPolygon, DegeneratePolygonsStillGiveNMinusTwoTriangles) {
    std::vector<Vec3> line;
    for (int i = 0; i < 50; ++i) line.push_back({double(i), 0, 0});
    EXPECT_EQ(triangulatePolygon(line).size(), 48u);
    // A bow tie (self-intersecting) has no proper triangulation; it still gets n − 2 triangles.
    const std::vector<Vec3> bow = {{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {1, 1.2, 0}, {0, 2, 0}};
    EXPECT_EQ(triangulatePolygon(bow).size(), 3u);
}

TEST(HardeningObj, APolygonOfHundredThousandCornersLoads) {
    const int n = 100000;
    const std::vector<Vec3> p = star(n, 0.5);
    test::TempDir dir;
    const std::string path = (dir.path() / "big.obj").string();
    {
        std::ofstream out(path);
        for (const Vec3& v : p) out << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
        out << 'f';
        for (int i = 1; i <= n; ++i) out << ' ' << i;
        out << '\n' << "f 1 2 3\n";  // and a triangle after it: the faces stay in order
    }
    const ObjMesh m = loadObj(path);
    ASSERT_EQ(m.faces.size(), size_t(n - 2 + 1));
    std::vector<Vec3> read(m.positions.begin(), m.positions.end());
    std::vector<std::array<int, 3>> tris;
    for (size_t f = 0; f + 1 < m.faces.size(); ++f) tris.push_back(m.faces[f].v);
    expectCovers(read, tris, {0, 0, 1});
    EXPECT_EQ(m.faces.back().v, (std::array<int, 3>{0, 1, 2}));
}

// ---- the stack ----------------------------------------------------------------------------------

Scene facingMirrors() {
    ParseOptions opt;
    opt.warn = [](const std::string&) {};
    return parseScene("camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n"
                      "plane { <0,0,1>, -1 pigment { color rgb 1 } finish { reflection 1 } }\n"
                      "plane { <0,0,-1>, -20 pigment { color rgb 1 } finish { reflection 1 } }\n",
                      "t.pov", opt);
}

// Runs f on a thread with a stack of `bytes`.
template <class F>
void onSmallStack(size_t bytes, F f) {
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, bytes);
    pthread_t t;
    auto body = [](void* arg) -> void* {
        (*static_cast<F*>(arg))();
        return nullptr;
    };
    ASSERT_EQ(pthread_create(&t, &attr, body, &f), 0);
    pthread_join(t, nullptr);
    pthread_attr_destroy(&attr);
}

TEST(HardeningStack, ReflectionsStopAtTheStacksEndNotPastIt) {
    // Two facing mirrors and a depth far past the options' limit, on a 1 MiB stack: before the
    // guard this overflowed (SIGSEGV); now the tree stops where the stack runs short.
    const Scene s = facingMirrors();
    const Bvh bvh(s.objects);
    RenderSettings rs;
    rs.maxDepth = 1000000;
    size_t levels = 0;
    onSmallStack(size_t(1) << 20, [&] {
        TraceContext ctx;
        std::vector<TraceRecord> log;
        Tracer(s, bvh, rs).tracePrimary(Ray{{0, 0, 14}, {0, 0, -1}}, ctx, &log);
        levels = log.size();
    });
    EXPECT_GT(levels, 100u);      // deep, as far as the stack allows
    EXPECT_LT(levels, 1000001u);  // but not the whole way
}

TEST(HardeningStack, GiBouncesStopAtTheStacksEnd) {
    const Scene s = facingMirrors();
    const Bvh bvh(s.objects);
    RenderSettings rs;
    rs.gi = true;
    rs.giSamples[0] = rs.giSamples[1] = 1;
    rs.giBounces = 1000000;
    rs.maxDepth = 0;
    bool done = false;
    onSmallStack(size_t(1) << 20, [&] {
        TraceContext ctx;
        (void)Tracer(s, bvh, rs).tracePrimary(Ray{{0, 0, 14}, {0, 0, -1}}, ctx);
        done = true;
    });
    EXPECT_TRUE(done);
}

TEST(HardeningStack, PovTraceLevelsStopAtTheStacksEnd) {
    ParseOptions opt;
    opt.warn = [](const std::string&) {};
    const Scene s = parseScene("#version 3.7;\nglobal_settings { max_trace_level 256 adc_bailout 0 }\n"
                               "camera { location <0,0,14> look_at <0,0,0> }\n"
                               "plane { z, -1 pigment { rgb 1 } finish { reflection 1 } }\n"
                               "plane { -z, -20 pigment { rgb 1 } finish { reflection 1 } }\n",
                               "t.pov", opt);
    const Bvh bvh(s.objects);
    RenderSettings rs;
    bool done = false;
    onSmallStack(size_t(512) << 10, [&] {  // 512 KiB: room for the reserve the guard keeps under sanitizers too
        TraceContext ctx;
        (void)Tracer(s, bvh, rs).tracePrimary(Ray{{0, 0, 14}, {0, 0, -1}}, ctx);
        done = true;
    });
    EXPECT_TRUE(done);
}

// ---- other loaders ------------------------------------------------------------------------------

TEST(HardeningPrism, LongOutlinesGetTheSameOutwardSidesAsEdgeByEdge) {
    // A star outline of 2000 points with a square hole: the long outline is decided by one edge
    // (linear time), and every edge's side agrees with testing it against the whole outline.
    std::vector<Vec3> pts;
    const int n = 2000;
    for (int i = 0; i <= n; ++i) {
        const double a = 2 * std::numbers::pi * (i % n) / n, r = i % 2 ? 0.6 : 1.0;
        pts.push_back({r * std::cos(a), 0, r * std::sin(a)});
    }
    for (const Vec3 q : {Vec3{-0.2, 0, -0.2}, Vec3{0.2, 0, -0.2}, Vec3{0.2, 0, 0.2}, Vec3{-0.2, 0, 0.2}, Vec3{-0.2, 0, -0.2}})
        pts.push_back(q);
    ShapeData data;
    ASSERT_TRUE(makePrism(pts, 0, 1, data));
    const std::vector<double>& e = data.values;
    ASSERT_EQ(e.size(), size_t(5 * (n + 4)));
    auto inside = [&](double px, double pz) {
        bool in = false;
        for (size_t i = 0; i < e.size(); i += 5)
            if ((e[i + 1] > pz) != (e[i + 3] > pz) && px < e[i] + (pz - e[i + 1]) * (e[i + 2] - e[i]) / (e[i + 3] - e[i + 1]))
                in = !in;
        return in;
    };
    size_t wrong = 0;
    for (size_t i = 0; i < e.size(); i += 5) {
        const double dx = e[i + 2] - e[i], dz = e[i + 3] - e[i + 1], len = std::hypot(dx, dz);
        const double mx = 0.5 * (e[i] + e[i + 2]) + 1e-6 * dz / len, mz = 0.5 * (e[i + 1] + e[i + 3]) - 1e-6 * dx / len;
        if ((inside(mx, mz) ? -1.0 : 1.0) != e[i + 4]) ++wrong;
    }
    EXPECT_EQ(wrong, 0u);
}

}}  // namespace RAYS_TEST_UNIT, namespace
