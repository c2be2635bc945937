// POV-Ray camera projections read from POV text: the ray of chosen pixels of a 101×101 image
// compared with POV-Ray 3.7.0.10's. The directions were measured by rendering a sphere around the
// camera whose colour is 0.5 + 0.5·(unit direction) (16-bit PPM, linear), the orthographic and
// cylinder 3/4 origins from a plane z = 10 coloured by the hit point
// (tests/data/povray/camera/measure_camera.py 'CAMERA BODY' 101 101 x,y ...).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/pov/load_pov.h"
#include "rays/render/sampler.h"
#include "rays/render/tracer.h"
#include "rays/scene/camera.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

constexpr int kSize = 101;
constexpr double kMeasured = 2e-4;  // 16-bit colour quantisation of the measurement

Camera loadCamera(const std::string& body) {
    ParseOptions o;
    o.language.installedIncludeDir.clear();
    const Scene s = pov::parsePovText("#version 3.7;\ncamera { " + body + " }\n", "scene.pov", ".", o);
    return s.cameras.at(0);
}

// The ray of pixel (x, y), y counted from the top row as in an image file.
Ray pixelRay(const std::string& body, int x, int y) {
    return CameraRays(loadCamera(body)).rayThrough(x + 0.5, kSize - 1 - y + 0.5, kSize, kSize);
}

void expectDir(const std::string& body, int x, int y, Vec3 want, double tol = kMeasured) {
    SCOPED_TRACE(body + " at " + std::to_string(x) + "," + std::to_string(y));
    const Ray r = pixelRay(body, x, y);
    EXPECT_NEAR(r.dir.x, want.x, tol);
    EXPECT_NEAR(r.dir.y, want.y, tol);
    EXPECT_NEAR(r.dir.z, want.z, tol);
}

// Where the pixel's ray meets the plane z = 10 (x, y).
void expectHit(const std::string& body, int x, int y, double hx, double hy, double tol = 2e-3) {
    SCOPED_TRACE(body + " at " + std::to_string(x) + "," + std::to_string(y));
    const Ray r = pixelRay(body, x, y);
    const Vec3 p = r.at((10 - r.origin.z) / r.dir.z);
    EXPECT_NEAR(p.x, hx, tol);
    EXPECT_NEAR(p.y, hy, tol);
}

TEST(PovCamera, AngleSetsTheDirectionFromTheFinalRightWhereverItIsWritten) {
    // Measured with POV-Ray 3.7 on a checker wall: `angle 35` before or after `right x*4/3`, before
    // or after `direction z*5`, and with `right x*2 up y*1.5` give the same image. Here a 90°
    // view 2 wide: the left column's ray meets z = 10 at x = −10·(1 − 1/101), the top row's at
    // y = 5·(1 − 1/101).
    for (const char* body : {"location 0 angle 90 right x*2 up y look_at z", "location 0 right x*2 up y angle 90 look_at z",
                             "location 0 angle 90 direction z*5 right x*2 up y look_at z",
                             "location 0 right x*2 up y direction z*5 look_at z angle 90"}) {
        expectHit(body, 0, 50, -9.900990, 0, 1e-6);
        expectHit(body, 50, 0, 0, 4.950495, 1e-6);
    }
}

TEST(PovCamera, OrthographicWindowFromRightAndUp) {
    // The window is right × up wherever the direction points and however long it is.
    expectHit("orthographic location 0 direction 3*z right 4*x up 3*y", 100, 50, 1.9803, 0);
    expectHit("orthographic location <1,2,0> right 4*x up 3*y", 0, 100, -0.9799, 0.5148);
    // Only right given: up keeps its default (y).
    expectHit("orthographic location 0 right 4*x look_at 5*z", 0, 0, -1.9803, 0.4953);
    const Ray r = pixelRay("orthographic location 0 right 4*x up 3*y look_at <1,0,1>", 30, 40);
    EXPECT_NEAR(r.dir.x, r.dir.z, 1e-12);  // parallel rays along the view direction
}

TEST(PovCamera, TransformationsApplyAfterEveryOtherItem) {
    // POV-Ray 3.7 moves the camera by its transformations after location, angle and look_at,
    // wherever they stand: povray renders `location L rotate R look_at P`, `location L look_at P
    // rotate R` and `rotate R location L look_at P` to identical images, and a shear before
    // look_at survives it (the image keeps its converging verticals).
    const std::string after = "location <0,1,-5> right x up y look_at <2,1,0> rotate y*30";
    for (const std::string before : {"location <0,1,-5> right x up y rotate y*30 look_at <2,1,0>",
                                     "rotate y*30 location <0,1,-5> right x up y look_at <2,1,0>"})
        for (const auto& [x, y] : {std::pair{0, 0}, std::pair{50, 50}, std::pair{100, 30}}) {
            const Ray a = pixelRay(before, x, y), b = pixelRay(after, x, y);
            EXPECT_NEAR(length(a.dir - b.dir), 0, 1e-12) << before;
            EXPECT_NEAR(length(a.origin - b.origin), 0, 1e-12) << before;
        }
    // The centre ray of the rotated camera no longer meets the look_at point (measured direction).
    expectDir("location <0,1,-5> rotate y*30 look_at <2,1,0>", 50, 50, {0.787, 0, 0.617}, 3e-3);
    // A shear in y then look_at: the rows of pixels keep the shear's tilt.
    const std::string sheared = "location <0,1,-5> right x up y matrix <1,0,0, 0,1,-0.4, 0,0,1, 0,0,0> look_at <0,1,0>";
    const Ray top = pixelRay(sheared, 50, 0), plain = pixelRay("location <0,1,-5> right x up y look_at <0,1,0>", 50, 0);
    EXPECT_GT(length(top.dir - plain.dir), 0.05);
}

TEST(PovCamera, LookAtMirrorsUnlessUpCrossDirectionPointsAlongRight) {
    // look_at keeps POV-Ray's left-handed frame only when (up × direction)·right > 0; with up along
    // the direction (0) or a negative product the image is mirrored (measured at the left edge; the
    // tolerance covers this measurement's offset of perspective rays, ~0.007, far below the 0.6
    // between the two sides).
    const Vec3 plain{0.19686, -0.51543, 0.83401}, mirrored{0.83401, -0.51543, 0.19686};
    constexpr double kSide = 0.01;
    expectDir("location <-10,10,-10> right x up y look_at 0", 0, 50, plain, kSide);
    expectDir("location <-10,10,-10> right x up z look_at 0", 0, 50, mirrored, kSide);
    expectDir("location <-10,10,-10> right -x up z look_at 0", 0, 50, mirrored, kSide);
    expectDir("location <-10,10,-10> right x up -y look_at 0", 0, 50, mirrored, kSide);
}

TEST(PovCamera, LookingAlongTheSkyKeepsTheRightVectorAsWritten) {
    // Measured with POV-Ray 3.7 looking straight down from <2.5, 10, 0> (it warns that the
    // look_at direction and sky should differ and keeps the right vector): with the default
    // vectors +z is up and +x right; `right -x*4/3` shows −z up and +x right; `up z right x`
    // (left- or right-handed undecided, as a mirrored camera) +z up and −x right.
    auto axes = [](const std::string& vectors, Vec3 wantRight, Vec3 wantUp) {
        SCOPED_TRACE(vectors);
        const std::string body = "location <2.5, 10, 0> look_at <2.5, 0, 0> " + vectors;
        const Vec3 centre = normalize(pixelRay(body, 50, 50).dir);
        const Vec3 towardsRight = normalize(pixelRay(body, 100, 50).dir) - centre;
        const Vec3 towardsTop = normalize(pixelRay(body, 50, 0).dir) - centre;
        EXPECT_GT(dot(towardsRight, wantRight), 0.9 * length(towardsRight));
        EXPECT_GT(dot(towardsTop, wantUp), 0.9 * length(towardsTop));
    };
    axes("", {1, 0, 0}, {0, 0, 1});
    axes("right -x*4/3", {1, 0, 0}, {0, 0, -1});
    axes("up z right x", {-1, 0, 0}, {0, 0, 1});
    axes("right -x up z", {1, 0, 0}, {0, 0, -1});
}

TEST(PovCamera, LookAtComesLastFromVersion35AndInOrderBefore) {
    // Measured with POV-Ray 3.7 (a sphere at the look_at point and one above the origin): under
    // #version 3.5 and later `direction`, `location`, `right` and `sky` written after look_at give
    // the image of the same items written before it; under 3.1 (3.49 too) they apply in order,
    // so a direction written after look_at turns the camera away from the point.
    auto centre = [](const std::string& version, const std::string& body) {
        ParseOptions o;
        o.language.installedIncludeDir.clear();
        const Scene s = pov::parsePovText("#version " + version + ";\ncamera { " + body + " }\n", "scene.pov", ".", o);
        return CameraRays(s.cameras.at(0)).rayThrough(50.5, 50.5, kSize, kSize);
    };
    auto expectTowards = [](const Ray& r, Vec3 p) {
        const Vec3 want = normalize(p - r.origin), got = normalize(r.dir);
        EXPECT_NEAR(length(got - want), 0, 1e-9);
    };
    for (const char* v : {"3.5", "3.7"}) {
        SCOPED_TRACE(v);
        expectTowards(centre(v, "location <0,0,-10> look_at <5,0,0> direction z"), {5, 0, 0});
        expectTowards(centre(v, "location <0,0,-10> look_at <5,0,0> location <0,0,-20>"), {5, 0, 0});
        EXPECT_NEAR(centre(v, "location <0,0,-10> look_at <5,0,0> location <0,0,-20>").origin.z, -20, 1e-12);
    }
    // A sky written after look_at rolls the view as one written before it (a corner pixel).
    const Ray late = CameraRays(loadCamera("location <0,0,-10> look_at <5,0,0> sky x")).rayThrough(10.5, 90.5, kSize, kSize);
    const Ray early = CameraRays(loadCamera("location <0,0,-10> sky x look_at <5,0,0>")).rayThrough(10.5, 90.5, kSize, kSize);
    EXPECT_NEAR(length(late.dir - early.dir), 0, 1e-12);
    // Before 3.5: in order. The direction after look_at points the camera along +z again, the
    // location after it moves the camera without turning it.
    EXPECT_NEAR(length(normalize(centre("3.1", "location <0,0,-10> look_at <5,0,0> direction z").dir) - Vec3{0, 0, 1}), 0, 1e-12);
    expectTowards(centre("3.49", "location <0,0,-10> look_at <5,0,0> location <0,0,-20>"), {5, 0, -10});
}

TEST(PovCamera, OrthographicWindowOfThePerspectiveView) {
    // No right or up: the perspective camera's view at the look_at point (right·dist/|direction|).
    expectHit("orthographic location 0 look_at 5*z", 100, 50, 3.2920, 0);
    expectHit("orthographic location 0 look_at 5*z", 50, 0, 0, 2.4753);
    expectHit("orthographic location 0 direction 2*z look_at 5*z", 100, 50, 1.6458, 0);
    // Without look_at the point is <0,0,1>, wherever the camera is.
    expectHit("orthographic location -10*z direction 2*z", 100, 50, 3.6216, 0);
    expectHit("orthographic location -10*z direction 2*z", 50, 0, 0, 2.7225);
    // angle: 2·dist·tan(angle/2) wide, up's aspect kept; in any order with look_at.
    expectHit("orthographic location 0 right 4*x up 3*y look_at 5*z angle 90", 100, 50, 4.9503, 0);
    expectHit("orthographic location 0 right 4*x up 3*y look_at 5*z angle 90", 50, 0, 0, 3.7131);
    expectHit("orthographic location <0,0,-10> angle 90 look_at <0,0,-7>", 100, 50, 2.9703, 0);
    // angle without a value: the perspective view with the vectors as given.
    expectHit("orthographic location 0 right 4*x up 3*y look_at 5*z angle", 100, 50, 9.9010, 0);
    expectHit("orthographic location 0 right 4*x up 3*y look_at 5*z angle", 50, 0, 0, 7.4260);
}

TEST(PovCamera, Fisheye) {
    expectDir("fisheye location 0 direction z right x up y angle 180", 100, 50, {0.99988, 0, 0.01555});
    expectDir("fisheye location 0 direction z right x up y angle 180", 85, 15, {0.70675, 0.70675, 0.03117});
    expectDir("fisheye location 0 direction z right x up y angle 360", 85, 15, {0.04408, 0.04408, -0.99805});
    expectDir("fisheye location 0 direction z right x up y", 85, 15, {0.49215, 0.49215, 0.71804});  // 90°
    // A wider right squeezes the circle horizontally (a circle on a 4:3 image with right 4/3).
    expectDir("fisheye location 0 direction 3*z right 2*x up y angle 180", 75, 50, {0.99988, 0, 0.01555});
    // Outside the circle: no ray (POV-Ray writes black there, not the background).
    EXPECT_TRUE(CameraRays::missed(pixelRay("fisheye location 0 direction z right x up y angle 180", 90, 10)));
    EXPECT_TRUE(CameraRays::missed(pixelRay("fisheye location 0 direction 3*z right 2*x up y", 100, 50)));
    EXPECT_FALSE(CameraRays::missed(pixelRay("fisheye location 0 direction 3*z right 2*x up y", 50, 0)));
}

TEST(PovCamera, UltraWideAngle) {
    expectDir("ultra_wide_angle location 0 direction z right x up y angle 180", 85, 15, {0.69693, 0.69693, 0.16912});
    expectDir("ultra_wide_angle location 0 direction z right x up y angle 180", 0, 0, {-0.70712, 0.70712, 0.00017});
    expectDir("ultra_wide_angle location 0 direction z right 2*x up y angle 180", 85, 15, {0.80529, 0.47066, 0.36052});
    expectDir("ultra_wide_angle location 0 direction z right x up y", 0, 0, {-0.62945, 0.62945, 0.45559});
}

TEST(PovCamera, Omnimax) {
    // Square: a 180° fisheye with a measured radial curve, cut below the dome's rim.
    const std::string square = "omnimax location 0 direction z right x up y";
    expectDir(square, 75, 50, {0.64025, 0, 0.76815});
    expectDir(square, 100, 50, {0.99979, 0, 0.02083});
    expectDir(square, 50, 70, {0, -0.52743, 0.84961});
    expectDir(square, 80, 65, {0.72381, -0.36190, 0.58749});
    expectDir(square, 30, 62, {-0.51751, -0.31051, 0.79736});
    EXPECT_TRUE(CameraRays::missed(pixelRay(square, 50, 80)));
    EXPECT_TRUE(CameraRays::missed(pixelRay(square, 80, 78)));  // inside the circle, below the rim
    // Wider than high: the frame from 45° below the horizon to the zenith.
    const std::string wide = "omnimax location 0 direction z right 1.33*x up y";
    expectDir(wide, 50, 50, {0, 0.30584, 0.95209});
    expectDir(wide, 75, 50, {0.64968, 0.27971, 0.70687});
    expectDir(wide, 50, 100, {0, -0.69918, 0.71496});
    expectDir(wide, 20, 20, {-0.65872, 0.73159, 0.17577});
    EXPECT_TRUE(CameraRays::missed(pixelRay(wide, 100, 50)));
    // Higher than wide: the circle stretched vertically.
    const std::string tall = "omnimax location 0 direction 2*z right 0.75*x up y";
    expectDir(tall, 75, 30, {0.58871, 0.62795, 0.50906});
    expectDir(tall, 60, 70, {0.25032, -0.66751, 0.70126});
    expectDir(tall, 90, 50, {0.91318, 0, 0.40758});
}

TEST(PovCamera, Panoramic) {
    expectDir("panoramic location 0 direction z right x up y", 85, 15, {0.41082, 0.88602, 0.21498});
    expectDir("panoramic location 0 direction z right 2*x up y", 85, 15, {0.66946, 0.72192, 0.17516});
    expectDir("panoramic location 0 direction z right 2*x up y", 75, 50, {0.89160, 0, 0.45278});
    expectDir("panoramic location 0 right x up y look_at <-1,0,1>", 20, 70, {-0.80380, -0.58273, -0.11965});
}

TEST(PovCamera, Cylinders) {
    expectDir("cylinder 1 location 0 direction z right 2*x up 3*y angle 180", 85, 15, {0.61422, 0.72070, 0.32143});
    expectDir("cylinder 1 location 0 direction 2*z right x up y angle 180", 0, 0, {-0.89609, 0.44366, 0.01393});
    expectDir("cylinder 1 location 0 direction z right x up y", 0, 0, {-0.62875, 0.44366, 0.63861});
    expectDir("cylinder 2 location 0 direction z right 2*x up 3*y angle 180", 85, 15, {0.56963, 0.72821, 0.38109});
    expectDir("cylinder 2 location 0 direction 2*z right 2*x up 3*y", 0, 0, {-0.70358, 0.49856, 0.50637});
    // Types 3 and 4 move the viewpoint along up (right).
    expectHit("cylinder 3 location 0 direction z right 2*x up 3*y angle 180", 75, 0, 9.8454, 1.4853, 0.01);
    expectHit("cylinder 3 location 0 direction z right 2*x up 3*y angle 180", 85, 15, 19.1089, 1.0397, 0.01);
    expectHit("cylinder 4 location 0 direction z right 2*x up 3*y angle 180", 75, 40, 0.4953, 3.2151, 0.01);
    expectHit("cylinder 4 location 0 direction z right 2*x up 3*y angle 180", 10, 60, -0.7919, -3.2151, 0.01);
    expectHit("cylinder 4 location 0 direction z right 2*x up 3*y angle 180", 85, 15, 0.6931, 19.1089, 0.01);
}

TEST(PovCamera, Spherical) {
    expectDir("spherical location 0 direction z right 2*x up 3*y angle 180 90", 85, 15, {0.75796, 0.51785, 0.39666});
    expectDir("spherical location 0 direction z right x up y angle 180", 85, 15, {0.75796, 0.51785, 0.39666});
    expectDir("spherical location 0 direction z right x up y", 85, 15, {0.38094, 0.88602, -0.26430});  // 360 × 180
    expectDir("spherical location 0 angle 180 look_at <1,0.5,1>", 85, 15, {0.67834, 0.62045, -0.39358});
    expectDir("spherical location 0 angle 180 look_at <1,0.5,1>", 20, 70, {-0.09093, -0.09963, 0.99088});
}

// ---- no_image, no_reflection ----------------------------------------------------------------
// A red ambient sphere (modifiers as given) in front of a white floor lit head-on, seen along the
// camera ray through (x, y) from z = −3 (POV-Ray: camera { orthographic location -3*z look_at 0
// right 4*x up 4*y }, 4×4 pixels; measured colours: 0, 1 or the blue background exactly).
Vec3 seenThrough(const std::string& sphereModifiers, const std::string& more, double x, double y) {
    ParseOptions o;
    o.language.installedIncludeDir.clear();
    const Scene s = pov::parsePovText("#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                                      "background { rgb <0,0,1> }\n"
                                      "light_source { <0,0,-100>, rgb 1 }\n"
                                      "plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
                                      "sphere { <0,0,-1.5>, 1 pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } " +
                                          sphereModifiers + " }\n" + more,
                                      "scene.pov", ".", o);
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    return Tracer(s, bvh, rs).tracePrimary(Ray{{x, y, -3}, {0, 0, 1}}, ctx);
}

void expectSeen(Vec3 got, Vec3 want) {
    EXPECT_NEAR(got.x, want.x, 1e-3);
    EXPECT_NEAR(got.y, want.y, 1e-3);
    EXPECT_NEAR(got.z, want.z, 1e-3);
}

const Vec3 kRed{1, 0, 0}, kBlack{0, 0, 0}, kBlue{0, 0, 1};
// A mirror just in front of the floor, and a clear pane in front of the sphere.
const std::string kMirror = "plane { -z, 0.1 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }\n";
const std::string kPane = "box { <-2,-2,-2.8>, <2,2,-2.7> pigment { rgb 1 transmit 1 } finish { ambient 0 diffuse 0 } }\n";

TEST(PovVisibility, NoImageHidesFromCameraRaysButCastsShadows) {
    expectSeen(seenThrough("", "", -0.5, 0.5), kRed);
    expectSeen(seenThrough("no_image", "", -0.5, 0.5), kBlack);  // the floor in its shadow
    expectSeen(seenThrough("no_image", kPane, -0.5, 0.5), kBlack);  // nor through a clear pane
    expectSeen(seenThrough("no_image off", "", -0.5, 0.5), kRed);
}

TEST(PovVisibility, NoImageShowsInReflections) {
    expectSeen(seenThrough("no_image", kMirror, -0.5, 0.5), kRed);
    expectSeen(seenThrough("no_image no_reflection", kMirror, -0.5, 0.5), kBlue);
    expectSeen(seenThrough("no_image", kMirror, -1.5, 1.5), kBlue);
}

TEST(PovVisibility, NoReflectionHidesFromReflectedRaysOnly) {
    expectSeen(seenThrough("no_reflection", "", -0.5, 0.5), kRed);
    expectSeen(seenThrough("no_reflection", kMirror + kPane, -0.5, 0.5), kRed);
    // Seen only in the mirror (the camera ray passes it), then hidden from the reflection too.
    expectSeen(seenThrough("no_image no_reflection", kMirror, -0.5, 0.5), kBlue);
}

TEST(PovVisibility, FlagsHoldForTheObjectsInside) {
    const std::string greenUnion = "union { sphere { <-0.5,0.5,-0.4>, 0.2 } sphere { <3,3,3>, 0.1 } "
                                   "pigment { rgb <0,1,0> } finish { ambient 1 diffuse 0 } no_image }\n";
    expectSeen(seenThrough("no_image", greenUnion, -0.5, 0.5), kBlack);
    expectSeen(seenThrough("no_image", greenUnion + kMirror, -0.5, 0.5), Vec3(0, 1, 0));
}

// ---- double_illuminate, crand -----------------------------------------------------------------

Scene loadScene(const std::string& body) {
    ParseOptions o;
    o.language.installedIncludeDir.clear();
    return pov::parsePovText("#version 3.7;\nglobal_settings { assumed_gamma 1 }\n" + body, "scene.pov", ".", o);
}

TEST(PovVisibility, DoubleIlluminateLightsTheBackSide) {
    // A plane facing the camera lit from behind (measured 0.9565 at that pixel with
    // double_illuminate, black without; the second diffuse value makes no difference then).
    const std::string plane = "light_source { <30,0,100>, rgb 1 }\nplane { -z, 0 pigment { rgb 1 } ";
    for (const char* finish : {"finish { ambient 0 diffuse 1 } ", "finish { ambient 0 diffuse 1, 0.5 } "}) {
        const Scene lit = loadScene(plane + finish + "double_illuminate }\n");
        const Bvh bvh(lit.objects);
        const RenderSettings rs;
        TraceContext ctx;
        EXPECT_NEAR(Tracer(lit, bvh, rs).tracePrimary(Ray{{-0.5, 0.5, -3}, {0, 0, 1}}, ctx).x, 0.9565, 1e-3);
    }
    const Scene dark = loadScene(plane + "finish { ambient 0 diffuse 1 } }\n");
    const Bvh bvh(dark.objects);
    const RenderSettings rs;
    TraceContext ctx;
    EXPECT_EQ(Tracer(dark, bvh, rs).tracePrimary(Ray{{-0.5, 0.5, -3}, {0, 0, 1}}, ctx), Vec3{});
}

// The colours of a lit white plane (ambient 0.3) seen by the samples of n pixels.
std::vector<Vec3> grainSamples(const std::string& lights, const std::string& finish, int n) {
    const Scene s = loadScene(lights + "plane { -z, 0 pigment { rgb 1 } finish { ambient 0.3 diffuse 1 " + finish + " } }\n");
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    const Tracer tracer(s, bvh, rs);
    std::vector<Vec3> out;
    TraceContext ctx;
    for (int i = 0; i < n; ++i) {
        ctx.rng = SampleRng(uint32_t(i % 37), uint32_t(i / 37), 0, 1);
        out.push_back(tracer.tracePrimary(Ray{{0, 0, -3}, {0, 0, 1}}, ctx));
    }
    return out;
}

void meanAndDeviation(const std::vector<Vec3>& v, double& mean, double& sd) {
    mean = sd = 0;
    for (Vec3 c : v) mean += c.x;
    mean /= double(v.size());
    for (Vec3 c : v) sd += (c.x - mean) * (c.x - mean);
    sd = std::sqrt(sd / double(v.size()));
}

TEST(PovCrand, DarkensEachLightsDiffuseTermUniformly) {
    // POV-Ray (100×100 pixels of a plane lit head-on): ambient + diffuse·(1 − crand·U), U uniform
    // in [0, 1), the same U for the three channels: crand 0.2 gives [1.1, 1.3), sd 0.2/√12.
    const std::vector<Vec3> v = grainSamples("light_source { <0,0,-100>, rgb 1 }\n", "crand 0.2", 4000);
    double lo = 10, hi = -10, mean, sd;
    for (Vec3 c : v) {
        lo = std::min(lo, c.x), hi = std::max(hi, c.x);
        EXPECT_EQ(c.x, c.y);
        EXPECT_EQ(c.x, c.z);
    }
    meanAndDeviation(v, mean, sd);
    EXPECT_GE(lo, 1.1 - 1e-9);
    EXPECT_LE(hi, 1.3);
    EXPECT_LT(lo, 1.105);
    EXPECT_GT(hi, 1.295);
    EXPECT_NEAR(mean, 1.2, 0.005);
    EXPECT_NEAR(sd, 0.2 / std::sqrt(12.0), 0.003);
}

TEST(PovCrand, OneDrawPerLightAndNoneWithoutLight) {
    // Two lights of 0.5, crand 0.5: the two draws add (a triangular spread, sd 0.25/√12·√2;
    // measured 0.1011 over 10000 pixels).
    const std::vector<Vec3> two =
        grainSamples("light_source { <0,0,-100>, rgb 0.5 }\nlight_source { <0,0,-100>, rgb 0.5 }\n", "crand 0.5", 4000);
    double mean, sd;
    meanAndDeviation(two, mean, sd);
    EXPECT_NEAR(mean, 0.3 + 0.75, 0.005);
    EXPECT_NEAR(sd, 0.25 / std::sqrt(6.0), 0.004);
    // Ambient alone is left as it is.
    for (Vec3 c : grainSamples("", "crand 0.5", 50)) EXPECT_EQ(c, Vec3(0.3));
}

TEST(PovCrand, SameSampleSameGrain) {
    const std::vector<Vec3> a = grainSamples("light_source { <0,0,-100>, rgb 1 }\n", "crand 0.2", 20);
    const std::vector<Vec3> b = grainSamples("light_source { <0,0,-100>, rgb 1 }\n", "crand 0.2", 20);
    EXPECT_EQ(a, b);
    EXPECT_NE(a[0], a[1]);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
