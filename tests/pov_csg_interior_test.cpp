// Interiors of CSG children and of open objects along viewing and shadow rays, as POV-Ray 3.7
// fades them (measured with povray 3.7.0.10 on advanced/wineglass.pov's parts: a merge of glass
// parts with fade distances from 0.025 to 3.25, and a quadric cone clipped to a slab standing on
// the floor).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rays/accel/bvh.h"
#include "rays/render/tracer.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

Scene load(const std::string& body) {
    return test::loadPov(body, "#version 3.7;\nglobal_settings { assumed_gamma 1 max_trace_level 10 }\n").scene;
}

Vec3 trace(const Scene& s, const Ray& ray) {
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    return Tracer(s, bvh, rs).tracePrimary(ray, ctx);
}

const std::string kClear = "texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } }";

std::string sphere(double x, double fadeDistance) {
    return "sphere { <" + std::to_string(x) + ", 0, 0>, 1 " + kClear + " interior { fade_distance " +
           std::to_string(fadeDistance) + " fade_power 1 } }";
}

// A ray through one child of a CSG fades by that child's interior, not by another child's (the
// wine glass lying on its side came out black: its rim's fade_distance 0.025 faded the bowl).
TEST(PovCsgInterior, EachChildFadesByItsOwnInterior) {
    const std::string background = "background { rgb 1 }\n";
    const Ray through{{3, 0.2, -5}, {0, 0, 1}};  // through the sphere at x = 3 only
    const Vec3 alone = trace(load(background + sphere(3, 2)), through);
    EXPECT_LT(alone.x, 0.9);  // it fades
    for (const char* csg : {"union", "merge"}) {
        const Scene s = load(background + csg + " { " + sphere(-3, 0.01) + " " + sphere(3, 2) + " }");
        const Vec3 got = trace(s, through);
        EXPECT_NEAR(got.x, alone.x, 1e-9) << csg;
        EXPECT_NEAR(got.z, alone.z, 1e-9) << csg;
    }
}

// Where a stretch inside glass fades: at its end, on a surface the ray leaves, by that surface's
// interior (measured with POV-Ray 3.7, 16-bit linear output: boxes A = <-1,-1,-1>–<1,1,0> of
// fade_distance 1 and B = <-1,-1,-0.5>–<1,1,2> of fade_distance 10, fade_power 1, ior 1, seen along
// +z and along −z). Along +z through their union the stretch ending where the ray enters B does not
// fade, the overlap fades by A (left at its end) and the rest by B: 1/(1 + 0.5)·1/(1 + 2/10) =
// 0.5556; along −z 1/(1 + 0.5/10)·1/(1 + 0.5) = 0.6349. Through their merge or intersection the ray
// goes in through one box and out through the other's surface, and nothing fades (1.0000 each way).
TEST(PovCsgInterior, AStretchFadesByTheInteriorLeftAtItsEnd) {
    const std::string boxes = "box { <-1,-1,-1>, <1,1,0> " + kClear + " interior { fade_distance 1 fade_power 1 } }\n" +
                              "box { <-1,-1,-0.5>, <1,1,2> " + kClear + " interior { fade_distance 10 fade_power 1 } }\n";
    const Ray forward{{0.1, 0.2, -5}, {0, 0, 1}}, back{{0.1, 0.2, 5}, {0, 0, -1}};
    const Scene u = load("background { rgb 1 }\nunion { " + boxes + " }");
    EXPECT_NEAR(trace(u, forward).y, 1 / 1.5 / 1.2, 1e-3);  // each stretch starts 0.001 past its surface
    EXPECT_NEAR(trace(u, back).y, 1 / 1.05 / 1.5, 1e-3);
    for (const char* csg : {"merge", "intersection"}) {
        const Scene s = load(std::string("background { rgb 1 }\n") + csg + " { " + boxes + " }");
        EXPECT_NEAR(trace(s, forward).y, 1, 1e-9) << csg;
        EXPECT_NEAR(trace(s, back).y, 1, 1e-9) << csg;
    }
}

// The camera inside a fading object: its ray fades where it leaves it (measured with POV-Ray 3.7:
// the camera at the centre of a clear sphere of radius 2, fade_distance 1, fade_power 1, ior 1, a
// white background: 0.3333 = 1/(1 + 2)).
TEST(PovCsgInterior, ACameraInsideAFadingObjectIsFadedWhereItsRayLeaves) {
    const Scene s = load("camera { location 0 look_at z }\nbackground { rgb 1 }\nsphere { 0, 2 " + kClear +
                         " interior { fade_distance 1 fade_power 1 } }\n");
    EXPECT_NEAR(trace(s, Ray{{0, 0, 0}, {0, 0, 1}}).y, 1.0 / 3, 1e-9);
}

// Shadow rays fade by the same rule (measured with POV-Ray 3.7: the same two boxes between a white
// wall at z = −5 and a light at z = 10, the wall's brightness against that without them: union
// 0.5556, merge and intersection 1.0000; with the fade distances swapped, union 0.3175).
TEST(PovCsgInterior, ShadowRaysFadeByTheInteriorLeftAtTheEndOfEachStretch) {
    auto boxes = [](double fa, double fb) {
        return "box { <-1,-1,-1>, <1,1,0> " + kClear + " interior { fade_distance " + std::to_string(fa) +
               " fade_power 1 } }\nbox { <-1,-1,-0.5>, <1,1,2> " + kClear + " interior { fade_distance " +
               std::to_string(fb) + " fade_power 1 } }\n";
    };
    const std::string lit = "light_source { <0.1, 0.2, 10> rgb 1 }\nplane { z, -5 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n";
    const Vec3 from{6, 0.2, 3};  // looking at the wall point (0.1, 0.2, −5) past the boxes
    const Ray view{from, normalize(Vec3{0.1, 0.2, -5} - from)};
    const double bare = trace(load(lit), view).y;
    ASSERT_GT(bare, 0.01);
    auto seen = [&](const std::string& csg, double fa, double fb) { return trace(load(lit + csg + " { " + boxes(fa, fb) + " }"), view).y / bare; };
    EXPECT_NEAR(seen("union", 1, 10), 1 / 1.5 / 1.2, 1e-3);  // 0.5556
    EXPECT_NEAR(seen("union", 10, 1), 1 / 1.05 / 3.0, 1e-3);  // 0.3175
    EXPECT_NEAR(seen("merge", 1, 10), 1, 1e-9);
    EXPECT_NEAR(seen("intersection", 1, 10), 1, 1e-9);
}

// Children with interior blocks of their own stay apart even when the blocks and textures read
// alike (measured with POV-Ray 3.7: a clear box −1..1 minus a clear sphere of radius 0.6, each with
// `interior { fade_distance 1 fade_power 2 }`, crossed through the centre: 0.3538, the sphere's
// inside fading by 1/(1 + 1.2²) and the last stretch of the box by 1/(1 + 0.4²); had they been one
// interior, the two stretches of the box would fade and the cavity not: 0.7431).
TEST(PovCsgInterior, ChildrenWithInteriorsOfTheirOwnStayApartWhenAlike) {
    const std::string fade = " interior { fade_distance 1 fade_power 2 }";
    const Scene s = load("background { rgb 1 }\ndifference { box { -1, 1 " + kClear + fade + " } sphere { 0, 0.6 " + kClear +
                         fade + " } }\n");
    EXPECT_NEAR(trace(s, Ray{{0, 0, -5}, {0, 0, 1}}).y, 0.3538, 2e-3);
}

// Whether a ray goes into an interior or out of it is decided by the objects it is inside, not by
// the side of the surface it meets (measured with POV-Ray 3.7: a flat glass height field of ior 1.2
// under a mirroring scale, whose solid lies above its surface and whose open top the ray crosses
// without a hit, seen from above at 76° from its normal: the ray is refracted into it and meets the
// blue floor, where leaving the glass would reflect it totally, towards the red background).
TEST(PovCsgInterior, OpenObjectsAreEnteredWhereTheRayIsNotInsideThem) {
    const std::string field = "height_field { function 16, 16 { 0 } translate <-0.5, 0, -0.5> scale <12, -0.5, 12> "
                              "pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.2 } }\n";
    const Scene s = load("background { rgb <1, 0, 0> }\n"
                         "plane { y, -1 pigment { rgb <0, 0, 1> } finish { ambient 1 diffuse 0 } }\n" + field);
    const Vec3 dir = Vec3{0, -1, 4} / length(Vec3{0, -1, 4});
    const Vec3 got = trace(s, Ray{{0, 1, -4}, dir});
    EXPECT_NEAR(got.x, 0, 1e-9);
    EXPECT_NEAR(got.z, 1, 1e-9);
    // A closed glass met from inside at that angle still reflects totally.
    const Scene closed = load("background { rgb <1, 0, 0> }\n"
                              "box { <-6, -0.5, -6>, <6, 0.5, 6> pigment { rgbf 1 } finish { ambient 0 diffuse 0 } "
                              "interior { ior 1.2 } }\n");
    const Vec3 up = Vec3{0, 1, 4} / length(Vec3{0, 1, 4});
    EXPECT_NEAR(trace(closed, Ray{{0, 0.25, -5}, up}).x, 1, 1e-9);  // the camera (at 0) is inside it too
}

// A ray that touches a surface exactly tangentially does not go into it (measured with POV-Ray 3.7:
// interior/atten1.pov's orthographic rays along the rims of its fading spheres are not faded).
TEST(PovCsgInterior, ATangentRayDoesNotGoIn) {
    const Scene s = load("background { rgb 1 }\n" + sphere(0, 0.5));
    const Vec3 got = trace(s, Ray{{0, 1, -5}, {0, 0, 1}});  // along the top of the sphere
    EXPECT_NEAR(got.x, 1, 1e-9);
}

// A shadow ray that leaves a fading surface it was not inside (a cone clipped to a slab, over the
// floor its infinite surface encloses) is not faded (rays from inside a closed fading object still
// fade from their start: PovShading.LightInsideAFadingInteriorIsDividedByTheViewingRaysFade).
TEST(PovCsgInterior, ShadowRaysLeavingAnOpenObjectTheyWereNotInDoNotFade) {
    const std::string light = "light_source { <0, 100, 0> rgb 1 }\n";
    const std::string floor = "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n";
    // Seen low from the side, below the cone's wall (which starts at y = 0.5).
    const Ray low{{5, 0.1, 0.05}, Vec3{-4.95, -0.1, 0} / length(Vec3{-4.95, -0.1, 0})};
    const Vec3 bare = trace(load(light + floor), low);
    ASSERT_GT(bare.x, 0.5);
    // The cone x² + z² = (y − 1)² between y = 0.5 and 1 (open), its infinite surface round the
    // floor point; the shadow ray meets only its wall, leaving it.
    const std::string cone = "quadric { <1, -1, 1>, <0, 0, 0>, <0, 2, 0>, -1 clipped_by { plane { y, 1 } "
                             "plane { -y, -0.5 } } " + kClear + " interior { fade_distance 0.1 fade_power 1 } }\n";
    const Vec3 underCone = trace(load(light + floor + cone), low);
    EXPECT_NEAR(underCone.x, bare.x, 1e-9);
}

// A ray refracts by the ratio of the indices on the two sides of a surface: the interior it is in
// (the one entered last; air when none) and the one it enters, or the one it leaves and the one it
// is then in. POV-Ray 3.7's directions (measured: an orthographic ray, 16-bit renders of a sky
// coloured by direction, one channel at a time) for half-spaces y < 0 of ior 1.5 and y < −1 of ior
// 1.2 (or 1, or cut out of the glass by a difference), crossed from above at 40° and from below at
// 20°: after parallel surfaces sin θ = sin θ₀·n₀/n, whatever lies between.
TEST(PovCsgInterior, RaysRefractByTheIndicesOnBothSides) {
    const std::string clear = " pigment { rgbt 1 } finish { ambient 0 diffuse 0 } ";
    const std::string sky = "sky_sphere { pigment { average pigment_map {\n"
                            "  [1 function { (y + 1) / 2 } color_map { [0 rgb 0] [1 rgb <0, 2, 0>] }]\n"
                            "  [1 function { (z + 1) / 2 } color_map { [0 rgb 0] [1 rgb <0, 0, 2>] }] } } }\n";
    const std::string glass = "plane { y, 0" + clear + "interior { ior 1.5 } }\n";
    auto leaving = [&](const std::string& objects, Vec3 from, double degrees, bool up) {
        const double a = degrees * 3.14159265358979323846 / 180;
        const Vec3 d{0, up ? std::cos(a) : -std::cos(a), std::sin(a)};
        return 2.0 * trace(load(sky + objects), Ray{from, d}) - Vec3(1.0);
    };
    const std::string inner12 = "plane { y, -1" + clear + "interior { ior 1.2 } }";
    const std::string inner1 = "plane { y, -1" + clear + "}";
    const Vec3 above{0, 1, 0}, below{0, -5, 0};
    EXPECT_NEAR(leaving(glass + inner12, above, 40, false).z, 0.5357, 2e-3);  // sin 40°/1.2
    EXPECT_NEAR(leaving(glass + inner1, above, 40, false).z, 0.6428, 2e-3);   // sin 40°
    EXPECT_NEAR(leaving("difference { " + glass + inner1 + " }", above, 40, false).z, 0.6428, 2e-3);
    EXPECT_NEAR(leaving("difference { " + glass + inner12 + " }", above, 40, false).z, 0.5357, 2e-3);
    const std::string camera = "camera { location <0, -5, 0> look_at <0, -4, 0> }\n";  // inside both
    EXPECT_NEAR(leaving(camera + glass + inner12, below, 20, true).z, 0.4104, 2e-3);  // 1.2·sin 20°
    EXPECT_NEAR(leaving(camera + glass + inner1, below, 20, true).z, 0.3420, 2e-3);   // sin 20°
}

// A glass standing on a floor: its bottom and the floor's top meet a ray at distances that differ
// by rounding only. POV-Ray 3.7 shows the floor through the bottom wherever the ray comes down
// (measured: a glass box on a checkered plane seen from above); the ray leaving the glass must not
// start past the floor and see what lies beyond it (here the magenta background).
TEST(PovCsgInterior, AGlassOnAFloorShowsTheFloorThroughItsBottom) {
    for (const char* ior : {"1", "1.5"}) {
        const Scene s = load(std::string("background { rgb <1, 0, 1> }\n"
                                         "plane { y, 0 pigment { rgb 0.5 } finish { ambient 1 diffuse 0 } }\n"
                                         "box { <-1, 0, -1>, <1, 1, 1> pigment { rgbf 1 } finish { ambient 0 diffuse 0 } "
                                         "interior { ior ") + ior + " } }\n");
        int background = 0;
        for (int i = 0; i < 200; ++i) {
            const Vec3 from{0.37 * std::sin(1.7 * i), 3, -0.41 * std::cos(2.3 * i)};
            const Vec3 dir = normalize(Vec3{0.11 * std::cos(0.9 * i), -1, 0.13 * std::sin(1.1 * i)});
            background += trace(s, Ray{from, dir}).y < 0.25;
        }
        EXPECT_EQ(background, 0) << "ior " << ior;
    }
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
