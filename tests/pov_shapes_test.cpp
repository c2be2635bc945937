// The POV-Ray primitives of scene/shapes (torus, disc, polygon, quadric / cubic / quartic / poly /
// polynomial) and their root finder: hits, normals and inside at points computed by hand, CSG and
// shadows with them, and a small render compared with POV-Ray 3.7's pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/math/poly_roots.h"
#include "rays/pov/load_pov.h"
#include "rays/render/renderer.h"
#include "support/pov_scene.h"
#include "rays/scene/csg.h"
#include "rays/scene/shapes/poly.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

Scene build(const std::string& text, std::vector<std::string>* warnings = nullptr) { return test::buildPov(text, warnings); }

bool near(Vec3 a, Vec3 b, double eps = 1e-6) { return length(a - b) < eps; }

Hit shoot(const Scene& s, Vec3 from, Vec3 dir) { return test::shootPov(s, from, dir); }

std::vector<double> allHits(const Scene& s, Vec3 from, Vec3 dir) { return test::allHitsPov(s, from, dir, 1e-7); }

TEST(PovShapesRoots, FindsEveryRealRootInTheInterval) {
    // (t − 1)(t − 2)(t − 3)(t − 4) = t⁴ − 10t³ + 35t² − 50t + 24
    const double q[5] = {24, -50, 35, -10, 1};
    double r[4];
    ASSERT_EQ(polyRoots(q, 4, 0, 10, r), 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(r[i], i + 1, 1e-12);
    ASSERT_EQ(polyRoots(q, 4, 1.5, 3.5, r), 2);
    EXPECT_NEAR(r[0], 2, 1e-12);
    EXPECT_NEAR(r[1], 3, 1e-12);
    const double none[3] = {1, 0, 1};  // t² + 1
    EXPECT_EQ(polyRoots(none, 2, -10, 10, r), 0);
    // A zero leading coefficient lowers the degree: 2t − 1.
    const double lin[4] = {-1, 2, 0, 0};
    ASSERT_EQ(polyRoots(lin, 3, -10, 10, r), 1);
    EXPECT_NEAR(r[0], 0.5, 1e-15);
    // Degree 7 with close roots: Π (t − k/10), k = 1..7.
    double c[8] = {1};
    for (int k = 1; k <= 7; ++k) {
        for (int i = k; i >= 1; --i) c[i] = c[i - 1] - (k / 10.0) * c[i];
        c[0] *= -(k / 10.0);
    }
    double r7[7];
    ASSERT_EQ(polyRoots(c, 7, 0, 1, r7), 7);
    for (int k = 1; k <= 7; ++k) EXPECT_NEAR(r7[k - 1], k / 10.0, 1e-9);
}

TEST(PovShapesRoots, QuadraticsWithoutCancellationAndRootLimits) {
    double r[4];
    // t² − 1e8 t + 1 has roots 1e-8 (to 1e-24) and 1e8: the naive formula loses the small one.
    const double q[3] = {1, -1e8, 1};
    ASSERT_EQ(polyRoots(q, 2, -1, 2e8, r), 2);
    EXPECT_NEAR(r[0], 1e-8, 1e-20);
    EXPECT_NEAR(r[1], 1e8, 1e-6);
    // Negative leading coefficient: −(t − 2)(t + 3) = −t² − t + 6, ascending order.
    const double neg[3] = {6, -1, -1};
    ASSERT_EQ(polyRoots(neg, 2, -10, 10, r), 2);
    EXPECT_DOUBLE_EQ(r[0], -3);
    EXPECT_DOUBLE_EQ(r[1], 2);
    ASSERT_EQ(polyRoots(neg, 2, -1, 10, r), 1);  // only the one inside
    EXPECT_DOUBLE_EQ(r[0], 2);
    // A double root (t − 1)² counts once.
    const double dbl[3] = {1, -2, 1};
    ASSERT_EQ(polyRoots(dbl, 2, 0, 2, r), 1);
    EXPECT_DOUBLE_EQ(r[0], 1);
    // The limit: the nearest roots only (on the same interval, the same numbers as without it).
    const double quartic[5] = {24, -50, 35, -10, 1};  // roots 1, 2, 3, 4
    double all[4];
    ASSERT_EQ(polyRoots(quartic, 4, 0, 10, all), 4);
    ASSERT_EQ(polyRoots(quartic, 4, 0, 10, r, 1), 1);
    EXPECT_EQ(r[0], all[0]);
    ASSERT_EQ(polyRoots(quartic, 4, 2.5, 10, r, 2), 2);  // another interval: other brackets, same roots
    EXPECT_NEAR(r[0], all[2], 1e-12);
    EXPECT_NEAR(r[1], all[3], 1e-12);
    ASSERT_EQ(polyRoots(neg, 2, -10, 10, r, 1), 1);
    EXPECT_DOUBLE_EQ(r[0], -3);
}

TEST(PovShapesTorus, HitsNormalsAndInside) {
    const Scene s = build("torus { 2, 0.5 }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(shapeName(s.objects[0].type), "Torus");
    const std::vector<double> ts = allHits(s, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(ts.size(), 4u);
    const double want[4] = {2.5, 3.5, 6.5, 7.5};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(ts[size_t(i)], want[i], 1e-9);
    EXPECT_TRUE(near(shoot(s, {-5, 0, 0}, {1, 0, 0}).normal, {-1, 0, 0}));
    EXPECT_FALSE(shoot(s, {0, 5, 0}, {0, -1, 0}).valid());  // through the hole
    const Hit top = shoot(s, {0, 5, 2}, {0, -1, 0});
    EXPECT_NEAR(top.t, 4.5, 1e-9);
    EXPECT_TRUE(near(top.normal, {0, 1, 0}));
    // An oblique hit: the normal points from the rim's middle circle to the hit.
    const Hit side = shoot(s, {2 + 5 * std::sqrt(0.5), 5 * std::sqrt(0.5), 0}, {-1, -1, 0});
    EXPECT_NEAR(side.t, 5 - 0.5, 1e-9);
    EXPECT_TRUE(near(side.normal, normalize(Vec3{1, 1, 0})));
    EXPECT_EQ(insideShape(s.objects[0], {2, 0, 0}), 1);
    EXPECT_EQ(insideShape(s.objects[0], {0, 0, -2.4}), 1);
    EXPECT_EQ(insideShape(s.objects[0], {0, 0, 0}), 0);
    EXPECT_EQ(insideShape(s.objects[0], {2, 0.6, 0}), 0);
    // Transformed: rotated into the x-y plane and moved.
    const Scene t = build("torus { 2, 0.5 rotate 90*x translate <0, 0, 3> }");
    const Hit th = shoot(t, {2, 0, -5}, {0, 0, 1});
    EXPECT_NEAR(th.t, 7.5, 1e-9);
    EXPECT_TRUE(near(th.normal, {0, 0, -1}));
    const Bvh bvh(t.objects);
    EXPECT_TRUE(bvh.any(t.objects, Ray{{2, 0, -5}, {0, 0, 1}}, 1e-9, 10));  // shadows
    EXPECT_FALSE(bvh.any(t.objects, Ray{{0, 0, -5}, {0, 0, 1}}, 1e-9, 10));  // through the hole
}

TEST(PovShapesTorus, FarCamerasStillHitAccurately) {
    const Scene s = build("torus { 1, 0.25 }");
    EXPECT_NEAR(shoot(s, {-1000, 0, 0}, {1, 0, 0}).t, 1000 - 1.25, 1e-7);
    EXPECT_NEAR(shoot(s, {1, 1000, 0}, {0, -1, 0}).t, 1000 - 0.25, 1e-7);
}

// The quartic is skipped for rays that stay in the hole, above or below the ring, or beyond it:
// on random rays through thin and fat tori, wherever dense steps along the ray find a point
// inside, the hit is found, at or before that point and after the last outside step.
TEST(PovShapesTorus, RaysWithInsidePointsAlwaysHit) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(-1, 1);
    for (const char* torus : {"torus { 2, 0.1 }", "torus { 2, 0.5 }", "torus { 1, 0.9 }"}) {
        const Scene s = build(torus);
        ASSERT_EQ(s.objects.size(), 1u);
        int hits = 0;
        for (int i = 0; i < 3000; ++i) {
            const Vec3 from = 6.0 * normalize(Vec3{U(rng), U(rng), U(rng)});
            const Vec3 at{2.2 * U(rng), 0.6 * U(rng), 2.2 * U(rng)};
            const Vec3 d = normalize(at - from);
            const Hit h = shoot(s, from, d);
            const double step = 2e-3;
            for (double t = 6 - 3.1; t < 6 + 3.1; t += step) {  // the tori lie within 3 of the centre
                if (insideShape(s.objects[0], from + t * d) != 1) continue;
                ++hits;
                ASSERT_TRUE(h.valid()) << torus << " ray " << i << " inside at " << t;
                EXPECT_LE(h.t, t + 1e-9) << torus;
                EXPECT_GE(h.t, t - step - 1e-9) << torus;
                break;
            }
        }
        EXPECT_GT(hits, 300) << torus;
    }
}

TEST(PovShapesDisc, HitsTheRingOnly) {
    const Scene s = build("disc { <0, 1, 0>, <0, 2, 0>, 1, 0.5 }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(shapeName(s.objects[0].type), "Disc");
    const Hit h = shoot(s, {0.75, 5, 0}, {0, -1, 0});
    EXPECT_NEAR(h.t, 4, 1e-12);
    EXPECT_TRUE(near(h.normal, {0, 1, 0}));
    EXPECT_FALSE(shoot(s, {0.25, 5, 0}, {0, -1, 0}).valid());  // the hole
    EXPECT_FALSE(shoot(s, {0, 5, 1.2}, {0, -1, 0}).valid());   // beyond the radius
    const Scene full = build("disc { <0, 1, 0>, y, 1 }");
    EXPECT_NEAR(shoot(full, {0, 5, 0}, {0, -1, 0}).t, 4, 1e-12);
    // A tilted disc's box still holds it (the BVH finds it).
    const Scene tilted = build("disc { <3, 0, 0>, <1, 1, 0>, 1 }");
    EXPECT_NEAR(shoot(tilted, {3, 5, 0}, {0, -1, 0}).t, 5, 1e-12);
}

TEST(PovShapesPolygon, SubPolygonsFollowTheEvenOddRule) {
    // A square with a square hole, the second sub-polygon closed by repeating its first point.
    const Scene s = build(
        "polygon { 10, <0, 0>, <4, 0>, <4, 4>, <0, 4>, <0, 0>, <1, 1>, <3, 1>, <3, 3>, <1, 3>, <1, 1> }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(shapeName(s.objects[0].type), "Polygon");
    const Hit h = shoot(s, {0.5, 2, -5}, {0, 0, 1});
    EXPECT_NEAR(h.t, 5, 1e-12);
    EXPECT_NEAR(std::fabs(h.normal.z), 1, 1e-12);
    EXPECT_FALSE(shoot(s, {2, 2, -5}, {0, 0, 1}).valid());  // the hole
    EXPECT_FALSE(shoot(s, {5, 2, -5}, {0, 0, 1}).valid());  // outside
    // An unclosed polygon is closed; 3-D points in a tilted plane.
    const Scene tri = build("polygon { 3, <0, 0, 0>, <2, 0, 2>, <0, 2, 0> }");
    EXPECT_NEAR(shoot(tri, {0.5, 0.5, 5}, {0, 0, -1}).t, 4.5, 1e-12);
    EXPECT_FALSE(shoot(tri, {0.5, 1.8, 5}, {0, 0, -1}).valid());
}

TEST(PovShapesPoly, CoefficientOrderFollowsTheReference) {
    EXPECT_EQ(polyTermCount(4), 35);
    EXPECT_EQ(polyTermIndex(4, 4, 0, 0), 0);   // A1 x⁴
    EXPECT_EQ(polyTermIndex(4, 3, 1, 0), 1);   // A2 x³y
    EXPECT_EQ(polyTermIndex(4, 2, 0, 0), 9);   // A10 x²
    EXPECT_EQ(polyTermIndex(4, 0, 4, 0), 20);  // A21 y⁴
    EXPECT_EQ(polyTermIndex(4, 0, 2, 0), 25);  // A26 y²
    EXPECT_EQ(polyTermIndex(4, 0, 0, 0), 34);  // A35 1
    EXPECT_EQ(polyTermIndex(7, 0, 0, 7), 112);  // A113 z⁷
    EXPECT_EQ(polyTermIndex(7, 2, 3, 0), 40);   // A41 x²y³
}

// The reference's torus "the hard way": major radius √40, minor √12, around y.
const char* kQuarticTorus =
    "quartic { < 1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,"
    " 1, 0, 0, 2, 0, 56, 0, 0, 0, 0, 1, 0, -104, 0, 784 > sturm }";

TEST(PovShapesPoly, QuarticTorusMatchesTheTorus) {
    const Scene s = build(kQuarticTorus);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(shapeName(s.objects[0].type), "Poly");
    const double R = std::sqrt(40.0), r = std::sqrt(12.0);
    const std::vector<double> ts = allHits(s, {-20, 0, 0}, {1, 0, 0});
    ASSERT_EQ(ts.size(), 4u);
    EXPECT_NEAR(ts[0], 20 - R - r, 1e-8);
    EXPECT_NEAR(ts[1], 20 - R + r, 1e-8);
    EXPECT_NEAR(ts[3], 20 + R + r, 1e-8);
    EXPECT_TRUE(near(shoot(s, {-20, 0, 0}, {1, 0, 0}).normal, {-1, 0, 0}));
    const Hit top = shoot(s, {0, 20, R}, {0, -1, 0});
    EXPECT_NEAR(top.t, 20 - r, 1e-8);
    EXPECT_TRUE(near(top.normal, {0, 1, 0}));
    EXPECT_EQ(insideShape(s.objects[0], {R, 0, 0}), 1);
    EXPECT_EQ(insideShape(s.objects[0], {0, 0, 0}), 0);
    // The same surface as poly 4 and as polynomial.
    const Scene p = build(std::string("poly { 4, ") + (kQuarticTorus + 10));
    EXPECT_NEAR(shoot(p, {-20, 0, 0}, {1, 0, 0}).t, 20 - R - r, 1e-8);
    const Scene pn = build(
        "polynomial { 4, xyz(4,0,0):1, xyz(2,2,0):2, xyz(2,0,2):2, xyz(2,0,0):-104, xyz(0,4,0):1,"
        " xyz(0,2,2):2, xyz(0,2,0):56, xyz(0,0,4):1, xyz(0,0,2):-104, xyz(0,0,0):784 }");
    EXPECT_NEAR(shoot(pn, {-20, 0, 0}, {1, 0, 0}).t, 20 - R - r, 1e-8);
    EXPECT_NEAR(shoot(pn, {0, 20, R}, {0, -1, 0}).t, 20 - r, 1e-8);
}

TEST(PovShapesPoly, QuadricAndCubicFollowTheirTermOrders) {
    // x² + 4y² + 9z² − 36 = 0: an ellipsoid with half-axes 6, 3, 2.
    const Scene q = build("quadric { <1, 4, 9>, <0, 0, 0>, <0, 0, 0>, -36 }");
    EXPECT_NEAR(shoot(q, {-20, 0, 0}, {1, 0, 0}).t, 14, 1e-9);
    EXPECT_NEAR(shoot(q, {0, 20, 0}, {0, -1, 0}).t, 17, 1e-9);
    const Hit z = shoot(q, {0, 0, -20}, {0, 0, 1});
    EXPECT_NEAR(z.t, 18, 1e-9);
    EXPECT_TRUE(near(z.normal, {0, 0, -1}));
    // The linear terms G, H, I: x² + y² + z² − 2x − 3 = 0 is the sphere of radius 2 around x = 1.
    const Scene g = build("quadric { <1, 1, 1>, <0, 0, 0>, <-2, 0, 0>, -3 }");
    EXPECT_NEAR(shoot(g, {1, 10, 0}, {0, -1, 0}).t, 8, 1e-9);
    // cubic: the term x³ (A1) and 1 (A20): x³ − 8 = 0 is the plane x = 2.
    std::string cubic = "cubic { <1";
    for (int i = 1; i < 19; ++i) cubic += ", 0";
    cubic += ", -8> }";
    const Scene c = build(cubic);
    const Hit ch = shoot(c, {-5, 0.3, 0.7}, {1, 0, 0});
    EXPECT_NEAR(ch.t, 7, 1e-9);
    EXPECT_TRUE(near(ch.normal, {1, 0, 0}));  // ∇p points to where p grows
    EXPECT_EQ(insideShape(c.objects[0], {0, 0, 0}), 1);
}

TEST(PovShapesPoly, QuadricHitsMatchTheSphereOnRandomRays) {
    // Quadrics are solved in closed form: x² + y² + z² − 4 against the analytic sphere of radius 2,
    // from outside and from inside, with the far root when the near one is behind tMin.
    const Scene q = build("quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -4 }");
    uint64_t state = 12345;
    auto rnd = [&] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return double(state >> 11) / double(1ULL << 53) * 2 - 1;
    };
    int hits = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec3 o{4 * rnd(), 4 * rnd(), 4 * rnd()};
        const Vec3 d = normalize(Vec3{rnd(), rnd(), rnd()} + Vec3{1e-9, 0, 0});
        // The sphere's exact first hit beyond 1e-6.
        const double b = dot(o, d), c = dot(o, o) - 4, disc = b * b - c;
        double want = -1;
        if (disc >= 0) {
            const double t1 = -b - std::sqrt(disc), t2 = -b + std::sqrt(disc);
            want = t1 > 1e-6 ? t1 : (t2 > 1e-6 ? t2 : -1);
        }
        const Hit h = shoot(q, o, d);
        ASSERT_EQ(h.valid(), want > 0) << i;
        if (want <= 0) continue;
        ++hits;
        EXPECT_NEAR(h.t, want, 1e-9) << i;
        const Vec3 p = o + h.t * d;
        EXPECT_NEAR(length(h.normal - p / 2), 0, 1e-9) << i;
    }
    EXPECT_GT(hits, 50);
}

TEST(PovShapesPoly, QuadricInsideBoxesHoldTheirInsideTightly) {
    // Ellipsoids and cylinders (moved, sheared, along an axis) get boxes; others none. Each box is
    // checked against points sampled on the quadric's surface: all inside, the extremes reached.
    const char* bounded[] = {"quadric { <1, 4, 9>, <0, 0, 0>, <0, 0, 0>, -36 }",
                             "quadric { <1, 1, 1>, <0.5, 0, 0.3>, <-2, 1, 0.5>, -3 }",
                             "quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, 0>, -1 }",
                             "quadric { <2, 0, 1>, <0, 0.8, 0>, <1, 0, -1>, -2 }"};
    for (const char* text : bounded) {
        const Scene s = build(text);
        ASSERT_EQ(s.objects.size(), 1u) << text;
        const ShapeData& d = *s.objects[0].data;
        Bounds box;
        ASSERT_TRUE(quadricInsideBox(d, box)) << text;
        // Along rays from the centre in many directions, the surface point p = 0.
        const Vec3 centre = box.centroid();
        Vec3 c = centre;
        for (int a = 0; a < 3; ++a)
            if (!std::isfinite(c[a])) c[a] = 0.3;
        Bounds seen;
        for (int i = 0; i < 4000; ++i) {
            const double u = (i + 0.5) / 4000, phi = i * 2.399963229728653;
            const double z = 1 - 2 * u, rxy = std::sqrt(1 - z * z);
            const Vec3 dir{rxy * std::cos(phi), rxy * std::sin(phi), z};
            ASSERT_LT(evalPolySurface(d, c), 0) << text;
            double lo = 0, hi = 1;
            while (evalPolySurface(d, c + hi * dir) < 0 && hi < 1e6) hi *= 2;
            if (hi >= 1e6) continue;  // along a cylinder's axis
            for (int it = 0; it < 100; ++it) (evalPolySurface(d, c + 0.5 * (lo + hi) * dir) < 0 ? lo : hi) = 0.5 * (lo + hi);
            const Vec3 p = c + lo * dir;
            seen.extend(p);
            for (int a = 0; a < 3; ++a) {
                EXPECT_GE(p[a], box.lo[a] - 1e-9) << text;
                EXPECT_LE(p[a], box.hi[a] + 1e-9) << text;
            }
        }
        for (int a = 0; a < 3; ++a) {
            if (!std::isfinite(box.lo[a])) continue;
            EXPECT_NEAR(seen.lo[a], box.lo[a], 0.02) << text << " axis " << a;
            EXPECT_NEAR(seen.hi[a], box.hi[a], 0.02) << text << " axis " << a;
        }
    }
    // The cylinder along z is free in z alone.
    Bounds cyl;
    ASSERT_TRUE(quadricInsideBox(*build("quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, 0>, -1 }").objects[0].data, cyl));
    EXPECT_TRUE(std::isinf(cyl.lo.z) && std::isinf(cyl.hi.z));
    EXPECT_NEAR(cyl.hi.x, 1, 1e-12);
    // Hyperboloids, cones, paraboloids, planes and the cubic have no box.
    for (const char* text : {"quadric { <1, 1, -1>, <0, 0, 0>, <0, 0, 0>, -1 }", "quadric { <1, 1, -1>, <0, 0, 0>, <0, 0, 0>, 0 }",
                             "quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, -1>, 0 }", "quadric { <0, 0, 0>, <0, 0, 0>, <0, 1, 0>, 0 }",
                             "quadric { <-1, -1, -1>, <0, 0, 0>, <0, 0, 0>, 1 }"}) {
        Bounds none;
        EXPECT_FALSE(quadricInsideBox(*build(text).objects[0].data, none)) << text;
    }
}

TEST(PovShapesQuadric, BoxWithinAClipBoxHoldsTheInsidePointsAndNoMore) {
    // Quadrics without cross terms, unbounded or not, within clip boxes (some sides infinite):
    // every inside point of the clip box lies in the box (sampled), and the box is the one worked
    // out by hand (the extremes lie on edges of the inside, which sampling does not reach).
    struct Case {
        const char* quadric;
        Bounds clip, want;
    };
    const double inf = kInfinity, r10 = std::sqrt(10.0), r15 = std::sqrt(15.0), r2 = std::sqrt(2.0);
    // The ellipsoid's case: each axis's quadratic ≤ 4 less the other two at their least over the
    // clip box (2x² + x: −1/8 at x = −1/4; y² − y: −1/4 at y = 1/2; 3z² + z/2: −1/48 at z = −1/12).
    const double x6 = (-1 + std::sqrt(1 + 8 * (4 + 0.25 + 1.0 / 48))) / 4;
    const double y6 = (1 - std::sqrt(1 + 4 * (4 + 0.125 + 1.0 / 48))) / 2;
    const double zq = std::sqrt(0.25 + 12 * (4 + 0.125 + 0.25)), z6lo = (-0.5 - zq) / 6, z6hi = (-0.5 + zq) / 6;
    const Case cases[] = {
        // hyperboloid of one sheet: x² + z² ≤ 1 + y², |y| ≤ 3
        {"quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }", {{-inf, -2, -inf}, {inf, 3, inf}}, {{-r10, -2, -r10}, {r10, 3, r10}}},
        // two sheets: x² + z² ≤ y² − 1, y ≤ 4
        {"quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, 1 }", {{-inf, 1.5, -inf}, {inf, 4, inf}}, {{-r15, 1.5, -r15}, {r15, 4, r15}}},
        // paraboloid: x² + z² ≤ y ≤ 2
        {"quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0 }", {{-inf, -1, -inf}, {inf, 2, inf}}, {{-r2, 0, -r2}, {r2, 2, r2}}},
        // cone: x² + z² ≤ y², |y| ≤ 2.5
        {"quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, 0 }", {{-5, -1, -inf}, {0.5, 2.5, inf}}, {{-2.5, -1, -2.5}, {0.5, 2.5, 2.5}}},
        // |x| ≥ 1
        {"quadric { <-1, 0, 0>, <0, 0, 0>, <0, 0, 0>, 1 }", {{0.5, -1, -1}, {3, 1, 1}}, {{1, -1, -1}, {3, 1, 1}}},
        // an ellipsoid cut by x ≥ −0.5 and y ≤ 0.5
        {"quadric { <2, 1, 3>, <0, 0, 0>, <1, -1, 0.5>, -4 }", {{-0.5, -inf, -inf}, {inf, 0.5, inf}}, {{-0.5, y6, z6lo}, {x6, 0.5, z6hi}}}};
    for (const Case& c : cases) {
        const Scene scene = build(c.quadric);
        const ShapeData& d = *scene.objects[0].data;
        Bounds box;
        ASSERT_TRUE(quadricBoxWithin(d, c.clip, box)) << c.quadric;
        ASSERT_FALSE(box.empty()) << c.quadric;
        uint64_t state = 7;
        auto next = [&] {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            return double(state >> 11) * 0x1.0p-53;
        };
        for (int i = 0; i < 100000; ++i) {
            Vec3 p;
            for (int a = 0; a < 3; ++a) {  // within the clip box, infinite sides cut at ±6
                const double lo = std::max(c.clip.lo[a], -6.0), hi = std::min(c.clip.hi[a], 6.0);
                p[a] = lo + (hi - lo) * next();
            }
            if (evalPolySurface(d, p) > 0) continue;
            for (int a = 0; a < 3; ++a) {
                EXPECT_GE(p[a], box.lo[a]) << c.quadric;
                EXPECT_LE(p[a], box.hi[a]) << c.quadric;
            }
        }
        for (int a = 0; a < 3; ++a) {
            if (std::isfinite(c.want.lo[a])) EXPECT_NEAR(box.lo[a], c.want.lo[a], 1e-4) << c.quadric << " axis " << a;
            else EXPECT_TRUE(std::isinf(box.lo[a])) << c.quadric << " axis " << a;
            if (std::isfinite(c.want.hi[a])) EXPECT_NEAR(box.hi[a], c.want.hi[a], 1e-4) << c.quadric << " axis " << a;
            else EXPECT_TRUE(std::isinf(box.hi[a])) << c.quadric << " axis " << a;
        }
    }
    // No inside point in the clip box: an empty box. Cross terms: not handled.
    Bounds box;
    const Scene ball = build("quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }");
    ASSERT_TRUE(quadricBoxWithin(*ball.objects[0].data, Bounds{{2, -1, -1}, {3, 1, 1}}, box));
    EXPECT_TRUE(box.empty());
    const Scene slanted = build("quadric { <1, 1, 1>, <1, 0, 0>, <0, 0, 0>, -1 }");
    EXPECT_FALSE(quadricBoxWithin(*slanted.objects[0].data, Bounds{Vec3(-1), Vec3(1)}, box));
}

TEST(PovShapesCsg, AHyperboloidBetweenTwoPlanesIsBounded) {
    // chess2.pov's pawn neck: the intersection's box is the hyperboloid's part between the planes
    // (x² + z² ≤ 0.25·(1 + (y − 5)²) for y in [2.5, 5.5]), so the BVH can skip it.
    const Scene s = build("intersection { plane { y, 5.5 } quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -1 "
                          "translate 5*y scale <0.5, 1, 0.5> } plane { -y, -2.5 } }");
    ASSERT_EQ(s.objects.size(), 1u);
    const Bounds b = s.objects[0].csg->bounds;
    const double r = 0.5 * std::sqrt(1 + 2.5 * 2.5);
    EXPECT_NEAR(b.lo.y, 2.5, 1e-5);
    EXPECT_NEAR(b.hi.y, 5.5, 1e-5);
    EXPECT_NEAR(b.hi.x, r, 1e-4);
    EXPECT_NEAR(b.lo.z, -r, 1e-4);
}

TEST(PovShapesCsg, TorusAndPolyCutByABox) {
    const Scene s = build("difference { torus { 2, 0.5 } box { <0, -1, -3>, <3, 1, 3> } }");
    ASSERT_EQ(s.objects.size(), 1u);
    ASSERT_EQ(s.objects[0].type, ShapeType::Csg);
    EXPECT_NEAR(shoot(s, {-5, 0, 0}, {1, 0, 0}).t, 2.5, 1e-9);
    EXPECT_FALSE(shoot(s, {2, 5, 0}, {0, -1, 0}).valid());  // the removed half
    const Hit cut = shoot(s, {5, 0, 2}, {-1, 0, 0});         // the cut face at x = 0
    EXPECT_NEAR(cut.t, 5, 1e-9);
    EXPECT_TRUE(near(cut.normal, {1, 0, 0}));
    // An unbounded quadric (a cylinder along y) bounded by an intersection with a box.
    const Scene q = build("intersection { quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1 } box { -2, 2 } }");
    ASSERT_EQ(q.objects.size(), 1u);
    EXPECT_NEAR(shoot(q, {0, 10, 0}, {0, -1, 0}).t, 8, 1e-9);   // the box's top inside the cylinder
    EXPECT_NEAR(shoot(q, {-10, 0, 0}, {1, 0, 0}).t, 9, 1e-9);   // the cylinder's side
    EXPECT_FALSE(shoot(q, {-10, 5, 0}, {1, 0, 0}).valid());      // above the box
}

TEST(PovShapesSuperellipsoid, HitsNormalsAndInside) {
    // e = n = 1 is the unit sphere.
    const Scene sphere = build("superellipsoid { <1, 1> }");
    ASSERT_EQ(sphere.objects.size(), 1u);
    EXPECT_EQ(shapeName(sphere.objects[0].type), "Superellipsoid");
    const Hit d = shoot(sphere, {0.6, 5, 0}, {0, -1, 0});
    EXPECT_NEAR(d.t, 5 - 0.8, 1e-9);
    EXPECT_TRUE(near(d.normal, {0.6, 0.8, 0}));
    // <1, 0.25>: a rounded cylinder along z, (x² + y²)⁴ + z⁸ = 1.
    const Scene cyl = build("superellipsoid { <1, 0.25> }");
    const Hit end = shoot(cyl, {0.3, 0, -5}, {0, 0, 1});
    EXPECT_NEAR(end.t, 5 - std::pow(1 - std::pow(0.09, 4), 1.0 / 8), 1e-9);
    const Hit side = shoot(cyl, {-5, 0, 0.5}, {1, 0, 0});
    EXPECT_NEAR(side.t, 5 - std::pow(1 - std::pow(0.5, 8), 1.0 / 8), 1e-9);
    EXPECT_EQ(insideShape(cyl.objects[0], {0.7, 0.7, 0.9}), 0);   // outside the round cross-section
    EXPECT_EQ(insideShape(cyl.objects[0], {0.6, 0.6, 0.9}), 1);
    // <0.2, 0.2>: nearly a box, x¹⁰ + y¹⁰ + z¹⁰ = 1; its rounded corners are missed.
    const Scene box = build("superellipsoid { <0.2, 0.2> }");
    const double z = std::pow(1 - 2 * std::pow(0.5, 10), 0.1);
    const Hit face = shoot(box, {0.5, 0.5, -5}, {0, 0, 1});
    EXPECT_NEAR(face.t, 5 - z, 1e-9);
    EXPECT_TRUE(near(face.normal, normalize(Vec3{std::pow(0.5, 9), std::pow(0.5, 9), -std::pow(z, 9)})));
    EXPECT_FALSE(shoot(box, {0.99, 0.99, -5}, {0, 0, 1}).valid());
    // In CSG: a sphere cut out of it.
    const Scene cut = build("difference { superellipsoid { <1, 1> } sphere { <0, 0, -1>, 0.5 } }");
    EXPECT_NEAR(shoot(cut, {0, 0, -5}, {0, 0, 1}).t, 4.5, 1e-9);
}

TEST(PovShapesSuperellipsoid, HitsLieOnTheSurfaceForWholeAndFractionalPowers) {
    // Whole exponents 2/e, 2/n, e/n are taken by repeated squaring, others through exp2 and log2:
    // both put the hit on f = 1 as std::pow computes f.
    for (const Vec3 en : {Vec3{0.05, 0.05, 0}, Vec3{0.5, 0.25, 0}, Vec3{0.3, 0.7, 0}, Vec3{1, 2.5, 0}, Vec3{0.1, 1, 0}}) {
        const Scene s = build("superellipsoid { <" + std::to_string(en.x) + ", " + std::to_string(en.y) + "> }");
        const double e = en.x, n = en.y;
        int hits = 0;
        for (int i = 0; i < 50; ++i) {
            const Vec3 from{-3 + 0.11 * i, 0.4 - 0.013 * i, -5};
            const Vec3 dir = normalize(Vec3{0.05 * (25 - i) / 25.0, 0.02, 1} - Vec3{from.x * 0.15, 0, 0});
            const Hit h = shoot(s, from, dir);
            if (!h.valid()) continue;
            ++hits;
            const Vec3 p = from + h.t * dir;
            const double f = std::pow(std::pow(std::fabs(p.x), 2 / e) + std::pow(std::fabs(p.y), 2 / e), e / n) +
                             std::pow(std::fabs(p.z), 2 / n);
            EXPECT_NEAR(f, 1, 1e-7) << e << " " << n << " ray " << i;
        }
        EXPECT_GT(hits, 5) << e << " " << n;
    }
}

TEST(PovShapesSuperellipsoid, RaysFromInsideLeaveThroughTheSurface) {
    // A convex superellipsoid (e, n <= 2) takes the stretch from a start inside to the box's far side
    // as its bracket; a non-convex one (n = 2.5, 3) samples as from outside. Both exit on f = 1,
    // going outwards, and the unit sphere <1, 1> exactly where it should.
    const Scene sphere = build("superellipsoid { <1, 1> }");
    const Hit out = shoot(sphere, {0.2, 0.1, 0}, {1, 0, 0});
    EXPECT_NEAR(out.t, std::sqrt(0.99) - 0.2, 1e-9);
    EXPECT_TRUE(near(out.normal, {std::sqrt(0.99), 0.1, 0}));
    for (const Vec3 en : {Vec3{0.05, 0.05, 0}, Vec3{0.5, 0.25, 0}, Vec3{2, 2, 0}, Vec3{1, 2.5, 0}, Vec3{0.3, 3, 0}}) {
        const Scene s = build("superellipsoid { <" + std::to_string(en.x) + ", " + std::to_string(en.y) + "> }");
        const double e = en.x, n = en.y;
        for (int i = 0; i < 40; ++i) {
            const Vec3 from{0.02 * (i % 7) - 0.06, 0.015 * (i % 5) - 0.03, 0.01 * (i % 3)};
            const Vec3 dir = normalize(Vec3{std::cos(0.7 * i), std::sin(0.7 * i), 0.9 * std::sin(1.3 * i)});
            const Hit h = shoot(s, from, dir);
            ASSERT_TRUE(h.valid()) << e << " " << n << " ray " << i;
            const Vec3 p = from + h.t * dir;
            const double f = std::pow(std::pow(std::fabs(p.x), 2 / e) + std::pow(std::fabs(p.y), 2 / e), e / n) +
                             std::pow(std::fabs(p.z), 2 / n);
            EXPECT_NEAR(f, 1, 1e-7) << e << " " << n << " ray " << i;
            EXPECT_GT(dot(h.normal, dir), 0) << e << " " << n << " ray " << i;
        }
    }
}

TEST(PovShapesSuperellipsoid, PixelsMatchPovRay) {
    const Scene s = build(
        "global_settings { assumed_gamma 1.0 }\n"
        "camera { location <0, 3, -7> look_at <0, 0, 0> angle 50 }\n"
        "light_source { <-5, 8, -6> color rgb 1 }\n"
        "plane { y, -1.5 pigment { rgb <0.8, 0.8, 0.7> } }\n"
        "superellipsoid { <1, 0.2> rotate <-30, 20, 0> translate <-2.2, 0, 0> pigment { rgb <0.9, 0.3, 0.2> } }\n"
        "superellipsoid { <0.3, 0.3> rotate <10, 30, 0> pigment { rgb <0.3, 0.9, 0.3> } }\n"
        "difference { superellipsoid { <2.5, 0.6> } sphere { <0, 0, -1>, 0.7 } rotate <0, -20, 0>\n"
        "  translate <2.2, 0, 0> pigment { rgb <0.2, 0.4, 0.9> } }\n");
    const ImageF img = test::renderPov(s);
    // 0-255, POV-Ray 3.7.0.10 (+W160 +H120 -D -A +FP)
    const test::PovPixel pixels[] = {{25, 60, {191, 115, 95}},  {40, 55, {158, 95, 78}},    {75, 50, {117, 194, 117}},
                            {90, 60, {83, 140, 83}},   {125, 55, {103, 143, 206}}, {140, 50, {104, 144, 207}},
                            {130, 70, {39, 56, 85}},   {112, 62, {101, 140, 202}}};
    test::expectPovPixels(img, pixels);
}

TEST(PovShapesPrism, LinearSweepHitsNormalsAndInside) {
    // A square frame: the outer square 6 × 8, the inner 4 × 6 a hole (reference's example).
    const Scene s = build(
        "prism { linear_spline 0, 1, 10, <0,0>, <6,0>, <6,8>, <0,8>, <0,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1> }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(shapeName(s.objects[0].type), "Prism");
    const Hit top = shoot(s, {0.5, 5, 4}, {0, -1, 0});
    EXPECT_NEAR(top.t, 4, 1e-12);
    EXPECT_TRUE(near(top.normal, {0, 1, 0}));
    EXPECT_FALSE(shoot(s, {3, 5, 4}, {0, -1, 0}).valid());  // the hole
    const Hit side = shoot(s, {-5, 0.5, 4}, {1, 0, 0});
    EXPECT_NEAR(side.t, 5, 1e-12);
    EXPECT_TRUE(near(side.normal, {-1, 0, 0}));
    const Hit inner = shoot(s, {3, 0.5, 4}, {1, 0, 0});  // from inside the hole: the inner wall
    EXPECT_NEAR(inner.t, 2, 1e-12);
    EXPECT_TRUE(near(inner.normal, {-1, 0, 0}));  // out of the solid, into the hole
    EXPECT_EQ(insideShape(s.objects[0], {0.5, 0.5, 4}), 1);
    EXPECT_EQ(insideShape(s.objects[0], {3, 0.5, 4}), 0);
    EXPECT_EQ(insideShape(s.objects[0], {0.5, 1.5, 4}), 0);
    // open: no caps; the walls stay.
    const Scene open = build("prism { 0, 1, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> open }");
    EXPECT_FALSE(shoot(open, {0.2, 5, 0.2}, {0, -1, 0}).valid());
    EXPECT_NEAR(shoot(open, {0.2, 0.5, -5}, {0, 0, 1}).t, 5, 1e-12);
    // A conic sweep is drawn too (tests/pov_prism_test.cpp), without a note.
    std::vector<std::string> warnings;
    const Scene conic = build("prism { conic_sweep 0, 1, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> }", &warnings);
    EXPECT_EQ(conic.objects.size(), 1u);
    EXPECT_TRUE(warnings.empty());
}

TEST(PovShapesPrism, PixelsMatchPovRay) {
    const Scene s = build(
        "global_settings { assumed_gamma 1.0 }\n"
        "camera { location <0, 4, -7> look_at <0, 0.3, 0> angle 50 }\n"
        "light_source { <-5, 8, -6> color rgb 1 }\n"
        "plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } }\n"
        "prism { linear_spline -1, 0.5, 10, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>,\n"
        "  <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5>\n"
        "  rotate 20*y translate <-1.8, 0, 0> pigment { rgb <0.9, 0.3, 0.2> } }\n"
        "prism { 0, 1, 4, <0, 0>, <1.2, 0>, <0.6, 1.5>, <0, 0> open rotate <-20, 0, 0> translate <1, 0, 0>\n"
        "  pigment { rgb <0.3, 0.9, 0.3> } }\n"
        "difference { prism { -1, 1.5, 7, <0, 0>, <2, 0>, <2, 1>, <1, 1>, <1, 2>, <0, 2>, <0, 0> }\n"
        "  sphere { <2, 1.5, 0>, 0.8 } scale 0.6 translate <-0.5, 0, 0.5> pigment { rgb <0.2, 0.4, 0.9> } }\n");
    const ImageF img = test::renderPov(s);
    // 0-255, POV-Ray 3.7.0.10 (+W160 +H120 -D -A +FP)
    const test::PovPixel pixels[] = {{30, 60, {188, 114, 94}}, {40, 75, {171, 103, 85}},   {36, 55, {85, 48, 39}},
                            {95, 55, {80, 80, 75}},   {105, 60, {78, 131, 78}},   {112, 45, {48, 85, 48}},
                            {117, 48, {106, 176, 106}}, {70, 70, {39, 56, 85}}, {75, 60, {84, 117, 169}}};
    test::expectPovPixels(img, pixels);
}

// The object BVH rejects an object whose bounding sphere the ray misses (the leaf's box bounds
// several objects at once), so the sphere must hold every hit; a torus' sphere is its own, R + r,
// not the one round its box.
TEST(PovShapesBounds, BoundingSpheresHoldEveryHitAndATorusIsTight) {
    const Scene s = build(
        "torus { 10, 1.5 rotate 90*x translate 35*x rotate 15*y }\n"
        "torus { 2, 0.5 scale <1, 3, 0.5> rotate <20, 40, 60> translate <1, 2, 3> }\n"
        "box { <-1, -2, -0.5>, <2, 1, 3> rotate <10, 70, 5> scale <2, 1, 1> }\n"
        "cone { <0, 0, 0>, 1, <0, 3, 1>, 0.2 translate <5, 0, 0> }\n"
        "cylinder { <-1, 0, 0>, <1, 1, 0>, 0.3 rotate 30*z }\n"
        "sphere { <1, 1, 1>, 2 scale <1, 0.5, 3> rotate 45*y }\n"
        "superellipsoid { <0.3, 0.6> scale <3, 1, 1> rotate 30*z }\n"
        "difference { box { -1, 1 } sphere { 0, 1.2 } rotate <30, 30, 0> translate 4*y }\n");
    ASSERT_EQ(s.objects.size(), 8u);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (size_t i = 0; i < s.objects.size(); ++i) {
        const Object& o = s.objects[i];
        Vec3 c;
        double radius = 0;
        ASSERT_TRUE(worldBoundingSphere(o, c, radius)) << i;
        int hits = 0;
        for (int k = 0; k < 4000; ++k) {
            const Vec3 aim = c + radius * Vec3{u(rng), u(rng), u(rng)};
            const Vec3 from = c + 3 * radius * normalize(Vec3{u(rng), u(rng), u(rng)});
            ShapeHit h;
            if (!intersect(o, Ray{from, aim - from}, 1e-9, 1e30, h)) continue;
            ++hits;
            EXPECT_LE(length(from + h.t * (aim - from) - c), radius) << "object " << i;
        }
        EXPECT_GT(hits, 100) << "object " << i;
    }
    Vec3 c;
    double radius = 0;
    ASSERT_TRUE(worldBoundingSphere(s.objects[0], c, radius));
    const double a = 15 * M_PI / 180;
    EXPECT_TRUE(near(c, {35 * std::cos(a), 0, -35 * std::sin(a)}, 1e-9));  // rotate 15*y turns +x to −z
    EXPECT_NEAR(radius, 11.5, 1e-6);  // the box's sphere would be √(2·11.5² + 1.5²) ≈ 16.3
    ASSERT_TRUE(worldBoundingSphere(s.objects[5], c, radius));
    EXPECT_NEAR(radius, 6, 1e-6);  // the sphere's radius times its largest scale
}

TEST(PovShapesNotes, RenderedShapesAreNoLongerNoted) {
    std::vector<std::string> warnings;
    const Scene s = build(
        "torus { 1, 0.2 } disc { 0, y, 1 } polygon { 4, <0, 0>, <1, 0>, <1, 1>, <0, 0> }"
        " quadric { <1, 1, 1>, 0, 0, -1 } superellipsoid { <1, 1> }"
        " blob { sphere { 0, 1, 2 } } julia_fractal { <0, 0, 0, 0> }"
        " lathe { 3, <1, 0>, <2, 1>, <1, 2> } sor { 4, <0, 0>, <1, 1>, <1.5, 2>, <0.5, 4> }",
        &warnings);
    EXPECT_EQ(s.objects.size(), 9u);
    std::string all;
    for (const std::string& w : warnings) all += w + "\n";
    EXPECT_EQ(all.find("torus"), std::string::npos) << all;
    EXPECT_EQ(all.find("disc"), std::string::npos) << all;
    EXPECT_EQ(all.find("polygon"), std::string::npos) << all;
    EXPECT_EQ(all.find("quadric"), std::string::npos) << all;
    EXPECT_EQ(all.find("blob"), std::string::npos) << all;
    EXPECT_EQ(all.find("lathe"), std::string::npos) << all;
    EXPECT_EQ(all.find("sor"), std::string::npos) << all;
    EXPECT_EQ(all.find("julia_fractal"), std::string::npos) << all;
}

// Two tori (one cut by a box), a disc and a polygon with holes and the reference's quartic torus
// over a floor; the pixels were measured from POV-Ray 3.7.0.10 (povray +W160 +H120 -D -A +FP).
TEST(PovShapesRender, PixelsMatchPovRay) {
    const Scene s = build(
        "global_settings { assumed_gamma 1.0 }\n"
        "camera { location <0, 2, -8> look_at <0, 0.5, 0> angle 60 }\n"
        "light_source { <-5, 8, -6> color rgb 1 }\n"
        "plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } }\n"
        "torus { 1, 0.35 rotate -60*x translate <-2.3, 1.6, 0> pigment { rgb <0.9, 0.3, 0.2> } }\n"
        "difference { torus { 1, 0.4 } box { <0, -1, -2>, <2, 1, 0> } rotate -60*x translate <2.3, 1.6, 0> pigment { rgb <0.3, 0.9, 0.3> } }\n"
        "disc { <-2.2, -0.2, 0>, <0, 0.3, -1>, 0.9, 0.35 pigment { rgb <0.2, 0.4, 0.9> } }\n"
        "polygon { 10, <-0.8, -0.9>, <0.8, -0.9>, <0.8, 0.7>, <-0.8, 0.7>, <-0.8, -0.9>, <-0.4, -0.5>, <0.4, -0.5>, <0.4, 0.3>, <-0.4, 0.3>, <-0.4, -0.5>\n"
        "  pigment { rgb <0.9, 0.8, 0.2> } }\n"
        "quartic { < 1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 56, 0, 0, 0, 0, 1, 0, -104, 0, 784 >\n"
        "  sturm scale 0.12 rotate -70*x translate <2.3, -0.1, 0> pigment { rgb <0.8, 0.3, 0.8> } }\n"
);
    const ImageF img = test::renderPov(s);
    const test::PovPixel pixels[] = {
        {25, 28, {203, 123, 102}, "the red torus"},
        {45, 20, {176, 106, 87}, "the red torus"},
        {35, 35, {86, 86, 81}, "the floor through the red torus's hole"},
        {120, 30, {65, 111, 65}, "the green torus cut by a box"},
        {130, 40, {107, 177, 107}, "the green torus cut by a box"},
        {110, 45, {92, 154, 92}, "the green torus cut by a box"},
        {37, 65, {39, 56, 85}, "the blue disc"},
        {42, 75, {80, 80, 75}, "the floor through the disc's hole"},
        {72, 73, {165, 157, 82}, "the yellow polygon"},
        {78, 72, {80, 80, 75}, "the floor through the polygon's hole"},
        {120, 75, {169, 108, 169}, "the purple quartic"},
        {110, 75, {165, 105, 165}, "the purple quartic"},
        {115, 68, {161, 161, 151}, "the floor through the quartic's hole"},
    };
    test::expectPovPixels(img, pixels);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
