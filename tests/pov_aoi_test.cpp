// The aoi pattern (angle of incidence, pattern/pattern.cpp): values measured with POV-Ray 3.7.0.10
// at 16 bits and File_Gamma 1 with `global_settings { assumed_gamma 1 }`, `finish { ambient 1
// diffuse 0 }` and a black-to-white colour map: an orthographic view of a unit sphere along +z,
// planes turned 30° about y seen from either side, and a plane tilted by a gradient normal.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rays/accel/bvh.h"
#include "rays/render/renderer.h"
#include "rays/render/tracer.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

constexpr char kHead[] = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n";
constexpr char kAoi[] = "pigment { aoi color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 diffuse 0 }";

double seen(const Scene& s, const Ray& ray) {
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    return Tracer(s, bvh, rs).tracePrimary(ray, ctx, nullptr, nullptr).x;
}

TEST(PovAoi, IsOneMinusTheAngleToTheViewerOverPi) {
    const test::PovLoaded l = test::loadPov(std::string("sphere { 0, 1 ") + kAoi + " }", kHead);
    EXPECT_TRUE(l.warnings.empty());
    // povray at x = 0.105, 0.505, 0.905 on the row through the centre.
    const double measured[3][2] = {{0.105, 0.96648}, {0.505, 0.83148}, {0.905, 0.63986}};
    for (const auto& [x, v] : measured) EXPECT_NEAR(seen(l.scene, Ray{{x, 0, -5}, {0, 0, 1}}), v, 5e-4) << x;
}

TEST(PovAoi, AFaceSeenFromEitherSideReadsTheNormalFacingTheViewer) {
    for (const char* normal : {"z", "-z"}) {  // povray: 0.83334 (1 − 30/180) both ways
        const test::PovLoaded l =
            test::loadPov(std::string("plane { ") + normal + ", 0 " + kAoi + " rotate y*30 }", kHead);
        EXPECT_NEAR(seen(l.scene, Ray{{0.1, 0.1, -5}, {0, 0, 1}}), 0.83334, 5e-4) << normal;
    }
}

TEST(PovAoi, ReadsTheTiltedNormalAndIsZeroOffSurfaces) {
    // A gradient x 1 normal tilts by atan(2/15): povray 0.95781.
    const test::PovLoaded l = test::loadPov(
        "plane { -z, 0 texture { pigment { aoi color_map { [0 rgb 0] [1 rgb 1] } } normal { gradient x 1 }\n"
        "  finish { ambient 1 diffuse 0 } } }",
        kHead);
    EXPECT_NEAR(seen(l.scene, Ray{{0.3, 0.2, -5}, {0, 0, 1}}), 0.95781, 5e-4);
    // As a pattern function (no surface, no ray) povray gives 0.
    const test::PovLoaded f = test::loadPov(std::string("sphere { 0, 1 ") + kAoi + " }", kHead);
    const PovSurface& s = f.scene.povSurfaces.at(size_t(f.scene.objects.at(0).material.pov));
    EXPECT_EQ(f.scene.pigments.atRoot(s.pigment, {0.3, 0.2, 0.1}).rgb.x, 0.0);
    // And between a normal and a direction, directly: 60° from the viewer gives 1 − 60/180.
    const Vec3 d = normalize(Vec3{std::sqrt(3.0), 0, 1});
    EXPECT_NEAR(f.scene.pigments.atRoot(s.pigment, {0.3, 0.2, 0.1}, {0, 0, -1}, nullptr, d).rgb.x, 2.0 / 3, 1e-12);
}

TEST(PovAoi, AsANormalPatternItIsNoted) {
    std::vector<std::string> warnings;
    test::buildPov("sphere { 0, 1 normal { aoi } }", &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("normal pattern aoi"), std::string::npos);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
