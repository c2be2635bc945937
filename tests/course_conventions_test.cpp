// The course reference renderer's conventions of issue 28, each on a small scene whose expected
// result is worked out from the rule: printrays' layout, where secondary and shadow rays start,
// and global illumination's ambient term.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "rays/io/scene_parser.h"
#include "rays/math/sampling.h"
#include "rays/render/course_commands.h"
#include "rays/render/tracer.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

Scene sceneFrom(const std::string& text) {
    ParseOptions opt;
    opt.warn = [](const std::string&) {};
    return parseScene(text, "t.pov", opt);
}

void expectVec(Vec3 actual, Vec3 expected, double tol, const char* what) {
    EXPECT_NEAR(actual.x, expected.x, tol) << what;
    EXPECT_NEAR(actual.y, expected.y, tol) << what;
    EXPECT_NEAR(actual.z, expected.z, tol) << what;
}

// One printrays record: the lines of a ray that hits the sphere of CourseTree (white, ambient
// 0.2, filter 0.4, reflection 0.5: weights local 0.6·0.5 = 0.3, reflection 0.3, transmission
// 0.4), all its terms grey.
std::string hitRecord(const char* kind, const char* ray, const char* objectRay, const char* point, const char* t,
                      const char* normal, const char* color, const char* reflection, const char* refraction,
                      const char* extra) {
    auto grey = [](const char* v) { return std::string("{") + v + " " + v + " " + v + "}"; };
    std::string s = std::string("----\n") + "  Iteration type: " + kind + "\n" + "             Ray: " + ray + "\n" +
                    " Transformed Ray: " + objectRay + "\n" + "      Hit Object: (ID #1 - Sphere)\n" +
                    "    Intersection: " + point + " at T = " + t + "\n" + "          Normal: " + normal + "\n" +
                    "     Final Color: " + grey(color) + "\n" + "         Ambient: " + grey("0.0600") + "\n" +
                    "         Diffuse: " + grey("0.0000") + "\n" + "        Specular: " + grey("0.0000") + "\n" +
                    "      Reflection: " + grey(reflection) + "\n" + "      Refraction: " + grey(refraction) + "\n" +
                    "   Contributions: 0.3000 Local, 0.3000 Reflection, 0.4000 Transmission\n";
    if (extra) s += std::string("      Extra Info: ") + extra + "\n";
    return s;
}

std::string missRecord(const char* kind, const char* ray, const char* extra) {
    std::string s = std::string("----\n") + "  Iteration type: " + kind + "\n" + "             Ray: " + ray + "\n" +
                    "  No intersection.\n";
    if (extra) s += std::string("      Extra Info: ") + extra + "\n";
    return s + "\n";  // no children: a blank line
}

// A 1×1 image looks straight down −z at a sphere of radius 2 (a unit sphere scaled by 2, so
// every hit prints its object-space ray: origin and direction halved) with no lights: each hit
// is ambient 0.3·0.2 = 0.06 plus 0.3 × its reflection and 0.4 × its refraction. With ior 1 the
// refracted ray goes straight on; inside, the reflected ray bounces between z = −2 and z = 2 and
// every refracted ray leaving the sphere misses, until the limit of 5 bounces. Rays start 0.001
// off the surface along the normal. Colours from the deepest hit up:
//   depth 5: 0.06; 4: 0.06 + 0.3·0.06 = 0.078; 3: 0.06 + 0.3·0.078 = 0.0834;
//   2: 0.06 + 0.3·0.0834 = 0.08502; 1: 0.06 + 0.3·0.08502 = 0.085506;
//   primary: 0.06 + 0.4·0.085506 = 0.0942024 (its reflection, back towards the camera, misses);
//   pixel round(0.0942024·255) = 24.
TEST(CourseConventions, PrintraysTreeLayout) {
    const Scene s = sceneFrom(
        "camera { location <0,0,10> up <0,1,0> right <1,0,0> look_at <0,0,0> }\n"
        "sphere { <0,0,0>, 1 scale 2 pigment { color rgbf <1,1,1,0.4> } finish { ambient 0.2 reflection 0.5 ior 1 } }\n");
    const Bvh bvh(s.objects);
    RenderSettings rs;
    rs.width = rs.height = 1;
    std::ostringstream out;
    printRays(out, s, bvh, rs, 0, 0);

    const char* down = "{0.0000 0.0000 -1.0000}";
    const char* up = "{0.0000 0.0000 1.0000}";
    const char* front = "{0.0000 0.0000 2.0000}";
    const char* back = "{0.0000 0.0000 -2.0000}";
    // Inside: from just inside the back going up, from just inside the front going down.
    const char* upRay = "{0.0000 0.0000 -1.9990} -> {0.0000 0.0000 1.0000}";
    const char* upObj = "{0.0000 0.0000 -0.9995} -> {0.0000 0.0000 0.5000}";
    const char* downRay = "{0.0000 0.0000 1.9990} -> {0.0000 0.0000 -1.0000}";
    const char* downObj = "{0.0000 0.0000 0.9995} -> {0.0000 0.0000 -0.5000}";
    // Leaving: just outside the back going down, just outside the front going up.
    const char* outBack = "{0.0000 0.0000 -2.0010} -> {0.0000 0.0000 -1.0000}";
    const char* outFront = "{0.0000 0.0000 2.0010} -> {0.0000 0.0000 1.0000}";

    std::string expected = "Pixel: [0, 0] Color: (24, 24, 24)\n";
    expected += hitRecord("Primary", "{0.0000 0.0000 10.0000} -> {0.0000 0.0000 -1.0000}",
                          "{0.0000 0.0000 5.0000} -> {0.0000 0.0000 -0.5000}", front, "8.0000", up, "0.0942",
                          "0.0000", "0.0342", nullptr);
    // Its refraction subtree first: into the sphere, to the back (depth 1).
    expected += hitRecord("Refraction", downRay, downObj, back, "3.9990", down, "0.0855", "0.0255", "0.0000",
                          "into-object");
    expected += missRecord("Refraction", outBack, "into-air");                                                 // 2
    expected += hitRecord("Reflection", upRay, upObj, front, "3.9990", up, "0.0850", "0.0250", "0.0000", nullptr);  // 2
    expected += missRecord("Refraction", outFront, "into-air");                                                     // 3
    expected += hitRecord("Reflection", downRay, downObj, back, "3.9990", down, "0.0834", "0.0234", "0.0000", nullptr);
    expected += missRecord("Refraction", outBack, "into-air");                                                 // 4
    expected += hitRecord("Reflection", upRay, upObj, front, "3.9990", up, "0.0780", "0.0180", "0.0000", nullptr);  // 4
    expected += missRecord("Refraction", outFront, "into-air");                                                     // 5
    // Depth 5: the limit, no children.
    expected += hitRecord("Reflection", downRay, downObj, back, "3.9990", down, "0.0600", "0.0000", "0.0000", nullptr) +
                "\n";
    // Then the primary's reflection, back towards the camera: nothing there.
    expected += missRecord("Reflection", outFront, nullptr);
    expected += "\n" + std::string(80, '-') + "\n\n";
    EXPECT_EQ(out.str(), expected);
}

// A mirror (y = 0) hit at 45°: the reflected ray starts 0.001 along the normal, on the viewer's
// side, not 0.001 along its own direction.
TEST(CourseConventions, ReflectionRayStartsAlongTheNormal) {
    const Scene s = sceneFrom(
        "camera { location <0,0,10> up <0,1,0> right <1,0,0> look_at <0,0,0> }\n"
        "plane { <0,1,0>, 0 pigment { color rgb 1 } finish { reflection 1 } }\n");
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    std::vector<TraceRecord> log;
    Tracer(s, bvh, rs).tracePrimary(Ray{{-1, 1, 0}, normalize(Vec3{1, -1, 0})}, ctx, &log);
    ASSERT_EQ(log.size(), 2u);
    EXPECT_EQ(log[1].kind, TraceRecord::Kind::Reflection);
    expectVec(log[1].ray.origin, {0, 0.001, 0}, 1e-12, "reflection origin");
    expectVec(log[1].ray.dir, normalize(Vec3{1, 1, 0}), 1e-12, "reflection direction");
    // From below, the viewer's side is below.
    log.clear();
    Tracer(s, bvh, rs).tracePrimary(Ray{{-1, -1, 0}, normalize(Vec3{1, 1, 0})}, ctx, &log);
    ASSERT_EQ(log.size(), 2u);
    expectVec(log[1].ray.origin, {0, -0.001, 0}, 1e-12, "reflection origin from below");
}

// A clear plane (y = 0, ior 1.5) entered at 45° from above: the refracted ray starts 0.001 along
// the normal on the far side, whatever its direction.
TEST(CourseConventions, RefractionRayStartsOnTheFarSide) {
    const Scene s = sceneFrom(
        "camera { location <0,0,10> up <0,1,0> right <1,0,0> look_at <0,0,0> }\n"
        "plane { <0,1,0>, 0 pigment { color rgbf <1,1,1,1> } finish { ior 1.5 } }\n");
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    std::vector<TraceRecord> log;
    Tracer(s, bvh, rs).tracePrimary(Ray{{-1, 1, 0}, normalize(Vec3{1, -1, 0})}, ctx, &log);
    ASSERT_EQ(log.size(), 2u);
    EXPECT_EQ(log[1].kind, TraceRecord::Kind::Refraction);
    expectVec(log[1].ray.origin, {0, -0.001, 0}, 1e-12, "refraction origin");
    // Snell: sin θt = sin 45° / 1.5.
    const double st = std::sqrt(0.5) / 1.5;
    expectVec(log[1].ray.dir, {st, -std::sqrt(1 - st * st), 0}, 1e-12, "refraction direction");
}

// A white diffuse floor (y = 0) seen from straight above, lit by a light at (0, 10, 10), so
// N·L = cos 45°. A sphere of radius 0.0004 sits on the line from the offset point (0, 0.001, 0)
// to the light, 0.01 before the light. Aimed from the offset point, the shadow ray goes through
// the sphere's centre: the floor is black. (A ray from the offset point parallel to the direction
// from the un-offset hit point passes 0.001·sin 45° ≈ 0.0007 from the centre and would miss it.)
TEST(CourseConventions, ShadowRayIsAimedFromTheOffsetPoint) {
    const Vec3 light{0, 10, 10}, origin{0, 0.001, 0};
    const Vec3 c = light - 0.01 * normalize(light - origin);
    char blocker[160];
    std::snprintf(blocker, sizeof blocker, "sphere { <%.17g, %.17g, %.17g>, 0.0004 pigment { color rgb 1 } }\n", c.x,
                  c.y, c.z);
    const std::string base =
        "camera { location <0,0,10> up <0,1,0> right <1,0,0> look_at <0,0,0> }\n"
        "light_source { <0, 10, 10> color rgb 1 }\n"
        "plane { <0,1,0>, 0 pigment { color rgb 1 } finish { diffuse 1 } }\n";
    const Ray down{{0, 5, 0}, {0, -1, 0}};
    const RenderSettings rs;
    auto colorOf = [&](const std::string& text) {
        const Scene s = sceneFrom(text);
        const Bvh bvh(s.objects);
        TraceContext ctx;
        return Tracer(s, bvh, rs).tracePrimary(down, ctx);
    };
    expectVec(colorOf(base), Vec3(std::sqrt(0.5)), 1e-12, "lit without the blocker");
    expectVec(colorOf(base + blocker), Vec3(0.0), 0, "blocked by the tiny sphere");
}

// Global illumination's ambient term. A floor triangle with kd 0 at the centre of a big sphere
// (radius 100, ambient 0.5, diffuse 0.8, pigment (1, 0.5, 0.25)) with a white light at the big
// sphere's centre, 0.5 above the floor. Every sample ray from the floor goes up and meets the
// big sphere's inside where N·L = 1 and nothing shadows it; with one GI level that hit is at the
// last level (no ambient): each sample brings 0.8·(1, 0.5, 0.25). The floor's colour is then E,
// their plain mean (not kd·C·E = 0, the floor's kd being 0), and no diffuse of its own.
TEST(CourseConventions, GlobalIlluminationAmbientIsThePlainMean) {
    const Scene s = sceneFrom(
        "camera { location <0,5,0> up <0,0,1> right <1,0,0> look_at <0,0,0> }\n"
        "light_source { <0, 0.5, 0> color rgb 1 }\n"
        "triangle { <-1,0,-1>, <1,0,-1>, <0,0,1> pigment { color rgb 0.5 } finish { ambient 0.3 diffuse 0 } }\n"
        "sphere { <0,0.5,0>, 100 pigment { color rgb <1,0.5,0.25> } finish { ambient 0.5 diffuse 0.8 } }\n");
    const Bvh bvh(s.objects);
    RenderSettings rs;
    rs.gi = true;
    rs.giBounces = 1;
    rs.giSamples[0] = 16;
    const Ray down{{0, 5, 0}, {0, -1, 0}};
    TraceContext ctx;
    expectVec(Tracer(s, bvh, rs).tracePrimary(down, ctx), {0.8, 0.4, 0.2}, 1e-9, "course GI");
    // The physically based estimator weighs E by the floor's kd·C: 0.
    rs.giPhysical = true;
    expectVec(Tracer(s, bvh, rs).tracePrimary(down, ctx), Vec3(0.0), 1e-12, "physical GI");
    // Without GI: the floor's ka·C.
    rs.gi = false;
    expectVec(Tracer(s, bvh, rs).tracePrimary(down, ctx), Vec3(0.15), 1e-12, "no GI");
}

// Two GI levels on the same scene: a sample's hit on the big sphere (level 1) is its direct
// light 0.8·C (C = (1, 0.5, 0.25)) plus E', the plain mean of what its own samples bring; those
// hits (level 2, the last) have no ambient term, so each brings at most 0.8·C (less where the
// floor shadows the big sphere, nothing from the floor, whose kd is 0). The floor, E of the
// level-1 hits, lies strictly between 0.8·C (E' = 0) and 1.6·C.
TEST(CourseConventions, GlobalIlluminationTwoLevels) {
    const Scene s = sceneFrom(
        "camera { location <0,5,0> up <0,0,1> right <1,0,0> look_at <0,0,0> }\n"
        "light_source { <0, 0.5, 0> color rgb 1 }\n"
        "triangle { <-1,0,-1>, <1,0,-1>, <0,0,1> pigment { color rgb 0.5 } finish { ambient 0.3 diffuse 0 } }\n"
        "sphere { <0,0.5,0>, 100 pigment { color rgb <1,0.5,0.25> } finish { ambient 0.5 diffuse 0.8 } }\n");
    const Bvh bvh(s.objects);
    RenderSettings rs;
    rs.gi = true;
    rs.giSamples[0] = 16;
    rs.giSamples[1] = 16;
    TraceContext ctx;
    const Vec3 c = Tracer(s, bvh, rs).tracePrimary(Ray{{0, 5, 0}, {0, -1, 0}}, ctx);
    const Vec3 C{1, 0.5, 0.25};
    for (int k = 0; k < 3; ++k) {
        EXPECT_GT(c[k], 0.8 * C[k] * 1.1) << k;  // the upper half of the big sphere alone is lit
        EXPECT_LT(c[k], 1.6 * C[k]) << k;
    }
}

// A reflection ray starts the GI levels again. A floor (y = 0, diffuse) under a mirror ceiling
// (y = 1); one GI level, 4 samples, recursion limit 6. Every sample ray from the floor meets the
// mirror, whose reflected ray comes down to the floor again. Restarted at level 0 there, it
// gathers 4 samples again, as long as the depth allows (a sample and a reflection each add 1):
// floor gathers at depths 0, 2, 4, 6 (4 + 16 + 64 + 256 samples) and the mirror reflects at
// depths 1, 3, 5 (4 + 16 + 64 rays): 424 secondary rays. Were the level kept, the floor hit by
// a reflected sample (level 1, the last) would gather nothing: 8 rays.
TEST(CourseConventions, ReflectionRaysRestartTheGiLevel) {
    const Scene s = sceneFrom(
        "camera { location <0,0.5,0> up <0,0,1> right <1,0,0> look_at <0,0,0> }\n"
        "light_source { <0, 0.5, 0> color rgb 1 }\n"
        "plane { <0,1,0>, 0 pigment { color rgb 1 } finish { diffuse 0.5 } }\n"
        "plane { <0,-1,0>, -1 pigment { color rgb 1 } finish { reflection 1 } }\n");
    const Bvh bvh(s.objects);
    RenderSettings rs;
    rs.gi = true;
    rs.giBounces = 1;
    rs.giSamples[0] = rs.giSamples[1] = 4;
    rs.maxDepth = 6;
    TraceContext ctx;
    Tracer(s, bvh, rs).tracePrimary(Ray{{0, 0.5, 0}, {0, -1, 0}}, ctx);
    EXPECT_EQ(ctx.stats.secondaryRays, 424u);
}

// The GI samples' fast direction map gives cosineHemisphere()'s directions (same concentric map,
// sin and cos by series within π/4), unit length, on n's side; over a stratified grid their mean
// is n·2/3 as a cosine-weighted hemisphere's must be (E[cos θ] = 2/3).
TEST(CourseConventions, GiSampleDirectionsAreCosineHemisphere) {
    for (const Vec3 n : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, normalize(Vec3{1, -2, 0.5}), normalize(Vec3{-0.3, 0.1, -0.9})}) {
        const CosineHemisphere hemisphere(n);
        const int k = 64;
        double meanCos = 0;
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j) {
                const double a = (i + 0.37) / k, b = (j + 0.61) / k;
                const Vec3 d = hemisphere(a, b);
                expectVec(d, cosineHemisphere(n, a, b), 1e-9, "same direction");
                EXPECT_NEAR(length(d), 1.0, 1e-12);
                EXPECT_GE(dot(d, n), 0.0);
                meanCos += dot(d, n);
            }
        EXPECT_NEAR(meanCos / (k * k), 2.0 / 3.0, 1e-3);
    }
    double c, s;
    for (double th = -std::numbers::pi / 4; th <= std::numbers::pi / 4; th += 0.001) {
        sinCosQuarter(th, c, s);
        EXPECT_NEAR(c, std::cos(th), 1e-11);
        EXPECT_NEAR(s, std::sin(th), 1e-11);
    }
}

}}  // namespace RAYS_TEST_UNIT, namespace
