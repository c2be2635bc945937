// POV-Ray's camera `normal { }`: camera rays tilted as surface normals by the pattern at the
// sample's screen point (u, v, 0), u and v in [−½, ½] (v up), along world axes. The expected
// places come from POV-Ray 3.7 renders (160×120, -A, 16-bit linear) of a camera at <0, 0, −5>
// looking at the origin (angle 40) through a sine-wave gradient normal, in front of a wall whose
// colour ramps with x (or y), against the same render without the normal: the wall point each
// pixel sees moved with the tilt. For `gradient x 0.2 sine_wave scale 1.3` it moved towards +x
// at column 26 and towards −x at column 27, and the other way at columns 130 and 131 (the slope
// of the wave is zero near u = ±0.325, the tetrahedron's samples place the zero a little to the
// left); for `gradient y 0.2 sine_wave scale 0.7 translate 0.13*y` it moved up at rows 23, 66 and
// 107 (from the top) and down at rows 24, 65 and 108. At the centre the first moved towards −x.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rays/render/renderer.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

constexpr int kW = 160, kH = 120;

Scene sceneWith(const std::string& normal) {
    return test::buildPov("camera { location <0, 0, -5> look_at <0, 0, 0> angle 40 normal { " + normal +
                          " } }\nplane { z, 0 pigment { rgb 1 } }\n");
}

// The tilt of the camera ray through pixel (x, y) (y from the top row): its direction minus the
// untilted one.
Vec3 tiltAt(const Scene& scene, double x, double y) {
    RenderSettings s;
    s.width = kW;
    s.height = kH;
    const ViewSetup view = resolveView(scene, s);
    const double px = x + 0.5, py = kH - 1 - y + 0.5;
    const Ray plain = view.rays.rayThrough(px, py, kW, kH);
    const Ray tilted = cameraRayAt(view, px, py, kW, kH);
    EXPECT_NEAR(length(tilted.dir), 1, 1e-12);
    return tilted.dir - plain.dir;
}

TEST(PovCameraNormal, TiltsAlongXWhereThePatternSlopesAcrossTheScreen) {
    const Scene scene = sceneWith("gradient x 0.2 sine_wave scale 1.3");
    ASSERT_EQ(scene.cameras.at(0).normal, 0);
    const Vec3 centre = tiltAt(scene, 79.5, 60);
    EXPECT_LT(centre.x, -0.01);  // towards −x, as POV-Ray's wall showed
    EXPECT_NEAR(centre.y, 0, 1e-4);  // only the renormalisation moves y
    // The tilt turns between the columns where POV-Ray's wall turned.
    EXPECT_GT(tiltAt(scene, 26, 60).x, 0);
    EXPECT_LT(tiltAt(scene, 27, 60).x, 0);
    EXPECT_LT(tiltAt(scene, 130, 60).x, 0);
    EXPECT_GT(tiltAt(scene, 131, 60).x, 0);
    EXPECT_GT(tiltAt(scene, 10, 60).x, 0);
    EXPECT_GT(tiltAt(scene, 150, 60).x, 0);
}

TEST(PovCameraNormal, ScreenVCountsUpAndTheWaveKeepsItsTranslation) {
    const Scene scene = sceneWith("gradient y 0.2 sine_wave scale 0.7 translate 0.13*y");
    EXPECT_GT(std::fabs(tiltAt(scene, 80, 44).y), 0.01);
    // The tilt turns between the rows where POV-Ray's wall turned.
    for (int row : {23, 107}) {
        EXPECT_GT(tiltAt(scene, 80, row).y, 0) << row;
        EXPECT_LT(tiltAt(scene, 80, row + 1).y, 0) << row;
    }
    EXPECT_LT(tiltAt(scene, 80, 65).y, 0);
    EXPECT_GT(tiltAt(scene, 80, 66).y, 0);
}

TEST(PovCameraNormal, CamerasWithoutOneKeepTheirRays) {
    const Scene scene = test::buildPov("camera { location <0, 0, -5> look_at 0 }\nsphere { 0, 1 }\n");
    EXPECT_EQ(scene.cameras.at(0).normal, -1);
    EXPECT_EQ(length(tiltAt(scene, 30, 40)), 0);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
