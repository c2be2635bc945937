// POV-Ray media read from POV text and traced: absorption, emission, scattering and its phase
// functions, densities, several media, hollow objects and atmospheric media, shadows through media,
// media_attenuation, method 3's steps and the beams of spotlights. The expected values were
// measured with povray 3.7.0.10 (16-bit PPM, File_Gamma 1, assumed_gamma 1: the scenes as written
// here, 2×2 or 4×4 renders of an orthographic camera; docs/povray-lighting.md, "Media").
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rays/render/pov_media.h"
#include "rays/render/tracer.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

constexpr double kMeasured = 2e-4;  // povray's 16-bit output, and Rays' surface offset

Scene load(const std::string& body) {
    return test::loadPov(body, "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n").scene;
}

// The working-space colour seen along a ray (an orthographic camera's).
Vec3 seen(const Scene& s, Vec3 origin, Vec3 dir = {0, 0, 1}) {
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    return Tracer(s, bvh, rs).tracePrimary(Ray{origin, dir}, ctx);
}

void expectColor(Vec3 got, Vec3 want, double tol = kMeasured) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

// A clear hollow slab from z = 0 to z = depth holding the media, seen from z = −10.
std::string slab(const std::string& media, double depth = 1) {
    return "box { <-5,-5,0>, <5,5," + std::to_string(depth) + "> pigment { rgbf 1 } hollow interior { " + media +
           " } }\n";
}

const Vec3 kEye{0.1, 0.1, -10};

TEST(PovMedia, AbsorptionDimsByBeersLaw) {
    // Measured 0.36788 = e⁻¹: the white background through a slab of depth 1 absorbing 1.
    expectColor(seen(load("background { rgb 1 }\n" + slab("media { absorption 1 }")), kEye), Vec3(std::exp(-1.0)));
    expectColor(seen(load("background { rgb 1 }\n" + slab("media { absorption <1,0,2> }")), kEye),
                {std::exp(-1.0), 1, std::exp(-2.0)});
}

TEST(PovMedia, EmissionAddsItsColourTimesTheDepth) {
    expectColor(seen(load(slab("media { emission 1 }", 0.5)), kEye), Vec3(0.5));  // measured .50001
}

// An object inside a media-filled one keeps the media out unless it is hollow (measured with
// POV-Ray 3.7: emission 0.25 over a hollow slab of depth 2 holding a clear box of depth 1 gives
// 0.25 through the box, 0.5 when the box is hollow; 8-bit sRGB 137 and 188).
TEST(PovMedia, ObjectsInsideKeepTheMediaOutUnlessHollow) {
    const std::string outer =
        "box { <-5,-5,0>, <5,5,2> pigment { rgbf 1 } hollow interior { media { emission 0.25 } } }\n";
    const std::string inner = "box { <-4,-4,0.5>, <4,4,1.5> pigment { rgbf 1 } ";
    expectColor(seen(load(outer + inner + "}\n"), kEye), Vec3(0.25), 2e-3);
    expectColor(seen(load(outer + inner + "hollow }\n"), kEye), Vec3(0.5), 2e-3);
}

// Emission and absorption together: method 3's ⌊samples/2⌋ + 1 equal steps, each step's light
// dimmed by the steps before it (measured 0.68626 without samples, as with samples 10; 0.80330
// with samples 1 to 3; 0.64440 with samples 50). Exact integration would give 1 − e⁻¹ = 0.63212.
TEST(PovMedia, EmissionThroughAbsorptionIsSummedInMethod3Steps) {
    expectColor(seen(load(slab("media { emission 1 absorption 1 }")), kEye), Vec3(0.68626));
    expectColor(seen(load(slab("media { emission 1 absorption 1 samples 1 }")), kEye), Vec3(0.80330));
    expectColor(seen(load(slab("media { emission 1 absorption 1 samples 3 }")), kEye), Vec3(0.80330));
    expectColor(seen(load(slab("media { emission 1 absorption 1 samples 50 }")), kEye), Vec3(0.64440));
    EXPECT_EQ(povMediaSteps(10), 6);
    EXPECT_EQ(povMediaSteps(1), 2);
    EXPECT_EQ(povMediaSteps(7), 4);
}

// Methods 1 and 2: `samples`' maximum equal steps sampled in their middles, each sample's light
// dimmed up to it (measured with method 2: .63186 with samples 10,10, .62921 with samples 3,3).
TEST(PovMedia, Methods1And2SampleStepMiddles) {
    expectColor(seen(load(slab("media { emission 1 absorption 1 method 2 samples 10,10 }")), kEye), Vec3(0.631861));
    expectColor(seen(load(slab("media { emission 1 absorption 1 method 2 samples 3,3 }")), kEye), Vec3(0.629206));
}

// Densities multiply each other and the media's colours; media in one interior add up (measured
// <.22499,.4,.8> = <.5,1,2>·<.5,.6,.7>·.5 + .1).
TEST(PovMedia, DensitiesMultiplyAndMediaAdd) {
    const Scene s = load(slab(
        "media { emission <0.5,1,2> density { rgb <0.5,0.6,0.7> } density { rgb 0.5 } } media { emission 0.1 }"));
    expectColor(seen(s, kEye), {0.225, 0.4, 0.8});
}

// A density pattern with a colour map and a density list: checker's two densities (measured .5 and
// <.2,.3,.4> on either side of x = 0), a gradient's map.
TEST(PovMedia, DensityPatternsPickTheDensity) {
    const Scene s = load(slab("media { emission 1 density { checker density { rgb 0.5 } density { rgb <0.2,0.3,0.4> } } }"));
    expectColor(seen(s, {-0.5, -0.5, -10}), Vec3(0.5));
    expectColor(seen(s, {0.5, -0.5, -10}), {0.2, 0.3, 0.4});
    const Scene g = load(slab("media { emission 1 density { gradient x color_map { [0 rgb 0] [1 rgb 1] } } }"));
    expectColor(seen(g, {0.25, 0.1, -10}), Vec3(0.25), 1e-9);
    expectColor(seen(g, {0.75, 0.1, -10}), Vec3(0.75), 1e-9);
}

// density { object { OBJECT density { A }, density { B } } }: B inside the object (measured 0.38889
// through the sphere at <0.5, 0.5>: method 3's samples, not the chord's 0.35355; 0 outside).
TEST(PovMedia, ObjectDensityIsTheInsideDensityInsideTheObject) {
    const Scene s = load("box { -2, 2 pigment { rgbf 1 } hollow interior { media { emission 0.25 density { object {\n"
                         "  sphere { 0, 1 } density { rgb 0 }, density { rgb 1 } } } } } }");
    expectColor(seen(s, {1.5, 0.5, -10}), Vec3(0.0), 1e-12);
    // Rays' method 3 steps meet the sphere's edge elsewhere: 0.41667.
    expectColor(seen(s, {0.5, 0.5, -10}), Vec3(0.38889), 0.03);
}

// Densities multiply, so the cheap ones are placed first: where one is 0 the costly ones after it
// are not evaluated (the product stays the same).
TEST(PovMedia, CheapDensitiesComeFirst) {
    const Scene s = load(slab("media { emission 1 density { crackle } density { spherical } }"));
    ASSERT_EQ(s.povMedia.size(), 1u);
    const PovMedia& m = s.povMedia[0];
    ASSERT_EQ(m.densityCount, 2);
    const auto kind = [&](int k) {
        return s.pigments.nodes[size_t(s.pigments.roots[size_t(m.densityFirst + k)].node)].kind;
    };
    EXPECT_EQ(kind(0), pattern::PatternKind::Spherical);
    EXPECT_EQ(kind(1), pattern::PatternKind::Crackle);
}

// A density of a pattern Rays does not render is 0, and says so.
TEST(PovMedia, UnrenderedDensityPatternsAreZero) {
    const test::PovLoaded l = test::loadPov(
        slab("media { emission 1 density { tiling 26 color_map { [0 rgb 1] [1 rgb 1] } } }"),
        "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n");
    expectColor(seen(l.scene, kEye), Vec3(0.0), 1e-12);
    ASSERT_FALSE(l.warnings.empty());
    EXPECT_NE(l.warnings[0].find("density pattern tiling 26 (density 0: no media there)"), std::string::npos) << l.warnings[0];
}

// The media move with the object: a density translated with it.
TEST(PovMedia, DensitiesMoveWithTheObject) {
    const Scene s = load(
        "box { <-5,-5,0>, <5,5,1> pigment { rgbf 1 } hollow interior { media { emission 1 density { gradient x "
        "color_map { [0 rgb 0] [1 rgb 1] } } } } translate 0.5*x }\n");
    expectColor(seen(s, {0.75, 0.1, -10}), Vec3(0.25), 1e-9);
}

// Overlapping objects: a ray inside both sees both media, and still the first after leaving the
// second (measured <.2,.6,.2>: emission .1 over 2 units, <0,.2,0> over 2 units, 1 of them shared).
TEST(PovMedia, MediaOfNestedInteriorsAddUp) {
    const Scene s = load(
        "box { <-5,-5,0>, <5,5,2> pigment { rgbf 1 } hollow interior { media { emission 0.1 } } }\n"
        "box { <-5,-5,1>, <5,5,3> pigment { rgbf 1 } hollow interior { media { emission <0,0.2,0> } } }\n");
    expectColor(seen(s, {0.1, 0.1, -3}), {0.2, 0.6, 0.2});
}

// A camera inside an object with media sees them from the camera on (measured .2: emission .1 from
// the centre of a sphere of radius 2).
TEST(PovMedia, CameraInsideMedia) {
    const Scene s = load("sphere { 0, 2 pigment { rgbf 1 } hollow interior { media { emission 0.1 } } }\n");
    expectColor(seen(s, {0, 0, 0}), Vec3(0.2));
}

// The lights of a light_group light only the group's objects: no media (measured 0).
TEST(PovMedia, LightGroupLightsLightNoMedia) {
    const Scene s = load("light_group { light_source { <0,1000,0> rgb 10 } sphere { <0,0,-100>, 1 pigment { rgb 1 } } }\n" +
                         slab("media { scattering { 1, 1 } }", 0.01));
    expectColor(seen(s, kEye), Vec3(0.0), 1e-12);
}

// Radiosity gathers no light from media (its `media` is off by default: measured 0 on a floor
// under a shell of emission .5, which would light it .5 otherwise).
TEST(PovMedia, RadiosityGathersNoMediaLight) {
    const Scene s = test::loadPov(
                        "plane { y, 0 pigment { rgb 1 } finish { diffuse 1 ambient 0 } }\n"
                        "difference { sphere { 0, 100 } sphere { 0, 99 } pigment { rgbt 1 } finish { ambient 0 diffuse 0 }"
                        " interior { media { emission 0.5 } } hollow no_shadow }\n",
                        "#version 3.7;\nglobal_settings { assumed_gamma 1 radiosity { count 50 recursion_limit 1 } }\n")
                        .scene;
    expectColor(seen(s, {0.1, 5, 0.1}, {0, -1, 0}), Vec3(0.0), 1e-12);
}

// Atmospheric media fill the space outside objects and hollow objects, not other objects (measured:
// emission 0.02 over the 5 units from the camera to a black wall, 1 of them inside a clear box:
// .08 when the box is not hollow, .1 when it is).
TEST(PovMedia, AtmosphericMediaFillOnlyHollowObjects) {
    auto scene = [](const char* hollow) {
        return load(std::string("media { emission 0.02 }\n"
                                "plane { -z, -2 pigment { rgb 0 } finish { ambient 0 diffuse 0 } }\n"
                                "box { <-5,-5,0>, <5,5,1> pigment { rgbf 1 } finish { ambient 0 diffuse 0 } ") +
                    hollow + " }\n");
    };
    expectColor(seen(scene(""), {0.1, 0.1, -3}), Vec3(0.08));
    expectColor(seen(scene("hollow"), {0.1, 0.1, -3}), Vec3(0.1));
}

// Scattering: scattering colour × depth × phase × light. A slab of depth 0.01 scattering 1 with
// extinction 0, a light of 10 far off in the directions below (measured).
TEST(PovMedia, ScatteringFollowsThePhaseFunctions) {
    struct Case {
        const char* type;
        const char* light;
        double want;
    };
    const Case cases[] = {
        {"1", "<0,1000,-1000>", 0.100008},   {"2", "<0,0,1000>", 0.576654},      // isotropic; hazy forward
        {"2", "<0,1000,1000>", 0.203769},    {"2", "<0,1000,-1000>", 0.057664},  // hazy 45°, 135°
        {"4", "<0,1000,0>", 0.079942},       {"4", "<0,0,-1000>", 0.159869},     // Rayleigh 90°, 180°
        {"5", "<0,1000,1000>", 0.187396},    {"5", "<0,0,-1000>", 0.022217},     // Henyey-Greenstein .5
        {"3", "<0,1000,1000>", 0.065141},                                      // murky 45°
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(c.type) + " " + c.light);
        const Scene s = load(std::string("light_source { ") + c.light + " rgb 10 }\n" +
                             slab(std::string("media { scattering { ") + c.type +
                                      ", 1 extinction 0 eccentricity 0.5 } }",
                                  0.01));
        EXPECT_NEAR(seen(s, kEye).x, c.want, 1e-3 * c.want + 1e-5);
    }
    PovMedia hg;
    hg.type = PovMedia::Scattering::HenyeyGreenstein;
    hg.eccentricity = 0.5;
    EXPECT_NEAR(povMediaPhase(hg, 1), 6, 1e-12);   // (1 − g²)/(1 − g)³
    EXPECT_NEAR(povMediaPhase(hg, -1), 0.75 / 3.375, 1e-12);
}

// A light with media_interaction off lights no media.
TEST(PovMedia, MediaInteractionOffLightsNoMedia) {
    const Scene s = load("light_source { <0,1000,0> rgb 10 media_interaction off }\n" +
                         slab("media { scattering { 1, 1 extinction 0 } }", 0.01));
    expectColor(seen(s, kEye), Vec3(0.0), 1e-12);
}

// Interior media dim shadow rays whatever media_attenuation says; atmospheric media only with
// media_attenuation on (measured from above on a white floor lit from straight above: through an
// absorbing slab of depth 1 .13533 = e⁻², the slab crossed twice; in atmospheric absorption 0.1 with the
// camera 11 above the floor and the light 6: .33059 off, .18068 on).
TEST(PovMedia, ShadowRaysThroughMedia) {
    const std::string floor = "plane { y, -1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n";
    for (const char* attenuation : {"off", "on"}) {
        const Scene s = load(std::string("light_source { <0,1000,0> rgb 1 media_attenuation ") + attenuation + " }\n" +
                             floor +
                             "box { <-5,0,-5>, <5,1,5> pigment { rgbf 1 } hollow interior { media { absorption 1 } } }\n");
        expectColor(seen(s, {0.5, 10, 0.5}, {0, -1, 0}), Vec3(0.135332));
    }
    auto air = [&](const char* attenuation) {
        return load(std::string("light_source { <0,5,0> rgb 1 media_attenuation ") + attenuation + " }\n" + floor +
                    "media { absorption 0.1 }\n");
    };
    expectColor(seen(air("off"), {0.5, 10, 0.5}, {0, -1, 0}), Vec3(0.330587), 3e-3);
    expectColor(seen(air("on"), {0.5, 10, 0.5}, {0, -1, 0}), Vec3(0.180682), 2e-3);
}

// A spotlight's beam in scattering media: the stretch is cut at the beam's edges, so that a thin
// beam is lit however few the samples (a beam of half angle 5° across a 20-unit path with samples 3).
TEST(PovMedia, SpotlightBeamsAreSampledApart) {
    const Scene s = load(
        "light_source { <0,10,5> rgb 1 spotlight point_at <0,0,5> radius 5 falloff 5 }\n"
        "box { <-5,-5,-5>, <5,5,15> pigment { rgbf 1 } hollow interior { media { samples 3 scattering { 1, 0.1 "
        "extinction 0 } } } }\n");
    // The beam is 2·10·tan 5° = 1.75 wide at the ray's height (y = 0): scattering 0.1 over it
    // (measured .16773 with samples 3, .17446 with samples 50).
    const double width = 2 * 10 * std::tan(5 * 3.14159265358979 / 180);
    EXPECT_NEAR(seen(s, {0, 0, -10}).x, 0.1 * width, 0.02 * width);
    Light spot;
    spot.spot = Light::Spot::Cone;
    spot.position = {0, 10, 5};
    spot.direction = {0, -1, 0};
    spot.spotRadius = spot.spotFalloff = std::cos(5 * 3.14159265358979 / 180);
    double edges[4];
    ASSERT_EQ(povLightBeamEdges(spot, Ray{{0, 0, -10}, {0, 0, 1}}, 0, 30, edges, 4), 4);  // radius and falloff cones
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
