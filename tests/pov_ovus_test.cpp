// POV-Ray's ovus (reference 3.4.5.1.10): hits and normals against POV-Ray 3.7's trace() for
// several radii (the bottom sphere, the joining lemon, the top sphere, the one-sphere case), the
// box against min/max_extent, inside tests against the three parts.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "rays/scene/csg.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

struct Traced {
    const char* ovus;
    double y;       // from <5, y, 0> along −x (povray 3.7.0.10, #debug vstr 9 digits)
    double x;       // the hit's x
    Vec3 normal;
};

const Traced kTraced[] = {
    {"ovus { 1, 0.5 }", -0.98, 0.198997487, {0.198997, -0.98, 0}},
    {"ovus { 1, 0.5 }", -0.5, 0.866025404, {0.866025, -0.5, 0}},
    {"ovus { 1, 0.5 }", 0.1, 0.994987437, {0.994987, 0.1, 0}},
    {"ovus { 1, 0.5 }", 0.22, 0.977862294, {0.98501, 0.1725, 0}},
    {"ovus { 1, 0.5 }", 0.7, 0.829758459, {0.910958, 0.4125, 0}},
    {"ovus { 1, 0.5 }", 1.3, 0.411187478, {0.701672, 0.7125, 0}},
    {"ovus { 1, 0.5 }", 1.42, 0.271293199, {0.542586, 0.84, 0}},
    {"ovus { 1, 0.3 }", 0.4, 0.916515139, {0.916515139, 0.4, 0}},
    {"ovus { 1, 0.3 }", 0.8, 0.669709029, {0.782619799, 0.6225, 0}},
    {"ovus { 0.5, 0.4 }", 0.2, 0.518198377, {0.998198377, 0.06, 0}},
    {"ovus { 0.5, 0.4 }", 0.4, 0.485608616, {0.965608616, 0.26, 0}},
    {"ovus { 1, 0.8 }", 0.4, 1.036396754, {0.998198377, 0.06, 0}},
    {"ovus { 0.6, 1 }", 0.4, 0.979795897, {0.979795897, -0.2, 0}},
    {"ovus { 1, 2.5 }", 0.4, 2.42693222, {0.970772888, -0.24, 0}},
};

TEST(PovOvus, HitsAndNormalsMatchPovRayTrace) {
    for (const Traced& c : kTraced) {
        std::vector<std::string> warnings;
        const Scene s = test::buildPov(c.ovus, &warnings);
        ASSERT_EQ(s.objects.size(), 1u) << c.ovus;
        EXPECT_TRUE(warnings.empty()) << warnings[0];
        const Hit h = test::shootPov(s, {5, c.y, 0}, {-1, 0, 0});
        ASSERT_TRUE(h.valid()) << c.ovus << " y " << c.y;
        EXPECT_NEAR(5 - h.t, c.x, 1e-8) << c.ovus << " y " << c.y;
        EXPECT_GT(dot(h.normal, normalize(c.normal)), 1 - 1e-9) << c.ovus << " y " << c.y;
    }
    const Scene s = test::buildPov("ovus { 1, 0.5 }");
    EXPECT_NEAR(5 - test::shootPov(s, {0, 5, 0}, {0, -1, 0}).t, 1.5, 1e-12);
    EXPECT_NEAR(test::shootPov(s, {0, -5, 0}, {0, 1, 0}).t - 5, -1, 1e-12);
    EXPECT_FALSE(test::shootPov(s, {5, 1.54, 0}, {-1, 0, 0}).valid());
    EXPECT_FALSE(test::shootPov(s, {5, -1.1, 0}, {-1, 0, 0}).valid());
}

TEST(PovOvus, InsideIsTheUnionOfItsParts) {
    // ovus { 1, 0.5 }: the lemon's tube circle has radius 2, centre (−a, −0.125) with a² + 0.125² = 1.
    const Scene s = test::buildPov("ovus { 1, 0.5 }");
    ASSERT_EQ(s.objects.size(), 1u);
    const double a = std::sqrt(1 - 0.125 * 0.125);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(-1.6, 1.6);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 p{U(rng), 0.5 + U(rng), U(rng)};
        const double r = std::sqrt(p.x * p.x + p.z * p.z);
        // Between the touching heights 0.125 and 1.375 the lemon; the spheres beyond.
        const bool lemon = p.y > 0.125 && p.y < 1.375 && (r + a) * (r + a) + (p.y + 0.125) * (p.y + 0.125) < 4;
        const bool want = lemon || dot(p, p) < 1 || dot(p - Vec3{0, 1, 0}, p - Vec3{0, 1, 0}) < 0.25;
        EXPECT_EQ(insideShape(s.objects[0], p), want ? 1 : 0) << p.x << " " << p.y << " " << p.z;
    }
    // The box: POV-Ray's min/max_extent give ±1.007843 across (its whole torus); the surface
    // reaches 1 (the bottom sphere) and 1.5 in height.
    const Bounds b = worldBounds(s.objects[0]);
    EXPECT_NEAR(b.lo.y, -1, 1e-12);
    EXPECT_NEAR(b.hi.y, 1.5, 1e-12);
    EXPECT_NEAR(b.hi.x, 1, 1e-6);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
