// POV-Ray's julia_fractal (reference 3.4.5.1.7): hits and normals against POV-Ray 3.7's trace()
// for both algebras, several functions, max_iteration and slices; inside tests against the
// iteration written out here; the quaternion c = 0 case (the unit ball, whatever max_iteration).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "rays/scene/csg.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

struct Traced {
    const char* fractal;
    Vec3 from, dir;
    Vec3 point, normal;  // povray 3.7.0.10's trace() (#debug vstr, 9 and 6 digits)
};

const Traced kTraced[] = {
    {"<0,0,0,0> max_iteration 2 precision 1000", {-10, 0, 0}, {1, 0, 0}, {-1.000000039, 0, 0}, {-1, 0, 0}},
    {"<0,0,0,0> max_iteration 3 precision 10", {-10, 0.3, 0.2}, {1, 0, 0}, {-0.932737917, 0.3, 0.2}, {-0.932738, 0.3, 0.2}},
    {"<0,0,0,0> max_iteration 20 precision 1000", {-10, 0.3, 0.2}, {1, 0, 0}, {-0.93273789, 0.3, 0.2}, {-0.932738, 0.3, 0.2}},
    {"<0,0,0,0> max_iteration 3 precision 1000 hypercomplex", {-10, 0, 0}, {1, 0, 0}, {-1.414213562, 0, 0}, {-1, 0, 0}},
    {"<0,0,0,0> max_iteration 3 precision 1000 hypercomplex", {-10, 0.3, 0.2}, {1, 0, 0}, {-1.363533203, 0.3, 0.2}, {-0.939636, 0.261766, 0.220369}},
    {"<0,0,0,0> max_iteration 4 precision 1000 hypercomplex", {-10, 0.3, 0.2}, {1, 0, 0}, {-1.1180802, 0.3, 0.2}, {-0.861504, 0.364249, 0.353743}},
    {"<0,0,0,0> max_iteration 4 precision 1000 hypercomplex cube", {-10, 0.3, 0.2}, {1, 0, 0}, {-1.1180802, 0.3, 0.2}, {-0.861504, 0.364249, 0.353743}},
    {"<0.3,0,0,0> max_iteration 3 precision 1000 quaternion cube", {-10, 0.3, 0.2}, {1, 0, 0}, {-0.979610675, 0.3, 0.2}, {-0.952481, 0.25344, 0.16896}},
    {"<0.3,0,0,0> max_iteration 8 precision 1000", {-10, 0.3, 0.2}, {1, 0, 0}, {-0.782915395, 0.3, 0.2}, {-0.505931, -0.717705, -0.47847}},
    {"<0.1,0.5,-0.2,0.3> max_iteration 4 precision 1000", {-10, 0.1, -0.05}, {1, 0, 0}, {-0.695742545, 0.1, -0.05}, {-0.867079, -0.458095, 0.195762}},
    {"<0.1,0.5,-0.2,0.3> max_iteration 4 precision 1000", {0.2, 10, 0.1}, {0, -1, 0}, {0.2, 1.041921669, 0.1}, {0.613424, 0.788229, 0.049054}},
    {"<0.1,0.5,-0.2,0.3> max_iteration 4 precision 1000 hypercomplex", {0.2, 10, 0.1}, {0, -1, 0}, {0.2, 1.047517387, 0.1}, {0.252361, 0.684225, 0.684215}},
    {"<0.1,0.5,-0.2,0.3> max_iteration 3 precision 1000 quaternion cube", {0.2, 10, 0.1}, {0, -1, 0}, {0.2, 1.12993367, 0.1}, {0.05341, 0.982966, 0.175854}},
    {"<0.1,0.5,-0.2,0.3> max_iteration 3 precision 1000 hypercomplex cube", {-10, 0.3, 0.2}, {1, 0, 0.1}, {-0.359068099, 0.3, 1.16409319}, {-0.11676, 0.700276, 0.704259}},
    {"<0.1,0.5,-0.2,0.3> max_iteration 4 precision 1000 slice <0,0,0,1>, 0.2", {-10, 0.1, -0.05}, {1, 0, 0}, {-0.766403177, 0.1, -0.05}, {-0.909771, -0.378993, 0.169354}},
    {"<0.1,0.5,-0.2,0.3> max_iteration 4 precision 1000 slice <1,1,0,1>, 0.1", {0.2, 10, 0.1}, {0, -1, 0}, {0.2, 0.760148721, 0.1}, {0.517457, 0.851305, 0.086704}},
    {"<0.1,0.5,-0.2,0.3> max_iteration 4 precision 1000 slice <1,1,0,1>, 0.1", {0.1, -0.2, -10}, {0, 0, 1}, {0.1, -0.2, -1.081001318}, {0.359649, -0.149884, -0.920971}},
};

TEST(PovJuliaFractal, HitsAndNormalsMatchPovRayTrace) {
    for (const Traced& c : kTraced) {
        std::vector<std::string> warnings;
        const Scene s = test::buildPov(std::string("julia_fractal { ") + c.fractal + " }", &warnings);
        ASSERT_EQ(s.objects.size(), 1u) << c.fractal;
        EXPECT_TRUE(warnings.empty()) << warnings[0];
        const Hit h = test::shootPov(s, c.from, c.dir);
        ASSERT_TRUE(h.valid()) << c.fractal;
        const Vec3 p = c.from + h.t * normalize(c.dir);
        EXPECT_LT(length(p - c.point), 1e-7) << c.fractal << " from " << c.from.x << "," << c.from.y << "," << c.from.z;
        EXPECT_GT(dot(h.normal, normalize(c.normal)), 1 - 1e-5) << c.fractal;
    }
}

TEST(PovJuliaFractal, MaxIterationOneAndQuaternionFunctions) {
    std::vector<std::string> warnings;
    // max_iteration 1 draws nothing in POV-Ray 3.7 (trace() finds no surface).
    EXPECT_TRUE(test::buildPov("julia_fractal { <0,0,0,0> max_iteration 1 }", &warnings).objects.empty());
    EXPECT_TRUE(warnings.empty());
    // Quaternions know sqr and cube only: other functions are noted.
    const Scene s = test::buildPov("julia_fractal { <0,0,0,0> quaternion exp }", &warnings);
    EXPECT_TRUE(s.objects.empty());
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("julia_fractal"), std::string::npos);
}

// The reference's rule written out: h(0) = (x, y, z, 0); inside while |h(k)| stays within the
// escape radius for k = 1 … max_iteration − 1 (1 + |p| for quaternions, measured).
bool insideByHand(Vec3 q, const double* p, int n) {
    double a = q.x, b = q.y, c = q.z, d = 0;
    const double r = 1 + std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]);
    if (a * a + b * b + c * c > r * r) return false;
    for (int k = 1; k < n; ++k) {
        const double na = a * a - b * b - c * c - d * d + p[0], nb = 2 * a * b + p[1], nc = 2 * a * c + p[2], nd = 2 * a * d + p[3];
        a = na, b = nb, c = nc, d = nd;
        if (a * a + b * b + c * c + d * d > r * r) return false;
    }
    return true;
}

TEST(PovJuliaFractal, InsideAndFirstHitsAgreeWithTheIterationByHand) {
    const double p[4] = {-0.083, 0.0, -0.83, -0.025};
    const Scene s = test::buildPov("julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 200 }");
    ASSERT_EQ(s.objects.size(), 1u);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> U(-1.6, 1.6);
    int in = 0;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 q{U(rng), U(rng), U(rng)};
        const bool want = insideByHand(q, p, 8);
        in += want;
        EXPECT_EQ(insideShape(s.objects[0], q), want ? 1 : 0) << q.x << " " << q.y << " " << q.z;
    }
    EXPECT_GT(in, 50);
    // First hits: the ray is outside just before the hit and inside just after it.
    for (int i = 0; i < 60; ++i) {
        const Vec3 from = 4.0 * normalize(Vec3{U(rng), U(rng), U(rng)});
        const Vec3 d = normalize(Vec3{0.3 * U(rng), 0.3 * U(rng), 0.3 * U(rng)} - from);
        const Hit h = test::shootPov(s, from, d);
        if (!h.valid()) continue;
        EXPECT_FALSE(insideByHand(from + (h.t - 1e-6) * d, p, 8));
        EXPECT_TRUE(insideByHand(from + (h.t + 1e-6) * d, p, 8));
        for (double t = 0; t < h.t - 1e-6; t += 1.0 / 200) EXPECT_FALSE(insideByHand(from + t * d, p, 8)) << "missed at " << t;
        EXPECT_LT(dot(h.normal, d), 0);
    }
}

// The products written out on components: Hamilton's quaternions (ij = k = −ji) and the
// hypercomplex numbers (ij = ji = k, i² = j² = −1, k² = 1, reference 3.4.5.1.7).
using Q4 = std::array<double, 4>;
Q4 hamilton(const Q4& x, const Q4& y) {
    return {x[0] * y[0] - x[1] * y[1] - x[2] * y[2] - x[3] * y[3], x[0] * y[1] + x[1] * y[0] + x[2] * y[3] - x[3] * y[2],
            x[0] * y[2] - x[1] * y[3] + x[2] * y[0] + x[3] * y[1], x[0] * y[3] + x[1] * y[2] - x[2] * y[1] + x[3] * y[0]};
}
Q4 hypercomplex(const Q4& x, const Q4& y) {
    return {x[0] * y[0] - x[1] * y[1] - x[2] * y[2] + x[3] * y[3], x[0] * y[1] + x[1] * y[0] - x[2] * y[3] - x[3] * y[2],
            x[0] * y[2] + x[2] * y[0] - x[1] * y[3] - x[3] * y[1], x[0] * y[3] + x[3] * y[0] + x[1] * y[2] + x[2] * y[1]};
}

// Inside by the definition, for f(h) = h·h (or h·h·h) in the given product, escape radius r.
template <class Mul>
bool insideByProduct(Vec3 q, const Q4& p, int n, bool cube, double r, Mul mul) {
    Q4 h{q.x, q.y, q.z, 0};
    auto norm2 = [](const Q4& x) { return x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3]; };
    if (norm2(h) > r * r) return false;
    for (int k = 1; k < n; ++k) {
        Q4 f = mul(h, h);
        if (cube) f = mul(f, h);
        for (int i = 0; i < 4; ++i) h[i] = f[i] + p[i];
        if (norm2(h) > r * r) return false;
    }
    return true;
}

// Quaternion cube (h³ in closed form in the renderer) and hypercomplex sqr (two complex squares)
// against the products above, on random points; first hits lie on a change of state.
TEST(PovJuliaFractal, CubeAndHypercomplexInsideAgreeWithTheProducts) {
    const Q4 p = {0.33, 0.54, 0.52, 0.32};
    const double pn = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]);
    struct Case {
        const char* algebra;
        bool cube, hyper;
    };
    for (const Case& c : {Case{"quaternion cube", true, false}, Case{"hypercomplex sqr", false, true}}) {
        const Scene s = test::buildPov(std::string("julia_fractal { <0.33, 0.54, 0.52, 0.32> ") + c.algebra +
                                       " max_iteration 7 precision 200 }");
        ASSERT_EQ(s.objects.size(), 1u) << c.algebra;
        const double r = c.hyper ? 4.0 : 1 + pn;
        auto inside = [&](Vec3 q) {
            return c.hyper ? insideByProduct(q, p, 7, false, r, hypercomplex) : insideByProduct(q, p, 7, true, r, hamilton);
        };
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> U(-1.5, 1.5);  // the sets lie within |x| < 1.5
        int in = 0;
        for (int i = 0; i < 3000; ++i) {
            const Vec3 q{U(rng), U(rng), U(rng)};
            const bool want = inside(q);
            in += want;
            EXPECT_EQ(insideShape(s.objects[0], q), want ? 1 : 0) << c.algebra << " at " << q.x << " " << q.y << " " << q.z;
        }
        EXPECT_GT(in, 10) << c.algebra;
        int hits = 0;
        for (int i = 0; i < 60; ++i) {
            const Vec3 from = (r + 0.5) * normalize(Vec3{U(rng), U(rng), U(rng)});
            const Vec3 d = normalize(Vec3{0.2 * U(rng), 0.2 * U(rng), 0.2 * U(rng)} - from);
            const Hit h = test::shootPov(s, from, d);
            if (!h.valid()) continue;
            ++hits;
            EXPECT_FALSE(inside(from + (h.t - 1e-7) * d)) << c.algebra;
            EXPECT_TRUE(inside(from + (h.t + 1e-7) * d)) << c.algebra;
        }
        EXPECT_GT(hits, 10) << c.algebra;
    }
}

// Rays steps longer than 1/precision where a point's iterates show that no inside point is near
// (an exact bound for sqr and cube), but only by whole steps from the escape sphere's entry: the
// crossing found is always the one of the plain march, in the step where it first meets an
// inside point, thin parts included.
TEST(PovJuliaFractal, LongerStepsFindThePlainMarchsCrossing) {
    struct Case {
        const char* fractal;
        double radius;  // the escape sphere's
    };
    const Case cases[] = {
        {"<0.2, 0.1, 0.59, -0.2> max_iteration 7 precision 20 sqr hypercomplex", 4},
        {"<-0.745, 0, 0.113, 0.05> max_iteration 9 precision 20 hypercomplex", 4},
        {"<0.02, -0.02, 0.8, 0> max_iteration 10 precision 20 sqr quaternion", 1 + std::sqrt(0.02 * 0.02 * 2 + 0.64)},
        {"<0.33, 0.54, 0.52, 0.32> max_iteration 7 precision 20 cube quaternion",
         1 + std::sqrt(0.33 * 0.33 + 0.54 * 0.54 + 0.52 * 0.52 + 0.32 * 0.32)},
        {"<0.49, 0.5, -0.34, 0.1> max_iteration 7 precision 400 quaternion", 1 + std::sqrt(0.49 * 0.49 + 0.25 + 0.34 * 0.34 + 0.01)},
        {"<0.1, 0.5, -0.2, 0.3> max_iteration 6 precision 50 slice <1, 1, 0, 1>, 0.1", 1 + std::sqrt(0.01 + 0.25 + 0.04 + 0.09)},
    };
    for (const Case& c : cases) {
        const Scene s = test::buildPov(std::string("julia_fractal { ") + c.fractal + " }");
        ASSERT_EQ(s.objects.size(), 1u) << c.fractal;
        const double precision = std::stod(std::strstr(c.fractal, "precision ") + 10), step = 1 / precision;
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> U(-1, 1);
        int hits = 0, wrong = 0;
        for (int i = 0; i < 400; ++i) {
            const Vec3 from = (c.radius + 1) * normalize(Vec3{U(rng), U(rng), U(rng)});
            const Vec3 d = normalize(Vec3{0.8 * U(rng), 0.8 * U(rng), 0.8 * U(rng)} - from);
            // The plain march: points every step from the sphere's entry; the first inside one.
            const double b = dot(from, d), disc = b * b - (dot(from, from) - c.radius * c.radius);
            if (disc <= 0) continue;
            const double t0 = -b - std::sqrt(disc), t1 = -b + std::sqrt(disc);
            double first = -1;
            for (int k = 1; t0 + k * step < t1; ++k)
                if (insideShape(s.objects[0], from + (t0 + k * step) * d)) {
                    first = t0 + k * step;
                    break;
                }
            const Hit h = test::shootPov(s, from, d);
            if (first < 0) {
                wrong += h.valid();
                continue;
            }
            ++hits;
            wrong += !h.valid() || !(h.t > first - step - 1e-6 && h.t <= first + 1e-6);
        }
        EXPECT_GT(hits, 40) << c.fractal;
        EXPECT_EQ(wrong, 0) << c.fractal;
    }
}

// From inside (a ray through glass), the march looks at every step from the ray's start, four at
// a time where it can: the first point outside ends it, as in the plain march.
TEST(PovJuliaFractal, RaysFromInsideLeaveAtThePlainMarchsCrossing) {
    const char* fractals[] = {
        "<0.2, 0.1, 0.59, -0.2> max_iteration 7 precision 20 sqr hypercomplex",
        "<0.02, -0.02, 0.8, 0> max_iteration 10 precision 20 sqr quaternion",
        "<0.33, 0.54, 0.52, 0.32> max_iteration 7 precision 20 cube quaternion",
        "<-0.745, 0, 0.113, 0.05> max_iteration 9 precision 20 exp hypercomplex",  // no lanes
    };
    for (const char* fractal : fractals) {
        const Scene s = test::buildPov(std::string("julia_fractal { ") + fractal + " }");
        ASSERT_EQ(s.objects.size(), 1u) << fractal;
        const double step = 1 / std::stod(std::strstr(fractal, "precision ") + 10);
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> U(-1.5, 1.5);
        int rays = 0, wrong = 0;
        for (int i = 0; i < 20000 && rays < 200; ++i) {
            const Vec3 from{U(rng), U(rng), U(rng)};
            if (!insideShape(s.objects[0], from)) continue;
            ++rays;
            const Vec3 d = normalize(Vec3{U(rng), U(rng), U(rng)});
            double first = -1;
            for (int k = 1; k < 4000; ++k)
                if (!insideShape(s.objects[0], from + (1e-9 + k * step) * d)) {
                    first = 1e-9 + k * step;
                    break;
                }
            const Hit h = test::shootPov(s, from, d);
            wrong += !h.valid() || !(h.t > first - step - 1e-6 && h.t <= first + 1e-6);
        }
        EXPECT_GT(rays, 50) << fractal;
        EXPECT_EQ(wrong, 0) << fractal;
    }
}

// The bounds are a box the reaches prove holds every inside point, much smaller than the escape
// sphere's (radius 1 + |p|, or 4 for hypercomplex numbers): random points of the sphere found
// inside all lie in it, and the hits are still the plain march's from the sphere's entry
// (LongerStepsFindThePlainMarchsCrossing).
TEST(PovJuliaFractal, BoundsAreAProvenBoxAroundTheInsidePoints) {
    struct Case {
        const char* fractal;
        double radius;     // the escape sphere's
        double mostHalf;   // the box's half extent is at most this on every axis
    };
    const Case cases[] = {
        {"<0.02, -0.02, 0.8, 0> max_iteration 10 precision 20 sqr quaternion", 1.8005, 1.5},
        {"<0.33, 0.54, 0.52, 0.32> max_iteration 7 precision 20 cube quaternion", 1.8794, 1.5},
        {"<0.2, 0.1, 0.59, -0.2> max_iteration 7 precision 20 sqr hypercomplex", 4, 2.5},
        {"<0.1, 0.5, -0.2, 0.3> max_iteration 6 precision 50 slice <1, 1, 0, 1>, 0.1", 1.6245, 1.7},  // soundness only
    };
    for (const Case& c : cases) {
        const Scene s = test::buildPov(std::string("julia_fractal { ") + c.fractal + " }");
        ASSERT_EQ(s.objects.size(), 1u) << c.fractal;
        const Bounds b = worldBounds(s.objects[0]);
        for (int a = 0; a < 3; ++a) {
            EXPECT_LE(b.hi[a], c.mostHalf) << c.fractal;
            EXPECT_GE(b.lo[a], -c.mostHalf) << c.fractal;
        }
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> U(-c.radius, c.radius);
        int inside = 0, outOfBox = 0;
        for (int i = 0; i < 200000; ++i) {
            const Vec3 p{U(rng), U(rng), U(rng)};
            if (!insideShape(s.objects[0], p)) continue;
            ++inside;
            outOfBox += p.x < b.lo.x || p.y < b.lo.y || p.z < b.lo.z || p.x > b.hi.x || p.y > b.hi.y || p.z > b.hi.z;
        }
        EXPECT_GT(inside, 100) << c.fractal;
        EXPECT_EQ(outOfBox, 0) << c.fractal;
    }
}

// Copies of one fractal share its data (its bounds' proof is made once): 200 copies parse in about
// the time of one; another fractal gets its own.
TEST(PovJuliaFractal, CopiesShareTheirData) {
    const Scene s = test::buildPov(
        "#declare J = julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15 }\n"
        "object { J translate x } object { J rotate 30*y }\n"
        "julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15 }\n"
        "julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 9 precision 15 }\n");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(s.objects[0].data, s.objects[1].data);
    EXPECT_EQ(s.objects[0].data, s.objects[2].data);
    EXPECT_NE(s.objects[0].data, s.objects[3].data);
    EXPECT_EQ(s.shapeData.size(), 2u);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
