// POV-Ray's lathe and sor (scene/shapes/lathe.*, sor.*): hits and normals of each spline type at
// points derived from the spline definitions and checked against POV-Ray 3.7's trace() (its
// printed digits), inside tests, caps, bounds, CSG and a small render against POV-Ray's pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rays/scene/csg.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

Scene build(const std::string& text) { return test::buildPov(text); }

bool near(Vec3 a, Vec3 b, double eps = 1e-6) { return length(a - b) < eps; }

Hit shoot(const Scene& s, Vec3 from, Vec3 dir) { return test::shootPov(s, from, dir); }

// The x where a ray along +x at height y from x = −5 meets the object, and the normal there.
struct Seen {
    double x;
    Vec3 normal;
};
Seen fromLeft(const Scene& s, double y) {
    const Hit h = shoot(s, {-5, y, 0}, {1, 0, 0});
    EXPECT_TRUE(h.valid()) << y;
    return Seen{h.t - 5, h.normal};
}

TEST(PovLathe, SplinesMatchTheirDefinitionsAndPovRay) {
    // linear_spline: the cone frustums between the points.
    const Scene lin = build("lathe { linear_spline 3, <1, 0>, <2, 1>, <1, 2> }");
    ASSERT_EQ(lin.objects.size(), 1u);
    EXPECT_EQ(shapeName(lin.objects[0].type), "Lathe");
    Seen s = fromLeft(lin, 0.5);
    EXPECT_NEAR(s.x, -1.5, 1e-9);
    EXPECT_TRUE(near(s.normal, normalize(Vec3{-1, -1, 0})));
    // quadratic_spline: the parabola through <0,0>, <1,1>, <1,2> at −1, 0, 1, drawn from <1,1>:
    // x = 1 + s/2 − s²/2, y = 1 + s. POV-Ray: x = −1.125 at y = 1.5, −1.09375 at 1.25 with the
    // normal <−0.97014250, −0.24253563, 0>.
    const Scene quad = build("lathe { quadratic_spline 3, <0, 0>, <1, 1>, <1, 2> }");
    EXPECT_NEAR(fromLeft(quad, 1.5).x, -1.125, 1e-9);
    s = fromLeft(quad, 1.25);
    EXPECT_NEAR(s.x, -1.09375, 1e-9);
    EXPECT_TRUE(near(s.normal, {-0.97014250, -0.24253563, 0}, 1e-7));
    // cubic_spline: Catmull-Rom from <1,1> to <1.5,2> (POV-Ray's trace).
    const Scene cub = build("lathe { cubic_spline 4, <0, 0>, <1, 1>, <1.5, 2>, <0.5, 4> }");
    s = fromLeft(cub, 1.25);
    EXPECT_NEAR(s.x, -1.21698582, 1e-7);
    EXPECT_TRUE(near(s.normal, {-0.73496715, -0.67810272, 0}, 1e-6));
    s = fromLeft(cub, 1.5);
    EXPECT_NEAR(s.x, -1.41604102, 1e-7);
    EXPECT_TRUE(near(s.normal, {-0.85852304, -0.51277500, 0}, 1e-6));
    // bezier_spline: at its middle x = (1 + 3·2 + 3·2 + 1)/8 = 1.75.
    const Scene bez = build("lathe { bezier_spline 4, <1, 0>, <2, 0.5>, <2, 1.5>, <1, 2> }");
    s = fromLeft(bez, 1);
    EXPECT_NEAR(s.x, -1.75, 1e-9);
    EXPECT_TRUE(near(s.normal, {-1, 0, 0}));
    s = fromLeft(bez, 0.5);
    EXPECT_NEAR(s.x, -1.59479670, 1e-7);
    EXPECT_TRUE(near(s.normal, {-0.83787761, -0.54585815, 0}, 1e-6));
    // The box: POV-Ray's min_extent / max_extent are ±1.1250 across and 1 … 2 high.
    const Bounds b = worldBounds(quad.objects[0]);
    EXPECT_TRUE(near(b.lo, {-1.125, 1, -1.125}, 1e-9) && near(b.hi, {1.125, 2, 1.125}, 1e-9));
}

TEST(PovLathe, ThickTubeFromTheReference) {
    // The reference's example: a tube of radii 2 and 3, 5 high.
    const Scene s = build("lathe { linear_spline 5, <2, 0>, <3, 0>, <3, 5>, <2, 5>, <2, 0> }");
    const std::vector<double> ts = test::allHitsPov(s, {-5, 1, 0}, {1, 0, 0}, 1e-7);
    ASSERT_EQ(ts.size(), 4u);
    EXPECT_NEAR(ts[0], 2, 1e-9);
    EXPECT_NEAR(ts[1], 3, 1e-9);
    EXPECT_NEAR(ts[2], 7, 1e-9);
    EXPECT_NEAR(ts[3], 8, 1e-9);
    const Hit top = shoot(s, {2.5, 9, 0.1}, {0, -1, 0});
    EXPECT_NEAR(top.t, 4, 1e-9);
    EXPECT_TRUE(near(top.normal, {0, 1, 0}));
    const Hit inner = shoot(s, {0, 1, 0}, {0, 0, 1});  // from the hole: the inner wall faces the axis
    EXPECT_NEAR(inner.t, 2, 1e-9);
    EXPECT_TRUE(near(inner.normal, {0, 0, -1}));
    EXPECT_EQ(insideShape(s.objects[0], {2.5, 1, 0}), 1);
    EXPECT_EQ(insideShape(s.objects[0], {0, 2.5, 1.5}), 0);
    EXPECT_EQ(insideShape(s.objects[0], {1.8, 2.5, 1.8}), 1);  // ρ = 2.55
    EXPECT_EQ(insideShape(s.objects[0], {3, 1, 0.5}), 0);
    // In CSG: the tube's lower half.
    const Scene cut = build("intersection { lathe { linear_spline 5, <2, 0>, <3, 0>, <3, 5>, <2, 5>, <2, 0> }"
                            " plane { y, 2.5 } }");
    EXPECT_NEAR(shoot(cut, {2.5, 9, 0}, {0, -1, 0}).t, 6.5, 1e-9);
}

TEST(PovSor, CubicInTheHeightAsPovRayDefinesIt) {
    // Between <1,1> and <1.5,2>: r² = 1 + 1.5w + 1.25w² − 1.5w³ (w = y − 1; slopes 2r·Δr/Δh of the
    // neighbours: 2·1·0.75 and 2·1.5·(−1/6)). POV-Ray: x = −1.19569540 at y = 1.25 (normal
    // <−0.79194834, −0.61058809, 0>), −1.36930639 at 1.5.
    const Scene s = build("sor { 4, <0, 0>, <1, 1>, <1.5, 2>, <0.5, 4> }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(shapeName(s.objects[0].type), "Sor");
    auto r2 = [](double w) { return 1 + 1.5 * w + 1.25 * w * w - 1.5 * w * w * w; };
    Seen a = fromLeft(s, 1.25);
    EXPECT_NEAR(a.x, -std::sqrt(r2(0.25)), 1e-9);
    EXPECT_NEAR(a.x, -1.19569540, 1e-7);
    EXPECT_TRUE(near(a.normal, {-0.79194834, -0.61058809, 0}, 1e-6));
    EXPECT_NEAR(fromLeft(s, 1.5).x, -1.36930639, 1e-7);
    // A level ray (D.y = 0) and a slanted one meet the surface where ρ² = r²(y).
    const Hit h = shoot(s, {-3, 3, 0.2}, {1.8, -1.5, -0.1});
    ASSERT_TRUE(h.valid());
    const Vec3 p = Vec3{-3, 3, 0.2} + h.t * normalize(Vec3{1.8, -1.5, -0.1});
    ASSERT_LT(p.y, 2);  // the wall, not the top cap
    EXPECT_NEAR(p.x * p.x + p.z * p.z, r2(p.y - 1), 1e-9);
    // The top cap at y = 2 (radius 1.5) and the bottom at y = 1 (radius 1).
    const Hit top = shoot(s, {0.5, 5, 0}, {0, -1, 0});
    EXPECT_NEAR(top.t, 3, 1e-9);
    EXPECT_TRUE(near(top.normal, {0, 1, 0}));
    const Hit bottom = shoot(s, {0.5, -5, 0}, {0, 1, 0});
    EXPECT_NEAR(bottom.t, 6, 1e-9);
    EXPECT_TRUE(near(bottom.normal, {0, -1, 0}));
    // open: no caps; the inner wall is seen through the top.
    const Scene open = build("sor { 4, <0, 0>, <1, 1>, <1.5, 2>, <0.5, 4> open }");
    const Hit through = shoot(open, {1.3, 5, 0}, {0, -1, 0});
    ASSERT_TRUE(through.valid());
    EXPECT_NEAR(1.69, r2(5 - through.t - 1), 1e-9);
    EXPECT_FALSE(shoot(open, {0.2, 5, 0}, {0, -1, 0}).valid());
    // Inside, and the box (POV-Ray: ±1.5066 across, 1 … 2 high).
    EXPECT_EQ(insideShape(s.objects[0], {1.3, 1.5, 0}), 1);
    EXPECT_EQ(insideShape(s.objects[0], {1.4, 1.5, 0}), 0);
    EXPECT_EQ(insideShape(s.objects[0], {0, 2.1, 0}), 0);
    const Bounds b = worldBounds(s.objects[0]);
    EXPECT_NEAR(b.hi.x, 1.5066, 1e-4);
    EXPECT_NEAR(b.lo.y, 1, 1e-12);
    EXPECT_NEAR(b.hi.y, 2, 1e-12);
}

TEST(PovLathe, PixelsMatchPovRay) {
    const Scene s = build(
        "global_settings { assumed_gamma 1.0 }\n"
        "camera { location <0, 3, -8> look_at <0, 1, 0> angle 50 }\n"
        "light_source { <-5, 8, -6> color rgb 1 }\n"
        "plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }\n"
        "lathe { cubic_spline 7, <0, -0.5>, <0.8, 0>, <1.2, 1>, <0.5, 1.6>, <0.7, 2.2>, <0.4, 2.6>, <0, 3>\n"
        "  translate <-2, 0, 0> pigment { rgb <0.9, 0.3, 0.2> } }\n"
        "lathe { bezier_spline 8, <0.5, 0>, <1.2, 0.2>, <1.2, 0.8>, <0.6, 1>, <0.6, 1>, <0.2, 1.2>, <0.2, 1.8>, <0.5, 2>\n"
        "  pigment { rgb <0.3, 0.9, 0.3> } }\n"
        "sor { 7, <0, 0>, <0.12, 0>, <0.62, 0.54>, <0.21, 0.83>, <0.19, 0.96>, <0.29, 1>, <0.47, 1.03>\n"
        "  scale 2 translate <2, 0, 0> pigment { rgb <0.2, 0.4, 0.9> } }\n");
    // 0-255, POV-Ray 3.7.0.10 (+W160 +H120 -D -A +FP)
    const test::PovPixel pixels[] = {{30, 30, {206, 125, 104}}, {80, 40, {120, 198, 120}}, {120, 40, {84, 116, 169}},
                                     {30, 50, {207, 126, 104}}, {80, 50, {101, 167, 101}}, {110, 50, {99, 137, 197}},
                                     {20, 60, {208, 126, 104}}, {70, 60, {124, 205, 124}}, {110, 60, {104, 143, 206}},
                                     {70, 70, {124, 204, 124}}, {120, 70, {56, 79, 117}},  {80, 80, {54, 94, 54}}};
    test::expectPovPixels(test::renderPov(s), pixels);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

// sphere_sweep with linear_spline: the convex hulls of neighbouring spheres; points and normals
// from POV-Ray 3.7's trace().
TEST(PovSphereSweep, LinearSplineMatchesPovRay) {
    const Scene one = build("sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <3, 0, 0>, 0.5 }");
    ASSERT_EQ(one.objects.size(), 1u);
    EXPECT_EQ(shapeName(one.objects[0].type), "SphereSweep");
    struct Case {
        Vec3 from, dir, point, normal;
    };
    const Case cases[] = {
        // The tangent cone: sin α = (1 − 0.5)/3, radius r·cos α at z = r·sin α along the axis.
        {{1.5, 5, 0}, {0, -1, 0}, {1.5, 0.76063883, 0}, {0.16666667, 0.98601330, 0}},
        {{-5, 0.3, 0}, {1, 0, 0}, {-0.95393920, 0.3, 0}, {-0.95393920, 0.3, 0}},  // the first sphere
        {{5, 0.2, 0.1}, {-1, 0, 0}, {3.44721360, 0.2, 0.1}, {0.89442719, 0.4, 0.2}},  // the last
        {{1, 4, 3}, {0, -1, -1}, {1, 0.82732684, -0.17267316}, {0.16666667, 0.96521464, -0.20145203}}};
    for (const Case& c : cases) {
        const Hit h = shoot(one, c.from, c.dir);
        ASSERT_TRUE(h.valid());
        EXPECT_TRUE(near(c.from + h.t * normalize(c.dir), c.point, 1e-7)) << c.point.x;
        EXPECT_TRUE(near(h.normal, c.normal, 1e-7)) << c.point.x;
    }
    // A bend: the joint sphere inside both segments is not a surface.
    const Scene bend = build("sphere_sweep { linear_spline 3, <0, 0, 0>, 0.5, <2, 0, 0>, 0.5, <2, 2, 0>, 0.8 }");
    const Case more[] = {{{2.3, -3, 0.1}, {0, 1, 0}, {2.3, -0.38729833, 0.1}, {0.6, -0.77459667, 0.2}},
                         {{5, 1, 0}, {-1, 0, 0}, {2.65743826, 1, 0}, {0.98868600, -0.15, 0}},
                         {{1, 1, 0}, {1, -1, 0}, {1.40382932, 0.59617068, 0}, {-0.98868600, -0.15, 0}},
                         {{2, 5, 0}, {0, -1, 0}, {2, 2.8, 0}, {0, 1, 0}}};
    for (const Case& c : more) {
        const Hit h = shoot(bend, c.from, c.dir);
        ASSERT_TRUE(h.valid());
        EXPECT_TRUE(near(c.from + h.t * normalize(c.dir), c.point, 1e-7)) << c.point.x;
        EXPECT_TRUE(near(h.normal, c.normal, 1e-7)) << c.point.x;
    }
    // From inside the first segment the next surface is the sweep's outside, past the joint: the
    // second segment's cone, which bulges past the joint sphere (POV-Ray: x = 2.50572174).
    const Hit out = shoot(bend, {1, 0, 0}, {1, 0, 0});
    EXPECT_NEAR(1 + out.t, 2.50572174, 1e-8);
    EXPECT_EQ(insideShape(bend.objects[0], {2, 1, 0}), 1);
    EXPECT_EQ(insideShape(bend.objects[0], {1, 0.6, 0}), 0);
}

// b_spline and cubic_spline sweeps: tops of the swept spheres from POV-Ray 3.7's trace() straight
// down (povray 3.7.0.10, #debug vstr 9 and 6 digits); Rays samples the curve (1e-3 of the radii).
TEST(PovSphereSweep, SplineSweepsMatchPovRay) {
    struct Case {
        const char* sweep;
        double x, z, y;  // from <x, 5, z> along −y: the hit's y
        Vec3 normal;
    };
    const char* b = "sphere_sweep { b_spline 4, <-1,0,0>,0.2, <0,1,0>,0.3, <1,0,0>,0.2, <2,1,0>,0.4 }";
    const char* c = "sphere_sweep { cubic_spline 4, <-1,0,0>,0.2, <0,1,0>,0.3, <1,0,0>,0.2, <2,1,0>,0.4 }";
    const char* b5 = "sphere_sweep { b_spline 5, <-1,0,0>,0.2, <0,1,0>,0.3, <1,0,0>,0.2, <2,1,0>,0.4, <3,-1,0>,0.1 }";
    const Case cases[] = {
        {b, -0.2, 0, 0.843050087, {-0.75, 0.661438, 0}},     {b, 0.05, 0, 0.931623104, {0.067802, 0.997699, 0}},
        {b, 0.3, 0, 0.87589237, {0.342571, 0.939492, 0}},     {b, 0.55, 0, 0.759547367, {0.471903, 0.881651, 0}},
        {b, 0.8, 0, 0.630367789, {0.40114, 0.916017, 0}},     {b, 1.05, 0, 0.578282308, {0.2, 0.979796, 0}},
        {c, -0.2, 0, 1.223606798, {-0.666667, 0.745356, 0}}, {c, 0.05, 0, 1.297221857, {0.11048, 0.993878, 0}},
        {c, 0.3, 0, 1.194550658, {0.597138, 0.802139, 0}},   {c, 0.55, 0, 0.904197931, {0.84505, 0.534687, 0}},
        {c, 0.8, 0, 0.461573698, {0.866514, 0.499152, 0}},   {c, 1.05, 0, 0.193649167, {0.25, 0.968246, 0}},
        {b5, 0.3, 0.05, 0.870785351, {0.338068, 0.921719, 0.190118}},
        {b5, 0.8, 0.05, 0.624768995, {0.391268, 0.897586, 0.203098}},
        {b5, 1.3, 0.05, 0.704782282, {-0.452796, 0.874633, 0.173184}},
        {b5, 1.8, 0.05, 0.860548171, {-0.019522, 0.987364, 0.157263}},
    };
    for (const Case& k : cases) {
        std::vector<std::string> warnings;
        const Scene s = test::buildPov(k.sweep, &warnings);
        ASSERT_EQ(s.objects.size(), 1u) << k.sweep;
        EXPECT_TRUE(warnings.empty());
        const Hit h = shoot(s, {k.x, 5, k.z}, {0, -1, 0});
        ASSERT_TRUE(h.valid()) << k.sweep << " x " << k.x;
        EXPECT_NEAR(5 - h.t, k.y, 3e-4) << k.sweep << " x " << k.x;
        EXPECT_GT(dot(h.normal, normalize(k.normal)), 0.999) << k.sweep << " x " << k.x;
    }
    // Past the curve's end: nothing (POV-Ray misses too).
    EXPECT_FALSE(shoot(test::buildPov(b), {1.3, 5, 0}, {0, -1, 0}).valid());
    EXPECT_TRUE(test::buildPov("sphere_sweep { cubic_spline 3, 0, 1, x, 1, 2*x, 1 }").objects.empty());  // too few
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
