// POV-Ray's parametric (reference 3.4.5.1.9), drawn as a fine mesh: hits against POV-Ray 3.7's
// trace() on a height-like surface, against the exact sphere for a sphere, and the container.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

TEST(PovParametric, HeightSurfaceMatchesPovRayTrace) {
    std::vector<std::string> warnings;
    const Scene s = test::buildPov(
        "parametric { function { u } function { 0.3*sin(3*u)*cos(2*v) } function { v } <-1, -1>, <1, 1>"
        " contained_by { sphere { 0, 1.2 } } accuracy 0.0001 }",
        &warnings);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_TRUE(warnings.empty()) << warnings[0];
    // povray 3.7.0.10: trace() from <-0.9 + 0.33 i, 3, -0.7 + 0.27 i> along −y: the hit's y and normal.
    const double y[6] = {-0.021860469, -0.193928237, -0.187754403, 0.078149329, 0.206982897, 0.062362582};
    const Vec3 n[6] = {{-0.132949, -0.960906, -0.242866}, {-0.073937, -0.909349, -0.409412}, {0.537606, -0.83675, -0.104062},
                       {0.645809, -0.763032, -0.026697},  {0.182237, -0.914908, -0.360185}, {-0.136661, -0.903439, -0.406352}};
    for (int i = 0; i < 6; ++i) {
        const Hit h = test::shootPov(s, {-0.9 + i * 0.33, 3, -0.7 + i * 0.27}, {0, -1, 0});
        ASSERT_TRUE(h.valid()) << i;
        EXPECT_NEAR(3 - h.t, y[i], 5e-4) << i;
        EXPECT_GT(std::fabs(dot(h.normal, normalize(n[i]))), 0.999) << i;
    }
    // Outside the container sphere (radius 1.2): no surface.
    EXPECT_FALSE(test::shootPov(s, {0.95, 3, 0.95}, {0, -1, 0}).valid());
}

TEST(PovParametric, SphereLiesOnTheSphere) {
    const Scene s = test::buildPov(
        "parametric { function { cos(u)*cos(v) } function { sin(v) } function { sin(u)*cos(v) }"
        " <0, -1.2>, <2*pi, 1.2> contained_by { box { -1.1, 1.1 } } max_gradient 2 accuracy 0.0001 precompute 10 x, y, z }");
    ASSERT_EQ(s.objects.size(), 1u);
    for (int i = 0; i < 6; ++i) {
        const Vec3 from{3, -0.8 + i * 0.3, 0.1 + i * 0.05}, d = normalize(Vec3{-1, 0.02, 0});
        const Hit h = test::shootPov(s, from, d);
        ASSERT_TRUE(h.valid()) << i;
        const Vec3 p = from + h.t * d;
        EXPECT_NEAR(length(p), 1, 2e-4) << i;  // the grid's chords (POV-Ray's own hits lie 1-2.5% outside)
        EXPECT_GT(std::fabs(dot(h.normal, normalize(p))), 0.9999) << i;
    }
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
