// POV-Ray's blob (scene/shapes/blob.*, pov/scene_builder_blob.cpp): hits and normals at points
// derived from the reference's field s·(1 − (d/R)²)², spot-checked against POV-Ray 3.7's trace()
// (its printed digits; POV-Ray's solver is not exact, so within 1e-5), inside tests and CSG,
// component textures, bounds, and a small render against POV-Ray's pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rays/scene/csg.h"
#include "rays/scene/shapes/blob.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

Scene build(const std::string& text, std::vector<std::string>* warnings = nullptr) { return test::buildPov(text, warnings); }

bool near(Vec3 a, Vec3 b, double eps = 1e-6) { return length(a - b) < eps; }

Hit shoot(const Scene& s, Vec3 from, Vec3 dir) { return test::shootPov(s, from, dir); }

// The distance at which one component of strength s and radius R has field f: R·√(1 − √(f/s)).
double reach(double f, double s, double R) { return R * std::sqrt(1 - std::sqrt(f / s)); }

TEST(PovBlob, OneSphereIsASphereInsideItsRadius) {
    const Scene s = build("blob { threshold 0.5 sphere { 0, 1, 1 } }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(shapeName(s.objects[0].type), "Blob");
    const double r = reach(0.5, 1, 1);  // POV-Ray: trace() hits x = −0.54119610
    EXPECT_NEAR(r, 0.54119610, 1e-8);
    const Hit h = shoot(s, {-5, 0, 0}, {1, 0, 0});
    EXPECT_NEAR(h.t, 5 - r, 1e-9);
    EXPECT_TRUE(near(h.normal, {-1, 0, 0}));
    const Hit d = shoot(s, {0.3, 5, 0.2}, {0, -1, 0});
    EXPECT_NEAR(d.t, 5 - std::sqrt(r * r - 0.13), 1e-9);
    EXPECT_TRUE(near(d.normal, normalize(Vec3{0.3, std::sqrt(r * r - 0.13), 0.2})));
    EXPECT_EQ(insideShape(s.objects[0], {0.5, 0, 0}), 1);
    EXPECT_EQ(insideShape(s.objects[0], {0.6, 0, 0}), 0);
    // The box is the component's sphere (POV-Ray's min_extent and max_extent say ±1 too).
    const Bounds b = worldBounds(s.objects[0]);
    EXPECT_TRUE(near(b.lo, Vec3(-1)) && near(b.hi, Vec3(1)));
}

TEST(PovBlob, ThresholdAtOrAboveTheStrengthShowsNothing) {
    EXPECT_FALSE(shoot(build("blob { threshold 1 sphere { 0, 1, 1 } }"), {-5, 0, 0}, {1, 0, 0}).valid());
    EXPECT_TRUE(build("blob { threshold 0 sphere { 0, 1, 1 } }").objects.empty());
    // The default threshold is 1.
    EXPECT_NEAR(shoot(build("blob { sphere { 0, 2, 4 } }"), {-5, 0, 0}, {1, 0, 0}).t, 5 - reach(1, 4, 2), 1e-9);
}

TEST(PovBlob, CylinderHasHemisphericalEnds) {
    // POV-Ray 3.7: top <0, 1.54119610, 0>, side x = −0.54119610, at y = 1.2 x = −0.50288490 with
    // normal <−0.92921013, 0.36955181, 0>.
    const Scene s = build("blob { threshold 0.5 cylinder { <0, 0, 0>, <0, 1, 0>, 1, 1 } }");
    const double r = reach(0.5, 1, 1);
    EXPECT_NEAR(shoot(s, {0, 5, 0}, {0, -1, 0}).t, 5 - (1 + r), 1e-9);
    EXPECT_NEAR(shoot(s, {-5, 0.5, 0}, {1, 0, 0}).t, 5 - r, 1e-9);
    const Hit cap = shoot(s, {-5, 1.2, 0}, {1, 0, 0});
    const double x = std::sqrt(r * r - 0.04);
    EXPECT_NEAR(cap.t, 5 - x, 1e-9);
    EXPECT_NEAR(x, 0.50288490, 1e-8);
    EXPECT_TRUE(near(cap.normal, normalize(Vec3{-x, 0.2, 0})));
    EXPECT_TRUE(near(cap.normal, {-0.92921013, 0.36955181, 0}, 1e-7));
    EXPECT_EQ(insideShape(s.objects[0], {0.5, 1, 0}), 1);
    EXPECT_EQ(insideShape(s.objects[0], {0.52, 1.2, 0}), 0);  // 0.557 from the end, beyond 0.541
    EXPECT_EQ(insideShape(s.objects[0], {0, 1.5, 0}), 1);
    // A ray along the axis stays in the middle piece (constant distance) until the end.
    EXPECT_NEAR(shoot(s, {0.2, -5, 0}, {0, 1, 0}).t, 5 - std::sqrt(r * r - 0.04), 1e-9);
}

TEST(PovBlob, FieldsAddAndNegativeStrengthsDent) {
    // Two spheres of strength 1 and radius 1 at x = ±0.6: between them the sum on the x axis.
    const Scene two = build("blob { threshold 0.5 sphere { <-0.6, 0, 0>, 1, 1 } sphere { <0.6, 0, 0>, 1, 1 } }");
    auto field = [](double x) {
        double f = 0;
        for (double c : {-0.6, 0.6}) {
            const double d2 = (x - c) * (x - c);
            if (d2 < 1) f += (1 - d2) * (1 - d2);
        }
        return f;
    };
    const Hit h = shoot(two, {-5, 0, 0}, {1, 0, 0});
    ASSERT_TRUE(h.valid());
    EXPECT_NEAR(field(h.t - 5), 0.5, 1e-9);
    EXPECT_NEAR(h.t - 5, -0.6 - reach(0.5, 1, 1), 1e-9);  // the other sphere does not reach there
    // Above the middle both add 2(0.64 − y²)² = 0.5, so y = √0.14; alone neither reaches y = 0 there.
    const Hit top = shoot(two, {0, 5, 0}, {0, -1, 0});
    EXPECT_NEAR(5 - top.t, std::sqrt(0.14), 1e-9);
    EXPECT_TRUE(near(top.normal, {0, 1, 0}));
    // POV-Ray 3.7: a sphere of −0.5 at x = 0.8 dents the unit one to x = 0.32504126.
    const Scene dent = build("blob { threshold 0.5 sphere { 0, 1, 1 } sphere { <0.8, 0, 0>, 1, -0.5 } }");
    const Hit dh = shoot(dent, {5, 0, 0}, {-1, 0, 0});
    EXPECT_NEAR(5 - dh.t, 0.32504126, 1e-7);
    EXPECT_TRUE(near(dh.normal, {1, 0, 0}));
    EXPECT_EQ(insideShape(dent.objects[0], {0.2, 0, 0}), 1);
    EXPECT_EQ(insideShape(dent.objects[0], {0.4, 0, 0}), 0);
}

TEST(PovBlob, ComponentTransformationsMatchPovRay) {
    // Measured with POV-Ray 3.7's trace() (point and normal).
    const Scene s = build(
        "blob { threshold 0.5 sphere { 0, 1, 1 } sphere { <0, 0, 0>, 1, 1 scale <2, 1, 1> translate x } }");
    const Hit a = shoot(s, {-5, 0, 0}, {1, 0, 0});
    EXPECT_NEAR(a.t - 5, -0.61867164, 1e-6);
    EXPECT_TRUE(near(a.normal, {-1, 0, 0}));
    const Hit b = shoot(s, {5, 0.2, 0}, {-1, 0, 0});
    EXPECT_NEAR(5 - b.t, 2.00576979, 1e-6);
    EXPECT_TRUE(near(b.normal, {0.78261779, 0.62250252, 0}, 1e-6));
    const Scene c = build(
        "blob { threshold 0.5 sphere { 0, 1, strength 1 } cylinder { <0, 0, 0>, <1, 1, 0>, 0.5, strength 0.8 rotate 30*z }"
        " component 1, 0.7, <0, -1, 0> }");
    const Hit d = shoot(c, {3, 3, 0.1}, {-1, -1, 0});
    EXPECT_TRUE(near(Vec3{3, 3, 0.1} + d.t * normalize(Vec3{-1, -1, 0}), {0.47425270, 0.47425270, 0.1}, 1e-6));
    EXPECT_TRUE(near(d.normal, {0.95438407, 0.13918549, 0.26415610}, 1e-6));
    const Hit e = shoot(c, {0.1, -3, 0.1}, {0, 1, 0});
    EXPECT_NEAR(e.t - 3, -1.35145082, 1e-6);
    EXPECT_TRUE(near(e.normal, {0.26396558, -0.92770919, 0.26396558}, 1e-6));
}

TEST(PovBlob, ManyComponentsThroughTheBoxTree) {
    // 200 spheres along x (0.1 apart, radius 0.3): every ray from above stops where the field of
    // all of them, summed by hand, is the threshold.
    std::string text = "blob { threshold 0.5\n";
    for (int i = 0; i < 200; ++i) text += "sphere { <" + std::to_string(0.1 * i) + ", 0, 0>, 0.3, 0.4 }\n";
    const Scene s = build(text + "}");
    ASSERT_EQ(s.objects.size(), 1u);
    auto field = [](Vec3 p) {
        double f = 0;
        for (int i = 0; i < 200; ++i) {
            const Vec3 e = p - Vec3{0.1 * i, 0, 0};
            const double d2 = dot(e, e) / 0.09;
            if (d2 < 1) f += 0.4 * (1 - d2) * (1 - d2);
        }
        return f;
    };
    for (const double x : {-0.05, 0.0, 0.05, 3.33, 10.0, 19.9, 19.95}) {
        const Hit h = shoot(s, {x, 5, 0.01}, {0, -1, 0});
        ASSERT_TRUE(h.valid()) << x;
        EXPECT_NEAR(field({x, 5 - h.t, 0.01}), 0.5, 1e-9) << x;
        EXPECT_GT(field({x, 5 - h.t - 1e-3, 0.01}), 0.5) << x;  // inside just past it
    }
    EXPECT_FALSE(shoot(s, {20.3, 5, 0}, {0, -1, 0}).valid());
}

TEST(PovBlob, WorksInCsgAndWhenTransformed) {
    // A unit blob sphere (reach 0.541…) scaled by 2, with its right half cut away.
    const Scene s = build("difference { blob { threshold 0.5 sphere { 0, 1, 1 } scale 2 } box { <0, -5, -5>, 5 } }");
    ASSERT_EQ(s.objects.size(), 1u);
    const double r = 2 * reach(0.5, 1, 1);
    EXPECT_NEAR(shoot(s, {-5, 0, 0}, {1, 0, 0}).t, 5 - r, 1e-9);
    const Hit cut = shoot(s, {5, 0.1, 0}, {-1, 0, 0});
    EXPECT_NEAR(cut.t, 5, 1e-9);  // the box's face, inside the blob
    EXPECT_TRUE(near(cut.normal, {1, 0, 0}));
    // The blob subtracted from a box leaves a hollow.
    const Scene hollow = build("difference { box { -2, 2 } blob { threshold 0.5 sphere { 0, 1, 1 } } }");
    const std::vector<double> ts = test::allHitsPov(hollow, {-5, 0, 0}, {1, 0, 0}, 1e-7);
    ASSERT_EQ(ts.size(), 4u);
    EXPECT_NEAR(ts[1], 5 - reach(0.5, 1, 1), 1e-9);
}

TEST(PovBlob, ComponentTexturesShadeWhereTheyAddMostField) {
    // Left sphere red, right sphere blue, the top one the blob's green (POV-Ray blends them by
    // their fields; Rays takes the component adding most).
    const Scene s = build(
        "blob { threshold 0.5 sphere { <-0.6, 0, 0>, 1.2, 1 pigment { rgb x } }"
        " sphere { <0.6, 0, 0>, 1.2, 1 pigment { rgb z } translate 0 } sphere { <0, 0.9, 0>, 0.8, 1 }"
        " pigment { rgb y } }");
    ASSERT_EQ(s.objects.size(), 1u);
    auto colourAt = [&](Vec3 from) {
        const Hit h = shoot(s, from, {0, 0, 1});
        EXPECT_TRUE(h.valid());
        return shadedObject(s.objects, h).material.color;
    };
    EXPECT_TRUE(near(colourAt({-0.8, 0, -5}), {1, 0, 0}));
    EXPECT_TRUE(near(colourAt({0.8, 0, -5}), {0, 0, 1}));
    EXPECT_TRUE(near(colourAt({0, 1.1, -5}), {0, 1, 0}));
}

TEST(PovBlob, PixelsMatchPovRay) {
    const Scene s = build(
        "global_settings { assumed_gamma 1.0 }\n"
        "camera { location <0, 2, -6> look_at <0, 0.3, 0> angle 50 }\n"
        "light_source { <-5, 8, -6> color rgb 1 }\n"
        "plane { y, -1.2 pigment { rgb <0.8, 0.8, 0.7> } }\n"
        "blob { threshold 0.6\n"
        "  sphere { <-1.2, 0, 0>, 1, 1 } sphere { <-0.4, 0.3, 0>, 0.9, 1 }\n"
        "  cylinder { <0.3, -0.5, 0>, <1.6, 0.8, 0.3>, 0.6, 1.5 }\n"
        "  sphere { <-0.8, 0.2, -0.6>, 0.5, -1 }\n"
        "  pigment { rgb <0.9, 0.5, 0.2> } rotate 10*y }\n");
    // 0-255, POV-Ray 3.7.0.10 (+W160 +H120 -D -A +FP)
    const test::PovPixel pixels[] = {{50, 55, {207, 159, 104}}, {60, 60, {174, 133, 86}}, {80, 60, {85, 63, 39}},
                                     {120, 40, {207, 159, 104}}, {110, 55, {202, 155, 102}}, {100, 60, {208, 159, 104}},
                                     {90, 65, {199, 153, 100}},  {80, 80, {193, 148, 97}},   {60, 70, {183, 140, 91}},
                                     {90, 70, {207, 159, 104}}};
    test::expectPovPixels(test::renderPov(s), pixels);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
