// The slope pattern (pattern/slope, pov/pigment_compile): values measured with POV-Ray 3.7.0.10 on
// an orthographic view of a unit sphere with `finish { ambient 1 diffuse 0 }` and a black-to-white
// colour map, read from 16-bit output at File_Gamma 1 (normals and points of those pixels below).
#include <gtest/gtest.h>

#include <string>

#include "rays/accel/bvh.h"
#include "rays/render/renderer.h"
#include "rays/render/tracer.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

struct Sample {
    Vec3 p;  // the point on the unit sphere, also its normal
    double value;
};

// Measured pixels: normals (0, 0.489, −0.872), (0, −0.880, −0.475), (−0.684, 0.293, −0.667), (0, 0, −1).
void expectSlope(const std::string& body, std::initializer_list<Sample> samples) {
    const test::PovLoaded b = test::loadPov("sphere { 0, 1 pigment { " + body +
                                            " color_map { [0 rgb 0] [1 rgb 1] } } }");
    EXPECT_TRUE(b.warnings.empty()) << body;
    const PovSurface& s = b.scene.povSurfaces.at(size_t(b.scene.objects.at(0).material.pov));
    ASSERT_GE(s.pigment, 0) << body;
    for (const Sample& x : samples)
        EXPECT_NEAR(b.scene.pigments.atRoot(s.pigment, x.p, normalize(x.p)).rgb.x, x.value, 2e-3)
            << body << " at " << x.p.x << " " << x.p.y << " " << x.p.z;
}

const Vec3 kUp{0, 0.489, -0.872}, kDown{0, -0.880, -0.475}, kSide{-0.684, 0.293, -0.667}, kFront{0, 0, -1};

TEST(PovSlope, SlopeIsTheAngleToTheDirection) {
    // 1 − angle/π: 1 along the direction, 0.5 across, 0 against; the direction's length is dropped.
    expectSlope("slope { <0, 1, 0> }", {{kUp, 0.6626}, {kDown, 0.1575}, {kSide, 0.5948}, {kFront, 0.5}});
    expectSlope("slope y*3", {{kUp, 0.6626}, {kDown, 0.1575}});
    // Lo_slope, Hi_slope rescale without clamping; the ramp wave wraps what falls below 0.
    expectSlope("slope { <0, 1, 0>, 0.5, 1.0 }", {{kUp, 0.3252}, {kDown, 0.3151}, {kSide, 0.1895}, {kFront, 0}});
}

TEST(PovSlope, AltitudeIsWeighedByTheVectorsLengths) {
    expectSlope("slope { <0, 2, 0> altitude <0, 1, 0>, -1, 1 }", {{kUp, 0.6899}, {kDown, 0.1250}, {kSide, 0.6121}});
    expectSlope("slope { <0, 1, 0> altitude <0, 1, 0> }", {{kUp, 0.5757}, {kDown, 0.6388}, {kSide, 0.4441}, {kFront, 0.25}});
    expectSlope("slope { <0, 1, 0> altitude <0, 2, 0> }", {{kUp, 0.5468}, {kDown, 0.4658}, {kFront, 0.1667}});
    // The pattern's transformations move the point (the altitude) but not the direction.
    expectSlope("slope { <0, 1, 0> altitude <0, 1, 0>, -1, 1 } scale 2", {{kUp, 0.6424}, {kDown, 0.2188}});
    expectSlope("slope { <0, 1, 0> } rotate z*90", {{kUp, 0.6626}, {kDown, 0.1575}});
}

// The colour the POV-Ray tracer sees along a ray.
Vec3 traceColor(const Scene& s, const Ray& ray) {
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    return Tracer(s, bvh, rs).tracePrimary(ray, ctx, nullptr, nullptr);
}

TEST(PovSlope, TexturePatternChoosesByTheNormalFacingTheViewer) {
    // A slope texture map on a plane: from above the normal runs along y (value 1: the second
    // texture), from below it faces down (value 0: the first), as POV-Ray 3.7 draws it.
    std::vector<std::string> warnings;
    const Scene s = test::buildPov(
        "plane { y, 0 texture { slope { y } texture_map {\n"
        "  [0 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 }]\n"
        "  [1 pigment { rgb <0, 0, 1> } finish { ambient 1 diffuse 0 }] } } }",
        &warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_NEAR(length(traceColor(s, Ray{{0, 5, 0}, {0, -1, 0}}) - Vec3{0, 0, 1}), 0, 1e-9);
    EXPECT_NEAR(length(traceColor(s, Ray{{0, -5, 0}, {0, 1, 0}}) - Vec3{1, 0, 0}), 0, 1e-9);
}

TEST(PovSlope, APigmentSlopeReadsTheTiltedNormal) {
    // With a normal pattern the slope follows the tilted normal (measured: bumps make it noisy).
    const Scene flat = test::buildPov(
        "plane { y, 0 pigment { slope { x } color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 diffuse 0 } }");
    const Scene bumpy = test::buildPov(
        "plane { y, 0 pigment { slope { x } color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 diffuse 0 }\n"
        "  normal { bumps 3 scale 0.05 } }");
    int differ = 0;
    for (int i = 0; i < 20; ++i) {
        const Ray r{{0.137 * i, 5, 0.071 * i}, {0, -1, 0}};
        EXPECT_NEAR(traceColor(flat, r).x, 0.5, 1e-9);
        differ += std::fabs(traceColor(bumpy, r).x - 0.5) > 0.02;
    }
    EXPECT_GT(differ, 10);
}

TEST(PovSlope, AsANormalPatternItIsNoted) {
    std::vector<std::string> warnings;
    test::buildPov("sphere { 0, 1 normal { slope { y } } }", &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("normal pattern slope"), std::string::npos);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
