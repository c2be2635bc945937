// POV-Ray 3.7's radiosity (global_settings { radiosity { ... } }): the rules measured with povray
// 3.7.0.10 (tests/data/povray/shading/measure_radiosity.py; 4×4 renders, 16-bit PPM, sRGB decoded,
// assumed_gamma 1) checked on the same scenes, the irradiance cache on its own, and renders that
// come out the same for any number of threads (docs/povray-lighting.md, "Radiosity").
#include <gtest/gtest.h>

#include <string>

#include "rays/render/irradiance_cache.h"
#include "rays/render/pov_radiosity.h"
#include "rays/render/tracer.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

using Loaded = test::PovLoaded;

Loaded load(const std::string& settings, const std::string& body, const char* version = "3.7") {
    return test::loadPov(body, std::string("#version ") + version + ";\nglobal_settings { assumed_gamma 1 " + settings + " }\n");
}

// The colour povray's 4×4 render shows at its centre: the camera of measure_radiosity.py
// (orthographic at z = −3 looking along +z), rendered small so that the pretrace runs.
Vec3 centre(const Scene& s) {
    RenderSettings settings;
    settings.width = settings.height = 4;
    settings.threads = 1;
    settings.linearOutput = true;  // the working-space colour, as the measurements decode it
    const Bvh bvh(s.objects);
    TraceStats stats;
    return render(s, bvh, settings, stats).at(2, 2);
}

const char* kOrtho = "camera { orthographic location -3*z look_at 0 right x up y }\n";

// A white plane facing the camera inside a big sphere that emits `sky` (uniform radiance).
std::string skyScene(const std::string& plane, const std::string& sky) {
    return std::string(kOrtho) + "plane { -z, 0 pigment { rgb 1 } finish { " + plane + " } }\n" +
           "sphere { 0, 100 pigment { rgb 1 } finish { " + sky + " } }\n";
}

void expectGrey(Vec3 got, double want, double tol = 2e-3) {
    EXPECT_NEAR(got.x, want, tol);
    EXPECT_NEAR(got.y, want, tol);
    EXPECT_NEAR(got.z, want, tol);
}

TEST(PovRadiosity, SurfaceUnderAUniformSkyGetsDiffuseTimesItsRadiance) {
    // E = L for a surface that sees uniform radiance L; the surface shows diffuse·C·brightness·E.
    // Measured: .29999 (diffuse .6, sky .5), .15001 (diffuse .3), .60001 (brightness 2), .15001
    // (pigment .5); 0 without radiosity.
    const std::string sky = "ambient 0 diffuse 0 emission .5";
    expectGrey(centre(load("", skyScene("ambient 0 diffuse .6", sky)).scene), 0.0, 1e-9);
    expectGrey(centre(load("radiosity { count 200 }", skyScene("ambient 0 diffuse .6", sky)).scene), 0.3);
    expectGrey(centre(load("radiosity { count 200 }", skyScene("ambient 0 diffuse .3", sky)).scene), 0.15);
    expectGrey(centre(load("radiosity { count 200 brightness 2 }", skyScene("ambient 0 diffuse .6", sky)).scene), 0.6);
}

// no_radiosity hides an object from the gathering rays only (reference, "Object Modifiers";
// measured with POV-Ray 3.7: a red emitting wall with no_radiosity no longer tints the floor
// before it, and still shows itself). The sky sphere hidden so, the plane gathers nothing.
TEST(PovRadiosity, NoRadiosityHidesAnObjectFromTheGatheringRays) {
    const std::string plane = std::string(kOrtho) + "plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse .6 } }\n";
    const std::string sky = "sphere { 0, 100 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission .5 } ";
    expectGrey(centre(load("radiosity { count 200 }", plane + sky + "}").scene), 0.3);
    expectGrey(centre(load("radiosity { count 200 }", plane + sky + "no_radiosity }").scene), 0.0, 1e-9);
    // Within a union too, and the object itself still shows.
    expectGrey(centre(load("radiosity { count 200 }", plane + "union { " + sky + "} no_radiosity }").scene), 0.0, 1e-9);
    const std::string facing = std::string(kOrtho) + "plane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission .5 } no_radiosity }\n";
    expectGrey(centre(load("radiosity { count 200 }", facing).scene), 0.5);
}

TEST(PovRadiosity, AmbientIsDroppedInVersion37AndEmissionKept) {
    // Measured: plane ambient .2 → .29999 (as ambient 0), also with ambient_light .5; plane
    // emission .2 → .50001; a sky of ambient .5 (no emission) lights nothing: 0.
    const std::string sky = "ambient 0 diffuse 0 emission .5";
    expectGrey(centre(load("radiosity { count 200 }", skyScene("ambient .2 diffuse .6", sky)).scene), 0.3);
    expectGrey(centre(load("radiosity { count 200 } ambient_light .5", skyScene("ambient .2 diffuse .6", sky)).scene), 0.3);
    expectGrey(centre(load("radiosity { count 200 }", skyScene("ambient 0 emission .2 diffuse .6", sky)).scene), 0.5);
    expectGrey(centre(load("radiosity { count 200 }", skyScene("ambient 0 diffuse .6", "ambient .5 diffuse 0")).scene), 0.0, 1e-9);
}

TEST(PovRadiosity, LegacyScenesKeepAmbientAsLightOfItsOwn) {
    // #version 3.6, measured: plane ambient 0 under a sky of ambient .5 → .29999; plane ambient .2
    // diffuse 0 → .20001; ambient .2 diffuse .6 under ambient .5 with ambient_light .5 → .25000.
    const char* rad = "radiosity { count 200 }";
    expectGrey(centre(load(rad, skyScene("ambient 0 diffuse .6", "ambient .5 diffuse 0"), "3.6").scene), 0.3);
    expectGrey(centre(load(rad, skyScene("ambient .2 diffuse 0", "ambient .5 diffuse 0"), "3.6").scene), 0.2);
    expectGrey(centre(load(std::string(rad) + " ambient_light .5", skyScene("ambient .2 diffuse .6", "ambient .5 diffuse 0"), "3.6").scene), 0.25);
}

TEST(PovRadiosity, ClosedSphereAddsOneBounceForEachRecursionLevel) {
    // Inside a sphere of emission e = .5, diffuse ρ = .5: e·(1 + ρ + … + ρ^n) for recursion_limit n
    // (the last level's hits show emission and lights only, not ambient). Measured: .75000,
    // .87499, .93752, the same with ambient .2.
    const double want[] = {0.75, 0.875, 0.9375};
    for (int n = 1; n <= 3; ++n)
        for (const char* fin : {"ambient 0 diffuse .5 emission .5", "ambient .2 diffuse .5 emission .5"}) {
            const std::string body = std::string(kOrtho) + "sphere { 0, 100 pigment { rgb 1 } finish { " + fin + " } }\n";
            expectGrey(centre(load("radiosity { count 100 recursion_limit " + std::to_string(n) + " }", body).scene),
                       want[n - 1]);
        }
}

TEST(PovRadiosity, GatheringRaysSeeLightsButNoHighlights) {
    // A sphere of diffuse .5 lit from its centre by rgb .5 (.25 direct): .37501 with radiosity;
    // with phong .5 phong_size 1 .62499 (the camera's highlight .25, none in the gathered light).
    const std::string lit = std::string(kOrtho) + "light_source { 0, rgb .5 }\n";
    expectGrey(centre(load("radiosity { count 200 recursion_limit 1 }",
                           lit + "sphere { 0, 100 pigment { rgb 1 } finish { ambient 0 diffuse .5 } }\n").scene),
               0.375);
    expectGrey(centre(load("radiosity { count 200 recursion_limit 1 }",
                           lit + "sphere { 0, 100 pigment { rgb 1 } finish { ambient 0 diffuse .5 phong .5 phong_size 1 } }\n")
                          .scene),
               0.625);
}

// A floor and a ceiling 54.88 apart, a faded light in the ceiling's plane (as radiosity/cornell.pov's).
std::string ceilingScene(const std::string& light) {
    return "camera { orthographic location <12,20,40> look_at <12,54,40> right x*1 up z*1 }\n"
           "light_source { <27.8,54.88,27.95> color 1 fade_power 2 fade_distance 30 " + light + " }\n"
           "plane { y, 0 pigment { rgb 1 } finish { diffuse .75 ambient 0 } }\n"
           "plane { -y, -54.88 pigment { rgb 1 } finish { diffuse .75 ambient 0 } }\n";
}

TEST(PovRadiosity, GatheringRaysSeeAreaLightsAsPointsAtTheirCentre) {
    // The ceiling lit only by the floor: .10530 measured. With a 10×10 board 10.88 below the light
    // shading the floor: .06491 with a point light and the same .06491 with a 20×20 area light of
    // 8×8 samples (sampled, its soft shadow would give the ceiling .081).
    const char* rad = "radiosity { pretrace_start 0.04 pretrace_end 0.01 count 200 recursion_limit 1 nearest_count 10 error_bound 0.5 }";
    expectGrey(centre(load(rad, ceilingScene("")).scene), 0.10530, 2e-3);
    const std::string board = "box { <22.8,44,22.95>, <32.8,44.1,32.95> pigment { rgb 1 } finish { diffuse 0 ambient 0 } }\n";
    auto shaded = [&](const std::string& light) {
        std::string s = ceilingScene(light) + board;
        s.replace(s.find("location <12,20,40> look_at <12,54,40>"), 38, "location <10,40,10> look_at <10,54,10>");
        return s;
    };
    expectGrey(centre(load(rad, shaded("")).scene), 0.06491, 2e-3);
    expectGrey(centre(load(rad, shaded("area_light 20*x, 20*z, 8, 8")).scene), 0.06491, 2e-3);
}

TEST(PovRadiosity, GrayThresholdMovesTheGatheredColourTowardsItsGrey) {
    // Sky emission <.5,.2,.1>, plane diffuse 1. Measured: g 0 → .50001 .20001 .10000; g .5 →
    // .38885 .23885 .18886; g 1 → .27769 for all three.
    const std::string body = skyScene("ambient 0 diffuse 1", "ambient 0 diffuse 0 emission <.5,.2,.1>");
    const Vec3 half = centre(load("radiosity { count 200 gray_threshold .5 }", body).scene);
    EXPECT_NEAR(half.x, 0.38885, 2e-3);
    EXPECT_NEAR(half.y, 0.23885, 2e-3);
    EXPECT_NEAR(half.z, 0.18886, 2e-3);
    expectGrey(centre(load("radiosity { count 200 gray_threshold 1 }", body).scene), 0.27769);
    const Vec3 g = povGrayThreshold({0.5, 0.2, 0.1}, 1);
    EXPECT_NEAR(g.x, 0.27770, 1e-5);
}

TEST(PovRadiosity, ScenesWithRadiosityCarryNoNote) {
    const Loaded l = load("radiosity { count 35 error_bound 1.8 }", skyScene("diffuse .6", "emission .5"));
    for (const std::string& w : l.warnings) EXPECT_EQ(w.find("radiosity"), std::string::npos) << w;
    EXPECT_TRUE(l.scene.pov.radiosity.enabled);
    EXPECT_EQ(l.scene.pov.radiosity.count, 35);
    EXPECT_DOUBLE_EQ(l.scene.pov.radiosity.errorBound, 1.8);
}

// A corner of two walls and a floor under a light, with an emitting ball: light varies over the
// surfaces, so records are reused, blended and made on the spot.
const std::string kRoom = R"(
camera { location <0, 1.5, -4> look_at <0, 0.8, 0> }
light_source { <1, 3, -2>, rgb 1 }
plane { y, 0 pigment { rgb <1, .9, .8> } finish { ambient 0 diffuse .7 } }
plane { -z, -2 pigment { rgb <.3, .8, .3> } finish { ambient 0 diffuse .7 } }
plane { x, -2 pigment { rgb <.9, .2, .2> } finish { ambient 0 diffuse .7 } }
sphere { <0.5, 0.5, 0>, 0.5 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 2 } }
box { <-1.2, 0, -0.5>, <-0.4, 1.2, 0.3> pigment { rgb .8 } finish { ambient 0 diffuse .7 } }
)";

TEST(PovRadiosity, ImagesAreTheSameForAnyNumberOfThreads) {
    const Loaded l = load("radiosity { count 40 recursion_limit 2 error_bound .5 pretrace_start .16 pretrace_end .04 }", kRoom);
    const ImageF one = test::renderPov(l.scene, 48, 36, 1);
    const ImageF two = test::renderPov(l.scene, 48, 36, 2);
    const ImageF five = test::renderPov(l.scene, 48, 36, 5);
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 48; ++x) {
            ASSERT_EQ(one.at(x, y), two.at(x, y)) << x << "," << y;
            ASSERT_EQ(one.at(x, y), five.at(x, y)) << x << "," << y;
        }
}

TEST(PovRadiosity, TheRoomIsLitByWhatItsSurfacesSendBack) {
    // The wall beside the emitting ball, in the light's shadow side: brighter with radiosity.
    const Loaded with = load("radiosity { count 40 recursion_limit 1 }", kRoom);
    const Loaded without = load("", kRoom);
    const ImageF a = test::renderPov(with.scene, 48, 36, 2), b = test::renderPov(without.scene, 48, 36, 2);
    double sumWith = 0, sumWithout = 0;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 48; ++x) sumWith += a.at(x, y).x, sumWithout += b.at(x, y).x;
    EXPECT_GT(sumWith, sumWithout * 1.05);
}

TEST(IrradianceCache, BlendsValidRecordsByWardsWeights) {
    IrradianceCache cache;
    cache.add({.P = {0, 0, 0}, .N = {0, 0, 1}, .E = Vec3(1.0), .R = 1, .level = 0});
    cache.add({.P = {1, 0, 0}, .N = {0, 0, 1}, .E = Vec3(3.0), .R = 1, .level = 0});
    cache.add({.P = {0.5, 0, 0}, .N = {0, 0, 1}, .E = Vec3(9.0), .R = 1, .level = 1});  // another level
    cache.build(1.0);
    // Half way: both at ε = .5, equal weights.
    IrradianceBlend mid({0.5, 0, 0}, {0, 0, 1}, 0, 1.0, 5);
    cache.gather({0.5, 0, 0}, mid);
    Vec3 E;
    ASSERT_TRUE(mid.result(E));
    EXPECT_NEAR(E.x, 2.0, 1e-12);
    // At .25: ε .25 and .75, weights 1/ε − 1/a = 3 and 1/3.
    IrradianceBlend near({0.25, 0, 0}, {0, 0, 1}, 0, 1.0, 5);
    cache.gather({0.25, 0, 0}, near);
    ASSERT_TRUE(near.result(E));
    EXPECT_NEAR(E.x, (3 * 1.0 + 3.0 / 3) / (3 + 1.0 / 3), 1e-12);
    // Beyond the error bound of both, or facing elsewhere: nothing.
    IrradianceBlend far({3, 0, 0}, {0, 0, 1}, 0, 1.0, 5);
    cache.gather({3, 0, 0}, far);
    EXPECT_FALSE(far.result(E));
    IrradianceBlend turned({0, 0, 0}, {1, 0, 0}, 0, 1.0, 5);
    cache.gather({0, 0, 0}, turned);
    EXPECT_FALSE(turned.result(E));
    // nearest_count 1 keeps the best.
    IrradianceBlend one({0.25, 0, 0}, {0, 0, 1}, 0, 1.0, 1);
    cache.gather({0.25, 0, 0}, one);
    ASSERT_TRUE(one.result(E));
    EXPECT_NEAR(E.x, 1.0, 1e-12);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
