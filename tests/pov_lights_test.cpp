// POV-Ray lights and atmosphere read from POV text and traced: no_shadow, shadowless lights,
// spotlights, cylindrical lights, light fading, fog, looks_like. The expected values were measured
// with povray 3.7.0.10 (16-bit PPM, sRGB decoded, assumed_gamma 1: the scenes as written here,
// tests/data/povray/shading/measure_lights.py); they hold to 1e-4 unless a test says otherwise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/error.h"
#include "rays/pov/load_pov.h"
#include "support/pov_scene.h"
#include "rays/render/tracer.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

constexpr double kMeasured = 1e-4;  // povray's 16-bit output, decoded

using Loaded = test::PovLoaded;

Loaded load(const std::string& body) {
    return test::loadPov(body, "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n");
}

// The working-space colour seen along the ray of an orthographic camera at z = −3 looking along +z
// through (x, y) (POV-Ray's `camera { orthographic location -3*z look_at 0 ... }`).
Vec3 seen(const Scene& s, double x, double y, double z = -3) {
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    return Tracer(s, bvh, rs).tracePrimary(Ray{{x, y, z}, {0, 0, 1}}, ctx);
}

void expectColor(Vec3 got, Vec3 want, double tol = kMeasured) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

// A white floor facing the camera lit by diffuse 1 only.
const std::string kFloor = "plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n";
// A point light far off at 60° from the floor's normal, and a thin box beside the view on its way.
const std::string kLight60 = "light_source { <0.866025,0,-0.5>*100, rgb 1 }\n";
std::string sideBox(const std::string& pigment, const std::string& modifiers) {
    return "box { <1,-5,-1.01>, <5,5,-1> pigment { " + pigment + " } finish { ambient 0 diffuse 0 } " + modifiers +
           " }\n";
}

// Centre pixel of povray's 4×4 render of that camera (right x, up y).
constexpr double kCx = 0.125, kCy = -0.125;

// POV-Ray weighs an area light's samples by halving each axis's index range again and again (an
// odd number of samples sharing its middle one, an even number split into disjoint halves), the
// parts alike, down to single cells whose corners average; with `adaptive A` a part at depth A or
// deeper whose corners agree is taken whole. povray 3.7 (16-bit linear): a wall z = 0 lit by an
// unjittered N × N light 2 units wide at z = −4 past the edge of a black slab (x < 0 at z = −1;
// the wall is looked at where x ≥ 0, beside the slab), and past a thin pole (|x| < 0.03 at
// z = −2, no_image) in front of a 9 × 9 light.
TEST(PovAreaLight, SamplesWeighAsPovRaysSubdivisionWeighsThem) {
    auto wall = [](int n, const std::string& light, const std::string& occluder, double x) {
        const Loaded l = load("light_source { <0,0,-4> rgb 1 area_light <2,0,0>, <0,2,0>, " + std::to_string(n) + ", " +
                              std::to_string(n) + " " + light + " }\n"
                              "plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n" + occluder);
        return seen(l.scene, x, 0.005, -10).x;
    };
    const std::string edge = "box { <-10,-10,-1.01>, <0,10,-1> pigment { rgb 0 } }\n";
    // x = 0.035, 0.135 and 0.275: 3, 4 and 5 of N = 5 or 6 columns lit, 2, 3 and 3 of N = 4.
    EXPECT_NEAR(wall(4, "", edge, 0.035), 0.5, kMeasured);
    EXPECT_NEAR(wall(4, "", edge, 0.135), 0.7496, kMeasured);
    EXPECT_NEAR(wall(5, "", edge, 0.035), 0.625, kMeasured);  // the trapezoid rule (plain mean: 0.6)
    EXPECT_NEAR(wall(5, "", edge, 0.275), 0.8729, kMeasured);
    EXPECT_NEAR(wall(6, "", edge, 0.035), 0.5, kMeasured);
    EXPECT_NEAR(wall(6, "", edge, 0.135), 0.6246, kMeasured);
    EXPECT_NEAR(wall(6, "", edge, 0.275), 0.8729, kMeasured);
    const std::string pole = "box { <-0.03,-10,-2.01>, <0.03,10,-2> pigment { rgb 0 } no_image }\n";
    EXPECT_NEAR(wall(9, "", pole, -0.815), 0.8574, kMeasured);
    EXPECT_NEAR(wall(9, "adaptive 0", pole, 0.005), 1.0, kMeasured);  // the four corners are lit
    EXPECT_NEAR(wall(9, "adaptive 1", pole, 0.005), 0.875, kMeasured);
    EXPECT_NEAR(wall(9, "adaptive 1", pole, -0.565), 0.9902, kMeasured);
    EXPECT_NEAR(wall(9, "adaptive 2", pole, -0.565), 0.8664, kMeasured);
}

// area_illumination: povray 3.7 (16-bit linear), a white sphere (diffuse 1) at <1,0.4,0> of
// radius 0.4 under a 4 × 4 area light at <0,1,0>, seen by an orthographic camera along +z: the
// plain mean of the samples' own diffuse, unshadowed, times the share of the light arriving, in
// which a sample behind the surface is blocked (weighed as above).
TEST(PovAreaLight, AreaIlluminationShadesEachSampleFromItsOwnPlace) {
    auto front = [](const std::string& grid, double x) {
        const Loaded l = load("light_source { <0,1,0> rgb 1 area_light <4,0,0>, <0,0,4>, " + grid +
                              " area_illumination on }\n"
                              "sphere { <1,0.4,0>, 0.4 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n");
        return seen(l.scene, x, 0.395, -5).x;
    };
    constexpr double k8bit = 2e-3;  // measured on 8-bit-precise points of the 16-bit image
    EXPECT_NEAR(front("5, 5", 1.005), 0.0843, k8bit);
    EXPECT_NEAR(front("5, 5", 0.605), 0.2519, k8bit);
    EXPECT_NEAR(front("1, 2", 1.005), 0.1991, k8bit);  // one sample in front: its diffuse / 2, times 1/2
    EXPECT_NEAR(front("2, 2", 1.005), 0.1576, k8bit);
    EXPECT_NEAR(front("3, 3", 1.005), 0.0571, k8bit);  // one column in front: weight 1/4
    EXPECT_NEAR(front("3, 3", 0.605), 0.3087, k8bit);
    // Without it the light shades from its centre, behind this point's surface: dark.
    const Loaded off = load("light_source { <0,1,0> rgb 1 area_light <4,0,0>, <0,0,4>, 5, 5 }\n"
                            "sphere { <1,0.4,0>, 0.4 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n");
    EXPECT_NEAR(seen(off.scene, 1.005, 0.395, -5).x, 0.0, 1e-9);
}

TEST(PovNoShadow, ObjectsWithNoShadowCastNone) {
    for (const char* pigment : {"rgb <.5,.6,.7>", "rgbf <.5,.6,.7,.5>", "rgbt <.5,.6,.7,.5>"}) {
        SCOPED_TRACE(pigment);
        // Measured: 0, .03129/.04505/.06131, .12513 with shadows; .50054 with no_shadow.
        const Loaded plain = load(kLight60 + kFloor + sideBox(pigment, ""));
        EXPECT_LT(seen(plain.scene, kCx, kCy).x, 0.2);
        const Loaded ns = load(kLight60 + kFloor + sideBox(pigment, "no_shadow"));
        EXPECT_TRUE(ns.warnings.empty()) << ns.warnings[0];
        expectColor(seen(ns.scene, kCx, kCy), Vec3(0.50054));
    }
}

TEST(PovNoShadow, HoldsForAUnionsChildrenAndTheObjectIsStillSeen) {
    // Measured .50054 under a union { box sphere no_shadow }.
    const Loaded u = load(kLight60 + kFloor + "union { box { <1,-5,-1.01>, <5,5,-1> } sphere { <3,0,-5>, 0.1 }" +
                          " pigment { rgb 1 } no_shadow }");
    expectColor(seen(u.scene, kCx, kCy), Vec3(0.50054));
    // The box itself: ambient .1 of its white and the light at 60°·0.6 diffuse (its face −z).
    const Vec3 box = seen(u.scene, 2, 0);
    EXPECT_GT(box.x, 0.3);
}

// The floor lit head-on through a wall that hides it from the light: pigment <.5,.6,.7>, diffuse .5.
const std::string kLitFloor = "plane { -z, 0 pigment { rgb <.5,.6,.7> } finish { ambient 0 diffuse 0.5 %s } }\n";
std::string litFloor(const std::string& finish) {
    std::string s = kLitFloor;
    return s.replace(s.find("%s"), 2, finish);
}
TEST(PovShadowless, LightsWithoutHighlights) {
    // Measured: .25 .3 .35 in all three cases; a plain light with phong 1 gives 1 1 1.
    const std::string light = "light_source { <0,0,-100>, rgb 1 shadowless }\n";
    expectColor(seen(load(light + litFloor("")).scene, kCx, kCy), {0.25, 0.3, 0.35});
    expectColor(seen(load(light + litFloor("phong 1")).scene, kCx, kCy), {0.25, 0.3, 0.35});
    expectColor(seen(load(light + litFloor("specular 1")).scene, kCx, kCy), {0.25, 0.3, 0.35});
    const std::string plain = "light_source { <0,0,-100>, rgb 1 }\n";
    EXPECT_GT(seen(load(plain + litFloor("phong 1")).scene, kCx, kCy).x, 0.9);
}

TEST(PovShadowless, NothingBlocksTheLight) {
    // Measured: a shadowless light behind an opaque wall (no_image) lights the floor as if the
    // wall were not there; here the box beside the view, as in PovNoShadow (.50054 unblocked).
    const std::string light = "light_source { <0.866025,0,-0.5>*100, rgb 1 shadowless }\n";
    expectColor(seen(load(light + kFloor + sideBox("rgb 1", "")).scene, kCx, kCy), Vec3(0.50054));
    EXPECT_EQ(seen(load(kLight60 + kFloor + sideBox("rgb 1", "")).scene, kCx, kCy), Vec3{});
}

struct Sample {
    double x, value;  // a floor point (x, 0.015625) and the red channel povray gave there
};

void expectFloor(const std::string& light, const std::vector<Sample>& samples) {
    const Loaded l = load(kFloor + "light_source { " + light + " }\n");
    EXPECT_TRUE(l.warnings.empty()) << l.warnings[0];
    for (const Sample& s : samples) EXPECT_NEAR(seen(l.scene, s.x, 0.015625).x, s.value, kMeasured) << "x " << s.x;
}

TEST(PovSpotlight, RadiusFalloffAndTightnessShapeTheCone) {
    // The floor 1 below the light: full light within 10°, the curve between 10° and 30°, none beyond.
    expectFloor("<0,0,-1>, rgb 1 spotlight point_at 0 radius 10 falloff 30",
                {{0.07812, 0.99684}, {0.26562, 0.90378}, {0.32812, 0.75365}, {0.39062, 0.53532},
                 {0.45312, 0.29025}, {0.51562, 0.08491}, {0.64062, 0}});
    expectFloor("<0,0,-1>, rgb 1 spotlight point_at 0 radius 10 falloff 40 tightness 10",
                {{0.07812, 0.96581}, {0.26562, 0.67264}, {0.39062, 0.38883}, {0.51562, 0.16135},
                 {0.64062, 0.04186}, {0.76562, 0.00353}, {0.82812, 0.00006}});
    // The defaults: radius 30, falloff 45.
    expectFloor("<0,0,-1>, rgb 1 spotlight point_at 0",
                {{0.07812, 0.99684}, {0.51562, 0.88873}, {0.64062, 0.78988}, {0.70312, 0.63877},
                 {0.76562, 0.45210}, {0.82812, 0.26734}});
}

TEST(PovSpotlight, NegativeAnglesActAsTheirSize) {
    // Light at <0,0,-10> pointed 60° away from the centre pixel (kFloor of diffuse 1). Measured:
    // radius -90 falloff 90 and radius -60 falloff 90 light it fully (.99983); radius 10 falloff
    // -80 as falloff 80: .37452.
    const std::string at = "<0,0,-10>, rgb 1 spotlight tightness 0 point_at <17.32,0,0> ";
    EXPECT_NEAR(seen(load(kFloor + "light_source { " + at + "radius -90 falloff 90 }\n").scene, kCx, kCy).x, 0.99983, kMeasured);
    EXPECT_NEAR(seen(load(kFloor + "light_source { " + at + "radius -60 falloff 90 }\n").scene, kCx, kCy).x, 0.99983, kMeasured);
    EXPECT_NEAR(seen(load(kFloor + "light_source { " + at + "radius 10 falloff -80 }\n").scene, kCx, kCy).x, 0.37452, kMeasured);
}

TEST(PovLights, ADeclaredLightTakesTheModifiersWrittenAfterIt) {
    // `light_source { SP translate <1,0,0> }` with SP faded (fade_distance 4, power 2) 10 in front:
    // measured .27295 (moved), .27574 where it was.
    const Loaded l = load(kFloor + "#declare SP = light_source { <0,0,-10>, rgb 1 fade_power 2 fade_distance 4 }\n" +
                          "light_source { SP translate <1,0,0> }\n");
    ASSERT_EQ(l.scene.lights.size(), 1u);
    EXPECT_NEAR(seen(l.scene, kCx, kCy).x, 0.27295, kMeasured);
}

TEST(PovLights, ALightInASurfacesPlaneLightsWhatItFaces) {
    // A light in the plane of a ceiling 54.88 above a floor: shadow rays aimed at it from their
    // offset origin, not along the direction from the point, which would meet the ceiling first.
    // Measured on the floor: .29464 (fade_distance 30, power 2).
    const Loaded l = load("light_source { <27.8,54.88,27.95> color 1 fade_power 2 fade_distance 30 }\n"
                          "plane { y, 0 pigment { rgb 1 } finish { diffuse .75 ambient 0 } }\n"
                          "plane { -y, -54.88 pigment { rgb 1 } finish { diffuse .75 ambient 0 } }\n");
    const Bvh bvh(l.scene.objects);
    const RenderSettings rs;
    TraceContext ctx;
    const Vec3 c = Tracer(l.scene, bvh, rs).tracePrimary(Ray{{12, 20, 40}, {0, -1, 0}}, ctx);
    EXPECT_NEAR(c.x, 0.29464, 2e-3);
}

TEST(PovSpotlight, CylindricalLightsShineAlongTheirAxisWithinADistance) {
    // radius and falloff are distances from the axis; N·L is the axis's (1 on this floor).
    expectFloor("<0,0,-1>, rgb 1 cylinder point_at 0 radius 0.3 falloff 0.6",
                {{0.07812, 1}, {0.26562, 1}, {0.32812, 0.97464}, {0.39062, 0.78005}, {0.45312, 0.48304},
                 {0.51562, 0.19185}, {0.64062, 0}});
}

TEST(PovSpotlight, CylindricalLightsTightnessSharpensWithTheDistanceFromTheAxis) {
    // Measured (x, red) along the strip: (1 − r/falloff)^tightness times the curve.
    expectFloor("<0,0,-1>, rgb 1 cylinder point_at 0 radius 0.3 falloff 0.6 tightness 3",
                {{0.07812, 0.65219}, {0.20312, 0.28809}, {0.32812, 0.09030}, {0.45312, 0.00705}, {0.64062, 0}});
}

TEST(PovSpotlight, CylindricalLightsCastShadowsAlongTheAxis) {
    // A strip at x 0.1..0.2, 1 in front of the floor, light 2 in front: povray's floor is dark at
    // x .11 .14 .17 and lit at .2 and beyond (a point light shades .2 to .39).
    const Loaded l = load(kFloor + "box { <0.1,-1,-1.01>, <0.2,1,-1> pigment { rgb 1 } no_image }\n" +
                          "light_source { <0,0,-2>, rgb 1 cylinder point_at 0 radius 0.9 falloff 1 }\n");
    // Looked at from between the strip and the floor (Rays has no no_image yet).
    EXPECT_NEAR(seen(l.scene, 0.14, 0.015625, -0.5).x, 0, 1e-9);
    EXPECT_NEAR(seen(l.scene, 0.3, 0.015625, -0.5).x, 1, kMeasured);
}

TEST(PovLightFading, TwoOverOnePlusDistanceOverFadeDistanceToThePower) {
    expectFloor("<0,0,-2>, rgb 1 fade_distance 1 fade_power 2",
                {{0.07812, 0.39917}, {0.39062, 0.38093}, {0.64062, 0.35202}, {0.82812, 0.32498}});
    expectFloor("<0,0,-2>, rgb 1 fade_distance 0.5 fade_power 1",
                {{0.07812, 0.39943}, {0.39062, 0.38671}, {0.82812, 0.34672}});
}

// A wall of pigment <.5,.6,.7> at z = 0 lit by its ambient 1 alone: 3 from the camera.
const std::string kWallAmbient = "plane { -z, 0 pigment { rgb <.5,.6,.7> } finish { ambient 1 diffuse 0 } }\n";

TEST(PovFog, ConstantFogMixesByDistanceWithFilterAndTransmit) {
    struct Case {
        const char* color;
        Vec3 wall, background;
    } cases[] = {{"rgb <.2,.4,.8>", {0.26693, 0.44462, 0.77768}, {0.2, 0.4, 0.8}},
                 {"rgbf <.2,.4,.8,.5>", {0.22232, 0.40447, 0.76206}, {0.2, 0.4, 0.8}},
                 {"rgbt <.2,.4,.8,.3>", {0.29, 0.46, 0.77}, {0.44, 0.43, 0.63501}},
                 {"rgbft <.2,.4,.8,.5,.3>", {0.23, 0.40601, 0.74901}, {0.31999, 0.385, 0.6275}},
                 {"rgbt <.2,.4,.8,.1>", {0.26693, 0.44462, 0.77768}, {0.28, 0.41, 0.745}}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.color);
        const std::string fog = std::string("fog { distance 2 color ") + c.color + " }\n";
        const Loaded l = load(kWallAmbient + fog);
        EXPECT_TRUE(l.warnings.empty()) << l.warnings[0];
        expectColor(seen(l.scene, kCx, kCy), c.wall);
        expectColor(seen(load("background { rgb <1,.5,.25> }\n" + fog).scene, kCx, kCy), c.background);
    }
}

TEST(PovFog, SeveralFogsMultiplyTheirSharesAndAddTheirColours) {
    const Loaded l =
        load(kWallAmbient + "fog { distance 2 color rgb <.2,.4,.8> } fog { distance 4 color rgb <1,0,0> }");
    expectColor(seen(l.scene, kCx, kCy), {0.73570, 0.37399, 0.69527});
}

TEST(PovFog, ReflectedRaysGoThroughFogToo) {
    // A mirror at z = 0 facing the camera sees the wall behind it at z = −4: 3 + 4 in fog.
    const Loaded l = load("plane { -z, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }\n"
                          "plane { z, -4 pigment { rgb <.5,.6,.7> } finish { ambient 1 diffuse 0 } }\n"
                          "fog { distance 2 color rgb <.2,.4,.8> }");
    expectColor(seen(l.scene, kCx, kCy), {0.20905, 0.40605, 0.79697});
}

TEST(PovFog, FillsHollowObjectsOnly) {
    // A clear box across the view from z = −2 to −1: the fog is left out inside it unless it is
    // hollow (POV-Ray 3.7's 16-bit pixels; screen.inc's screen plane is hollow for this).
    const std::string fog = kWallAmbient + "fog { distance 2 color rgb <.2,.4,.8> }\n";
    const std::string box = "box { <-5,-5,-2>, <5,5,-1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } ";
    expectColor(seen(load(fog + box + "hollow }").scene, kCx, kCy), {0.26694, 0.44463, 0.77769});
    expectColor(seen(load(fog + box + "}").scene, kCx, kCy), {0.31037, 0.47358, 0.76321});
}

TEST(PovFog, GroundFogThinsAboveItsOffset) {
    // Horizontal rays at height −.125: the density is 1/(1 + ((h − offset)/alt)²) there.
    struct Level {
        double offset, alt;
        Vec3 want;
    } levels[] = {{-1.125, 1, {0.34171, 0.49447, 0.75277}},
                  {-0.625, 0.5, {0.34171, 0.49447, 0.75277}},
                  {0, 1, {0.26693, 0.44462, 0.77768}},
                  {-3.125, 0.5, {0.48809, 0.59205, 0.70398}}};
    for (const Level& v : levels) {
        const Loaded l = load(kWallAmbient + "fog { fog_type 2 fog_offset " + std::to_string(v.offset) + " fog_alt " +
                              std::to_string(v.alt) + " distance 2 color rgb <.2,.4,.8> }");
        expectColor(seen(l.scene, kCx, kCy), v.want);
    }
    // up x, or the fog turned so that its up is x: heights along x (0.125).
    for (const char* turn : {"up x", "rotate -90*z"}) {
        const Loaded l = load(kWallAmbient + "fog { fog_type 2 fog_offset 0 fog_alt 1 " + turn +
                              " distance 2 color rgb <.2,.4,.8> }");
        expectColor(seen(l.scene, kCx, kCy), {0.26849, 0.44568, 0.77717});
    }
}

TEST(PovFog, GroundFogIntegratesTheDensityAlongASlantedRay) {
    // The ray from <0,3,-3> to the floor y = 0 at the origin (povray: a 1×1 orthographic render).
    struct Level {
        double offset, alt;
        Vec3 want;
    } levels[] = {{0, 1, {0.32404, 0.48270, 0.75866}},
                  {1, 1, {0.26761, 0.44507, 0.77747}},
                  {1, 0.5, {0.29257, 0.46170, 0.76913}},
                  {-1, 2, {0.32076, 0.48050, 0.75976}}};
    for (const Level& v : levels) {
        const Loaded l = load("plane { y, 0 pigment { rgb <.5,.6,.7> } finish { ambient 1 diffuse 0 } }\n"
                              "fog { fog_type 2 fog_offset " + std::to_string(v.offset) + " fog_alt " +
                              std::to_string(v.alt) + " distance 2 color rgb <.2,.4,.8> }");
        const Bvh bvh(l.scene.objects);
        const RenderSettings rs;
        TraceContext ctx;
        const Vec3 got = Tracer(l.scene, bvh, rs).tracePrimary(Ray{{0, 3, -3}, normalize(Vec3{0, -3, 3})}, ctx);
        expectColor(got, v.want);
    }
}

// The fog's optical depth over a black wall 10 away seen through x, y (fog colour 1), divided by
// the depth without turbulence (t/distance, or the ground fog's integral: `plain`).
struct FogDepths {
    double mean = 0, min = 1e9, max = -1e9;
};
FogDepths fogDepthRatios(const std::string& fog, double plain) {
    const Loaded l = load("plane { -z, -7 pigment { rgb 0 } finish { ambient 0 diffuse 0 } }\n" + fog);
    EXPECT_TRUE(l.warnings.empty()) << l.warnings[0];
    FogDepths d;
    const int n = 20;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double k = -std::log(1 - seen(l.scene, -10 + i, -0.5 - 0.35 * j).x) / plain;
            d.mean += k / (n * n), d.min = std::min(d.min, k), d.max = std::max(d.max, k);
        }
    return d;
}

TEST(PovFog, TurbulenceThinsTheFogByTheMeasuredRule) {
    // Measured with POV-Ray 3.7 (constant fog 10 deep, distance 10): the depth is multiplied by
    // 1 − c·e^−1, c = min(1, turb_depth·T); over a wall POV-Ray's ratios spread 0.65–0.98 with mean
    // 0.815 at turb_depth 0.5, mean 0.963 at 0.1, and sit at 1 − e^−1 where c reaches 1.
    const FogDepths half = fogDepthRatios("fog { distance 10 color rgb 1 turbulence 1 }", 1);
    EXPECT_NEAR(half.mean, 0.815, 0.05);
    EXPECT_GT(half.max - half.min, 0.1);  // the fog varies from ray to ray
    EXPECT_GE(half.min, 1 - std::exp(-1.0) - 1e-9);
    EXPECT_LT(half.max, 1);
    EXPECT_NEAR(fogDepthRatios("fog { distance 10 color rgb 1 turbulence 1 turb_depth 0.1 }", 1).mean, 0.963, 0.01);
    const FogDepths full = fogDepthRatios("fog { distance 10 color rgb 1 turbulence 1 turb_depth 1 omega 0.8 }", 1);
    EXPECT_NEAR(full.min, 1 - std::exp(-1.0), 1e-9);
    // A ground fog (density 1 below its offset) thins by the same factor, its exponential still
    // the constant fog's e^(−10/distance).
    const FogDepths ground =
        fogDepthRatios("fog { fog_type 2 fog_offset 100 fog_alt 1 distance 10 color rgb 1 turbulence 1 }", 1);
    EXPECT_NEAR(ground.mean, half.mean, 1e-9);
    // The background (nothing hit) is not changed.
    const Loaded bg = load("fog { distance 2 color rgb <.2,.4,.8> turbulence 0.5 }");
    expectColor(seen(bg.scene, kCx, kCy), {0.2, 0.4, 0.8});
}

// A light with media_attenuation on is dimmed by the fogs on its way, by exp(−d/distance) of a
// constant or ground fog (transmit a floor under it, filter tinting it once), without adding the
// fog's colour; other lights are not. povray 3.7, a white plane at z = 0 (ambient 0, diffuse 1)
// seen from z = −0.001 with `fog { ... distance 80 }`:
TEST(PovFog, LightsWithMediaAttenuationAreDimmedByTheFog) {
    struct Case {
        const char *light, *fog;
        double want;
    } cases[] = {{"<0,0,-80>, rgb 1", "color rgb 0.5", 1.0},
                 {"<0,0,-80>, rgb 1 media_attenuation on", "color rgb 0.5", 0.36788},
                 {"<0,0,-160>, rgb 1 media_attenuation on", "color rgb 0.5", 0.13533},
                 {"<0,0,-80>, rgb 1 media_attenuation on", "color rgbt <0.5,0.5,0.5,0.5>", 0.5},
                 {"<0,0,-40>, rgb 1 media_attenuation on", "color rgbt <0.5,0.5,0.5,0.5>", 0.60653},
                 {"<0,0,-80>, rgb 1 media_attenuation on", "color rgbft <0.5,0.5,0.5,0.5,0.5>", 0.28125},
                 {"<0,0,-80>, rgb 1 media_attenuation on", "color rgbf <1,1,1,1>", 0.36788},
                 {"<0,60,-60>, rgb 1 media_attenuation on", "color rgb 0.5", 0.24482},
                 {"<0,60,-60>, rgb 1 media_attenuation on", "fog_type 2 fog_offset 10 fog_alt 5 color rgb 0.5", 0.52029},
                 {"<0,60,-60>, rgb 1", "fog_type 2 fog_offset 10 fog_alt 5 color rgb 0.5", 0.7071}};
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(c.light) + " / " + c.fog);
        const Loaded l = load(std::string("light_source { ") + c.light + " }\nfog { " + c.fog +
                              " distance 80 }\nplane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n");
        expectColor(seen(l.scene, 0, 0, -0.001), Vec3(c.want));
    }
    // The filter's tint is the fog's colour, channel by channel.
    const Loaded tinted = load("light_source { <0,0,-80>, rgb 1 media_attenuation on }\n"
                               "fog { color rgbf <1,0.5,0,1> distance 80 }\n"
                               "plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n");
    expectColor(seen(tinted.scene, 0, 0, -0.001), {0.36788, 0.09198, 0});
}

TEST(PovFog, DistanceZeroIsNoFog) {
    // Measured: distance 0 leaves the wall as it is.
    expectColor(seen(load(kWallAmbient + "fog { distance 0 color rgb 1 }").scene, kCx, kCy), {0.5, 0.6, 0.7});
}

// The white floor z = 0 lit along +z by a parallel light of 0.01 through a clear pane tilted by
// `degrees` about y, with the pane's interior caustics `power`.
double floorThroughPane(double degrees, double power, const std::string& normal = "", double x = 0.125) {
    const Loaded l = load(kFloor + "light_source { <0,0,-100>, rgb 0.01 parallel point_at 0 }\n" +
                          "box { <-50,-50,-1.2>, <50,50,-1.1> rotate y*" + std::to_string(degrees) +
                          " pigment { rgbt <1,1,1,1> } finish { ambient 0 diffuse 0 } interior { caustics " +
                          std::to_string(power) + " } " + normal + " }\n");
    EXPECT_TRUE(l.warnings.empty()) << l.warnings[0];
    return seen(l.scene, x, 0.125).x;
}

TEST(PovCaustics, LightThroughAClearPaneBrightensNearItsNormal) {
    // Measured with povray 3.7 (a pane of two faces): ×4 along the normal whatever the power,
    // ×2.243 at 10° and power 1, ×2.92 at 5° and power 2, nothing left at 30°.
    EXPECT_NEAR(floorThroughPane(0, 0), 0.01, 1e-9);
    EXPECT_NEAR(floorThroughPane(0, 1) / 0.01, 4, 1e-6);
    EXPECT_NEAR(floorThroughPane(0, 0.25) / 0.01, 4, 1e-6);
    EXPECT_NEAR(floorThroughPane(10, 1) / 0.01, 2.243, 0.02);
    EXPECT_NEAR(floorThroughPane(5, 2) / 0.01, 2.93, 0.02);
    EXPECT_NEAR(floorThroughPane(30, 1) / 0.01, 1.0, 0.01);
    // The pane's normal pattern tilts the normal the light is compared with (povray's
    // interior/caustic2 draws the water's bumps on the floor): the brightening varies.
    double lo = 4, hi = 0;
    for (int i = 0; i < 16; ++i) {
        const double v = floorThroughPane(0, 1, "normal { bumps 0.5 scale 0.3 }", 0.37 * i) / 0.01;
        lo = std::min(lo, v), hi = std::max(hi, v);
    }
    EXPECT_LT(lo, 3);
    EXPECT_GT(hi - lo, 0.5);
}

// The cosine share of irid on a grey floor lit by a parallel light turned `degrees` about y
// (diffuse 1, amount 0.5): (colour / colour without irid − 1) / 0.5 per channel.
Vec3 iridShare(double degrees, const std::string& irid, const std::string& global = "") {
    const Loaded l = load(global + "plane { -z, 0 pigment { rgb 0.5 } finish { ambient 0 diffuse 1 irid { 0.5 " +
                          irid + " } } }\nlight_source { <0,0,-100>, rgb 1 parallel point_at 0 rotate y*" +
                          std::to_string(degrees) + " }\n");
    EXPECT_TRUE(l.warnings.empty()) << l.warnings[0];
    const double base = 0.5 * std::cos(degrees * std::numbers::pi / 180);
    return (seen(l.scene, 0.125, 0.125) / base - Vec3(1.0)) / 0.5;
}

TEST(PovIrid, FilmInterferenceTintsTheLightByThicknessAndAngle) {
    // Measured with povray 3.7 (16-bit output): cos(2π·t·(N·L + N·V)/λ), λ = <0.70, 0.52, 0.48>.
    expectColor(iridShare(0, ""), Vec3(1.0), 1e-9);  // no thickness: × (1 + amount)
    expectColor(iridShare(0, "thickness 0.01"), {0.9839, 0.9709, 0.9659}, 2e-4);
    expectColor(iridShare(0, "thickness 0.1"), {-0.2225, -0.7485, -0.8660}, 2e-4);
    expectColor(iridShare(0, "thickness 0.18"), {-0.9960, -0.3546, 0.0}, 2e-4);
    expectColor(iridShare(60, "thickness 0.01"), {0.9909, 0.9836, 0.9808}, 2e-4);
    expectColor(iridShare(0, "thickness 0.01", "global_settings { irid_wavelength <0.25, 0.125, 0.1> }"),
                {0.8763, 0.5358, 0.3090}, 2e-4);
    // Turbulence scales the thickness point by point (mean 1 + turbulence).
    double lo = 1, hi = -1;
    for (int i = 0; i < 20; ++i) {
        const Loaded l = load("plane { -z, 0 pigment { rgb 0.5 } finish { ambient 0 diffuse 1 irid { 0.5 thickness 0.08 "
                              "turbulence 0.5 } } }\nlight_source { <0,0,-100>, rgb 1 parallel point_at 0 }\n");
        const double b = (seen(l.scene, 0.71 * i, 0.37 * i).z / 0.5 - 1) / 0.5;
        lo = std::min(lo, b), hi = std::max(hi, b);
    }
    EXPECT_GT(hi - lo, 0.5);
}

TEST(PovIrid, TintsTheReflectionAsALightAlongTheReflectedRay) {
    // A black mirror (reflection 0.5, irid 0.65, thickness 0.8) facing a white background, its
    // normal turned 0°, 30° and 60° from the view (POV-Ray 3.7's 16-bit pixels, the camera turned
    // instead): 0.5·(1 + 0.65·cos(2π·0.8·2(N·V)/λ)).
    struct Case {
        int angle;
        Vec3 want;
    } cases[] = {{0, {0.42768, 0.78778, 0.33750}}, {30, {0.82231, 0.33402, 0.74614}}, {60, {0.70263, 0.18445, 0.33750}}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.angle);
        const Loaded l = load("background { rgb 1 }\nplane { -z, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 "
                              "reflection 0.5 irid { 0.65 thickness 0.8 } } rotate x*" + std::to_string(-c.angle) + " }\n");
        expectColor(seen(l.scene, 0, 0), c.want, 2e-4);
    }
}

TEST(PovRainbow, ColoursByTheAngleToItsDirectionMixedAsAFog) {
    // The ray along +z sits 30° from the direction: index (30 − (30 − 10))/20 = 0.5 of the map
    // (measured with povray 3.7: the index as the manual says, the fog's mixing).
    auto seenThrough = [](const std::string& rainbow) {
        const Loaded l = load("background { rgb <0.2, 0.4, 0.6> }\nrainbow { angle 30 width 20 " + rainbow + " }\n");
        EXPECT_TRUE(l.warnings.empty()) << l.warnings[0];
        return seen(l.scene, 0, 0);
    };
    const std::string below = "direction <0, -0.5, 0.8660254> ";
    const std::string map = "color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] }";
    expectColor(seenThrough(below + map), {0.5, 0, 0.5}, 1e-6);
    expectColor(seenThrough(below + "color_map { [0 rgbt <1, 0.5, 0, 0.5>] [1 rgbt <1, 0.5, 0, 0.5>] }"), {0.6, 0.45, 0.3}, 1e-6);
    expectColor(seenThrough(below + "color_map { [0 rgbf <1, 0.5, 0, 1>] [1 rgbf <1, 0.5, 0, 1>] }"), {1, 0.5, 0}, 1e-6);
    // Outside the band: the background.
    expectColor(seenThrough("direction <0, -0.8, 0.6> " + map), {0.2, 0.4, 0.6}, 1e-9);
    // arc_angle about up: this ray lies opposite up (φ = 180°) when the direction leans up.
    expectColor(seenThrough("direction <0, 0.5, 0.8660254> arc_angle 120 " + map), {0.2, 0.4, 0.6}, 1e-9);
    expectColor(seenThrough(below + "arc_angle 120 " + map), {0.5, 0, 0.5}, 1e-6);
}

TEST(PovLooksLike, TheObjectSitsAtTheLightAndCastsNoShadow) {
    // 8×8 render of a 1×1 view: pixel (6,3) at (.3125, .0625) sees the red sphere around the light
    // at (.5, 0, −1); pixel (5,3) at (.1875, .0625) the floor, lit unshadowed: .95280.
    const Loaded l = load(kFloor +
                          "light_source { <0.5,0,-1>, rgb 1 looks_like { sphere { 0, 0.2 pigment { rgb <1,0,0> } "
                          "finish { ambient 1 diffuse 0 } } } }\n");
    EXPECT_TRUE(l.warnings.empty()) << l.warnings[0];
    expectColor(seen(l.scene, 0.3125, 0.0625), {1, 0, 0});
    expectColor(seen(l.scene, 0.1875, 0.0625), Vec3(0.95280));
    expectColor(seen(l.scene, -0.3125, 0.3125), Vec3(0.75424));  // pixel (1,1)
}

TEST(PovLights, ProjectedThroughLightsOnlyWhereTheWayCrossesTheObject) {
    // The light reaches the floor only through the declared sphere (which is not drawn itself).
    const Loaded l = load("#declare P = sphere { <0,0,-0.5>, 0.1 }\n" + kFloor +
                          "light_source { <0,0,-1>, rgb 1 projected_through { P } }\n");
    EXPECT_TRUE(l.warnings.empty()) << l.warnings[0];
    EXPECT_EQ(l.scene.objects.size(), 1u);
    EXPECT_NEAR(seen(l.scene, 0.05, 0.05).x, 0.99, 0.02);  // lit: cos of a small angle
    EXPECT_EQ(seen(l.scene, 0.5, 0.5).x, 0.0);              // its way misses the sphere
}

TEST(PovLights, ProjectedThroughShadowsOnlyBetweenThePointAndTheObject) {
    // Measured with POV-Ray 3.7 (a lit wall, the projector's copy drawn in the scene, one box
    // between the wall and the projector and one between the projector and the light): the copy
    // and the far box leave the projected light whole, the near box shadows it. Floor point
    // (0.15, 0): its way to the light crosses the sphere at z ≈ −0.5; the camera ray misses both.
    const std::string projector = "#declare P = sphere { <0,0,-0.5>, 0.1 }\n";
    const std::string light = "light_source { <0,0,-1>, rgb 1 projected_through { P } }\n";
    const double alone = seen(load(projector + kFloor + light).scene, 0.15, 0).x;
    EXPECT_GT(alone, 0.9);
    const std::string copy = "object { P pigment { rgb 1 } }\n";
    const std::string farBox = "box { <0.02,-0.02,-0.76>, <0.05,0.02,-0.74> pigment { rgb 1 } }\n";
    EXPECT_NEAR(seen(load(projector + kFloor + light + copy + farBox).scene, 0.15, 0).x, alone, 1e-9);
    const std::string nearBox = "box { <0.09,-0.02,-0.26>, <0.13,0.02,-0.24> pigment { rgb 1 } }\n";
    EXPECT_EQ(seen(load(projector + kFloor + light + copy + nearBox).scene, 0.15, 0).x, 0.0);
}

// A light_group's lights light only its objects; the scene's lights light them only with
// global_lights (measured: a white sphere in a group with a red light, a blue scene light beside it,
// is red without global_lights and magenta with it; a sphere outside the group is blue only).
TEST(PovLightGroup, ItsLightsLightOnlyItsObjectsAndTheScenesOnlyWithGlobalLights) {
    const std::string scene = "light_source { <0,0,-100>, rgb <0,0,1> }\n"
                              "sphere { <2,0,0>, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n";
    for (const char* texture : {"pigment { rgb 1 } finish { ambient 0 diffuse 1 }",
                                "texture { pigment { rgb 1 } finish { ambient 0 diffuse 1 } }"
                                " texture { pigment { rgbt 1 } finish { ambient 0 diffuse 1 } }"}) {
        SCOPED_TRACE(texture);
        for (const char* global : {"", "global_lights on"}) {
            SCOPED_TRACE(global);
            const std::string group = std::string("union { light_group { sphere { 0, 1 ") + texture +
                                      " } light_source { <0,0,-100>, rgb <1,0,0> } " + global + " } }\n";
            const Loaded l = load(scene + group);
            EXPECT_TRUE(l.warnings.empty()) << l.warnings[0];
            const Vec3 inGroup = seen(l.scene, 0, 0), outside = seen(l.scene, 2, 0);
            EXPECT_NEAR(inGroup.x, 1, 1e-9);
            EXPECT_NEAR(inGroup.z, *global ? 1.0 : 0.0, 1e-9);
            EXPECT_EQ(outside.x, 0.0);  // (the light is not quite along the sphere's normal there)
            EXPECT_NEAR(outside.z, 1, 1e-3);
        }
    }
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
