// POV-Ray's isosurface (scene/shapes/isosurface.*, pov/scene_builder_iso.cpp): hits and normals of
// functions with known roots, threshold, the container's faces (box and sphere), open, inside
// tests and CSG, transformations, and a small render against POV-Ray's pixels. Hits are within
// the accuracy (0.001 by default) of the exact surface, as POV-Ray 3.7's trace() is (it gives
// x = −0.99902344 for the unit sphere's function hit from −x).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "rays/scene/csg.h"
#include "rays/scene/shapes/isosurface.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

Scene build(const std::string& text, std::vector<std::string>* warnings = nullptr) { return test::buildPov(text, warnings); }

bool near(Vec3 a, Vec3 b, double eps) { return length(a - b) < eps; }

Hit shoot(const Scene& s, Vec3 from, Vec3 dir) { return test::shootPov(s, from, dir); }

constexpr double kAcc = 0.001;  // the default accuracy

TEST(PovIsosurface, SphereFunctionHitsAndNormals) {
    const Scene s = build("isosurface { function { x*x + y*y + z*z - 1 } contained_by { box { -2, 2 } } max_gradient 4 }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(shapeName(s.objects[0].type), "Isosurface");
    const Hit h = shoot(s, {-5, 0, 0}, {1, 0, 0});
    ASSERT_TRUE(h.valid());
    EXPECT_NEAR(h.t, 4, kAcc);
    EXPECT_TRUE(near(h.normal, {-1, 0, 0}, 1e-3));
    const Hit d = shoot(s, {0.3, 5, 0.2}, {0, -1, 0});  // POV-Ray: y = 0.93261719
    const double y = std::sqrt(1 - 0.13);
    EXPECT_NEAR(d.t, 5 - y, kAcc);
    EXPECT_TRUE(near(d.normal, Vec3{0.3, y, 0.2}, 2e-3));
    // A miss passes beside it.
    EXPECT_FALSE(shoot(s, {-5, 1.2, 0}, {1, 0, 0}).valid());
}

TEST(PovIsosurface, DeclaredFunctionAndThreshold) {
    const Scene s = build(
        "#declare F = function(x, y, z) { x*x + y*y + z*z }\n"
        "isosurface { function { F(x, y, z) } threshold 0.25 contained_by { box { -2, 2 } } max_gradient 4 }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_NEAR(shoot(s, {-5, 0, 0}, {1, 0, 0}).t, 4.5, kAcc);  // POV-Ray: x = −0.49902344
}

TEST(PovIsosurface, FindsEveryRootOfASine) {
    // sin(4x) in x ∈ [−2, 2]: inside (negative) at x = −2, so the container's face is drawn there
    // (POV-Ray: hit <−2, 0.2, 0.1>, normal −x); then the roots kπ/4, k = −2..2. From +x the
    // function is positive at x = 2 (no face) and the first surface is π/2 (POV-Ray: 1.5703125).
    const Scene s = build(
        "isosurface { function { sin(4*x) } contained_by { box { <-2, -1, -1>, <2, 1, 1> } } max_gradient 4.5 }");
    const Hit face = shoot(s, {-5, 0.2, 0.1}, {1, 0, 0});
    EXPECT_NEAR(face.t, 3, 1e-9);
    EXPECT_TRUE(near(face.normal, {-1, 0, 0}, 1e-12));
    const Hit back = shoot(s, {5, 0.2, 0.1}, {-1, 0, 0});
    EXPECT_NEAR(back.t, 5 - std::numbers::pi / 2, kAcc);
    EXPECT_TRUE(near(back.normal, {1, 0, 0}, 1e-3));
    const std::vector<double> ts = test::allHitsPov(s, {-5, 0.2, 0.1}, {1, 0, 0}, 1e-7);
    ASSERT_EQ(ts.size(), 6u);
    EXPECT_NEAR(ts[0], 3, 1e-9);
    for (int k = -2; k <= 2; ++k) EXPECT_NEAR(ts[size_t(k + 3)], 5 + k * std::numbers::pi / 4, kAcc);
}

TEST(PovIsosurface, ContainerFacesAndOpen) {
    // f = y − 0.3 in the default box {−1, 1}: solid below y = 0.3, the box's faces drawn there.
    const Scene closed = build("isosurface { function { y - 0.3 } }");
    EXPECT_NEAR(shoot(closed, {0, 5, 0}, {0, -1, 0}).t, 4.7, kAcc);  // POV-Ray: y = 0.29980469
    const Hit side = shoot(closed, {-5, 0, 0}, {1, 0, 0});
    EXPECT_NEAR(side.t, 4, 1e-9);
    EXPECT_TRUE(near(side.normal, {-1, 0, 0}, 1e-12));
    EXPECT_FALSE(shoot(closed, {-5, 0.5, 0}, {1, 0, 0}).valid());
    // open: no faces (POV-Ray's trace() finds nothing from −x at y = 0); the surface stays.
    const Scene open = build("isosurface { function { y - 0.3 } open }");
    EXPECT_FALSE(shoot(open, {-5, 0, 0}, {1, 0, 0}).valid());
    EXPECT_NEAR(shoot(open, {0, 5, 0}, {0, -1, 0}).t, 4.7, kAcc);
}

TEST(PovIsosurface, ContainedBySphere) {
    // f = y in the sphere of radius 1: the lower half ball; its round face below, its flat top.
    const Scene s = build("isosurface { function { y } contained_by { sphere { 0, 1 } } }");
    const Hit round = shoot(s, {-5, -0.5, 0}, {1, 0, 0});
    EXPECT_NEAR(round.t, 5 - std::sqrt(0.75), 1e-9);
    EXPECT_TRUE(near(round.normal, Vec3{-std::sqrt(0.75), -0.5, 0}, 1e-9));
    EXPECT_NEAR(shoot(s, {0.2, 5, 0.1}, {0, -1, 0}).t, 5, kAcc);
    EXPECT_FALSE(shoot(s, {-5, 0.5, 0}, {1, 0, 0}).valid());
    // Beyond the sphere nothing, though the function is negative there.
    EXPECT_FALSE(shoot(s, {0.9, 5, 0.9}, {0, -1, 0}).valid());
    // The threshold with a sphere container: x² + y² + z² = 0.25 (POV-Ray: x = −0.49902344).
    const Scene t = build(
        "isosurface { function { x*x + y*y + z*z } threshold 0.25 contained_by { sphere { 0, 2 } } max_gradient 4 }");
    EXPECT_NEAR(shoot(t, {-5, 0, 0}, {1, 0, 0}).t, 4.5, kAcc);
}

TEST(PovIsosurface, InsideAndCsg) {
    // POV-Ray's inside() of f = y − 0.3 in the default box: 1 at the origin, 0 at y = 0.5 and
    // at y = −1.5 (outside the box).
    const Scene s = build("isosurface { function { y - 0.3 } }");
    EXPECT_EQ(insideShape(s.objects[0], {0, 0, 0}), 1);
    EXPECT_EQ(insideShape(s.objects[0], {0, 0.5, 0}), 0);
    EXPECT_EQ(insideShape(s.objects[0], {0, -1.5, 0}), 0);
    // The sphere function cut by the half space x > 0: its flat face at x = 0.
    const Scene c = build(
        "intersection { isosurface { function { x*x + y*y + z*z - 1 } contained_by { box { -2, 2 } } max_gradient 4 }"
        "  box { <0, -3, -3>, <3, 3, 3> } }");
    ASSERT_EQ(c.objects.size(), 1u);
    const Hit h = shoot(c, {-5, 0.1, 0}, {1, 0, 0});
    EXPECT_NEAR(h.t, 5, 1e-9);
    EXPECT_TRUE(near(h.normal, {-1, 0, 0}, 1e-9));
    // A ball with a spherical hole: the ray through the middle meets the hole's wall.
    const Scene d = build(
        "difference { sphere { 0, 1 } isosurface { function { x*x + y*y + z*z - 0.25 } max_gradient 3 } }");
    const std::vector<double> ts = test::allHitsPov(d, {-5, 0, 0}, {1, 0, 0}, 1e-7);
    ASSERT_EQ(ts.size(), 4u);
    EXPECT_NEAR(ts[0], 4, 1e-9);
    EXPECT_NEAR(ts[1], 4.5, kAcc);
    EXPECT_NEAR(ts[2], 5.5, kAcc);
    EXPECT_NEAR(ts[3], 6, 1e-9);
}

TEST(PovIsosurface, TransformsLikeOtherShapes) {
    const Scene s = build(
        "isosurface { function { x*x + y*y + z*z - 1 } contained_by { box { -2, 2 } } max_gradient 4 "
        "scale <2, 1, 1> translate <0, 1, 0> }");
    const Hit h = shoot(s, {-5, 1, 0}, {1, 0, 0});
    EXPECT_NEAR(h.t, 3, 2 * kAcc);
    EXPECT_TRUE(near(h.normal, {-1, 0, 0}, 1e-3));
    EXPECT_NEAR(shoot(s, {0, 5, 0}, {0, -1, 0}).t, 3, kAcc);
}

TEST(PovIsosurface, NotANumberAndTooLowGradientsStillEnd) {
    // sqrt(x) is NaN for x < 0: the march goes on by the accuracy there and ends; from +x the
    // surface sqrt(x) = 0.5 is found.
    const Scene s = build("isosurface { function { sqrt(x) - 0.5 } }");
    EXPECT_NEAR(shoot(s, {5, 0, 0}, {-1, 0, 0}).t, 4.75, kAcc);
    (void)shoot(s, {-5, 0.1, 0}, {1, 0, 0});
    // A max_gradient far below the function's (200) steps over the thin shells: fewer hits, but
    // an answer.
    const Scene low = build("isosurface { function { sin(200*x) } max_gradient 0.01 }");
    EXPECT_LT(test::allHitsPov(low, {-5, 0.1, 0}, {1, 0, 0}, 1e-7).size(), 16u);
}

TEST(PovIsosurface, UnrenderedPatternFunctionsAreNotedAndLeftOut) {
    // Rendered patterns are evaluated (tests/pov_pattern_function_test.cpp); Penrose tiling 26 is not.
    std::vector<std::string> warnings;
    const Scene s = build(
        "#declare P = function { pattern { tiling 26 } }\n"
        "isosurface { function { P(x, y, z) - 0.5 } }\n"
        "sphere { 0, 1 }",
        &warnings);
    EXPECT_EQ(s.objects.size(), 1u);
    ASSERT_FALSE(warnings.empty());
    EXPECT_NE(warnings[0].find("isosurface"), std::string::npos) << warnings[0];
}

TEST(PovIsosurface, PixelsMatchPovRay) {
    const Scene s = build(
        "global_settings { assumed_gamma 1.0 }\n"
        "camera { location <0, 2, -6> look_at <0, 0.2, 0> angle 50 }\n"
        "light_source { <-5, 8, -6> color rgb 1 }\n"
        "plane { y, -1.2 pigment { rgb <0.8, 0.8, 0.7> } }\n"
        "#declare F = function { sqrt(x*x + y*y + z*z) - 1 + 0.15*sin(5*x)*sin(5*y) }\n"
        "isosurface { function { F(x, y, z) } contained_by { box { <-1.5, -1.1, -1.5>, <1.5, 0.6, 1.5> } }\n"
        "  max_gradient 2 pigment { rgb <0.9, 0.5, 0.2> } rotate 20*y translate <-0.4, 0, 0> }\n"
        "isosurface { function { x*x + y*y + z*z } threshold 0.3 contained_by { sphere { 0, 0.5 } } max_gradient 3\n"
        "  pigment { rgb <0.2, 0.6, 0.9> } translate <1.5, -0.5, -1> }\n");
    // 0-255, POV-Ray 3.7.0.10 (+W160 +H120 -D -A +FP)
    const test::PovPixel pixels[] = {
        {50, 55, {207, 159, 104}, "bumpy ball"}, {60, 60, {166, 127, 82}, "bumpy ball"},
        {80, 60, {202, 155, 101}, "bumpy ball"}, {90, 50, {180, 138, 90}, "flat top (container)"},
        {60, 45, {181, 138, 90}, "flat top (container)"}, {40, 70, {195, 150, 98}, "bumpy ball"},
        {60, 80, {189, 145, 95}, "bumpy ball"},  {120, 75, {91, 153, 183}, "cut ball"},
        {125, 80, {102, 170, 203}, "cut ball"},  {100, 70, {169, 169, 159}, "floor"},
        {70, 40, {148, 148, 139}, "floor"},      {30, 50, {160, 160, 151}, "floor"}};
    test::expectPovPixels(test::renderPov(s), pixels);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
