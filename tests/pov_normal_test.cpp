// POV-Ray normal patterns (src/rays/pattern/normal, pov/normal_compile): the tilt of the shading
// normal for patterns sampled by their gradient, bump_size, slope_map, waves and transformations,
// normal identifiers, and renders compared against povray 3.7's pixels. Expected pixels were
// rendered by povray 3.7.0.10 with `+FP16 File_Gamma=1.0` (linear 16-bit values) and
// `global_settings { assumed_gamma 1 }`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "rays/accel/bvh.h"
#include "rays/io/image_io.h"
#include "rays/pov/load_pov.h"
#include "support/pov_scene.h"
#include "support/process.h"
#include "support/tiny_images.h"
#include "rays/render/renderer.h"
#include "rays/render/tracer.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

constexpr double kMeasured = 2e-4;  // povray's 16-bit output

using Loaded = test::PovLoaded;

Loaded load(const std::string& body) {
    return test::loadPov(body, "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n");
}

// The working-space colour seen along the ray of an orthographic camera at z = −5 looking along +z.
Vec3 seen(const Scene& s, double x, double y) {
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    return Tracer(s, bvh, rs).tracePrimary(Ray{{x, y, -5}, {0, 0, 1}}, ctx);
}

// A white plane facing the camera at z = 0.5, lit by diffuse 1 only from a parallel light along
// <lx, 0, −1>: the brightness is the cosine between the shading normal and the light.
std::string litPlane(const std::string& normal, double lx) {
    return "light_source { <" + std::to_string(lx) + ", 0, -1>*1000 color 1 parallel point_at 0 }\n" +
           "plane { -z, -0.5 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { " + normal + " } }\n";
}

double planeBrightness(const std::string& normal, double lx, double x = 0.35) {
    const Loaded l = load(litPlane(normal, lx));
    return seen(l.scene, x, 0.2).x;
}

TEST(PovNormal, GradientTiltsTheNormalAgainstThePatternByTwoFifteenthsOfTheAmount) {
    // povray: a light from <1,0,-1> sees 0.6074 (flat: 0.7071), from <-1,0,-1> 0.7944, from -z 0.9912.
    EXPECT_NEAR(planeBrightness("gradient x 1", 1), 0.6074, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 1", -1), 0.7944, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 1", 0), 0.9912, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 10", 0), 0.6000, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 100", 0), 0.0748, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 2", 1), 0.5010, kMeasured);
    // The normal itself: (−2/15, 0, −1) normalised on the plane facing −z.
    const Loaded l = load(litPlane("gradient x 1", 1));
    const PovSurface& s = l.scene.povSurfaces.at(size_t(l.scene.objects.at(0).material.pov));
    ASSERT_GE(s.normal, 0);
    const Vec3 n = l.scene.normals.atRoot(l.scene.pigments, s.normal, {0.3, 0.2, 0.5}, {0, 0, -1});
    const Vec3 want = normalize(Vec3{-2.0 / 15.0, 0, -1});
    EXPECT_NEAR(n.x, want.x, 1e-6);
    EXPECT_NEAR(n.y, want.y, 1e-6);
    EXPECT_NEAR(n.z, want.z, 1e-6);
}

// Across a step the four samples cross one after another, so the bands the step shows place the
// tetrahedron: a step up at x = 0.5 (accuracy 0.1) gives a band 0.094 wide where only the +x
// sample has crossed, then one 0.047 wide where the +y sample has too; a step in y one band
// 0.133 wide. povray, lit by parallel lights along <1,0,−1> and <0,1,−1> (flat: 0.7071).
TEST(PovNormal, PatternGradientSamplesPovRaysTetrahedron) {
    auto brightness = [](const char* axis, double lx, double ly, double x, double y) {
        const std::string light = "light_source { <" + std::to_string(lx) + ", " + std::to_string(ly) +
                                  ", -1>*1000 color 1 parallel point_at 0 }\n";
        const Loaded l = load(light + "plane { -z, -0.5 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { "
                                      "pigment_pattern { gradient " + axis +
                              " color_map { [0.5 rgb 0][0.5 rgb 1] } } 0.5 accuracy 0.1 } }\n");
        return seen(l.scene, x, y).x;
    };
    EXPECT_NEAR(brightness("x", 1, 0, 0.4525, 0.5), 0.3343, kMeasured);
    EXPECT_NEAR(brightness("x", 1, 0, 0.5275, 0.5), 0.3237, kMeasured);
    EXPECT_NEAR(brightness("x", 0, 1, 0.4525, 0.5), 0.7379, kMeasured);
    EXPECT_NEAR(brightness("x", 0, 1, 0.5275, 0.5), 0.4083, kMeasured);
    EXPECT_NEAR(brightness("x", 0, 1, 0.5525, 0.5), 0.7071, kMeasured);
    EXPECT_NEAR(brightness("y", 1, 0, 0.5, 0.4525), 0.6325, kMeasured);
    EXPECT_NEAR(brightness("y", 0, 1, 0.5, 0.4125), 0.3162, kMeasured);
    EXPECT_NEAR(brightness("y", 0, 1, 0.5, 0.5275), 0.3162, kMeasured);
    EXPECT_NEAR(brightness("y", 0, 1, 0.5, 0.3875), 0.7071, kMeasured);
}

// object { OBJECT normal { A }, normal { B } }: A outside, B inside (povray: 0.6074 outside, as
// gradient x 1 alone, 0.5010 inside, as gradient x 2 alone).
TEST(PovNormal, ObjectPatternTiltsByItsOutsideAndInsideNormals) {
    const std::string n = "object { sphere { <0, 0, 0.5>, 1 } normal { gradient x 1 }, normal { gradient x 2 } }";
    EXPECT_NEAR(planeBrightness(n, 1, 0.35), 0.5010, kMeasured);
    EXPECT_NEAR(planeBrightness(n, 1, 1.5), 0.6074, kMeasured);
    EXPECT_TRUE(load(litPlane(n, 1)).warnings.empty());
}

TEST(PovNormal, BumpSizeZeroAndGradientsAlongTheNormalChangeNothing) {
    EXPECT_NEAR(planeBrightness("gradient x 1 bump_size 0", 1), std::sqrt(0.5), 1e-9);
    EXPECT_NEAR(planeBrightness("gradient x 0", 1), std::sqrt(0.5), 1e-9);
    EXPECT_NEAR(planeBrightness("gradient z 1", 0), 1.0, 1e-9);  // povray: 1
    // <1,0,1>: the whole gradient is subtracted from the normal (povray: 0.9963 from -z).
    EXPECT_NEAR(planeBrightness("gradient <1,0,1> 1", 0), 0.9963, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient <1,0,1> 1", 1), 0.6438, kMeasured);
}

TEST(PovNormal, WaveFrequencySlopeMapAndTransformationsShapeTheTilt) {
    EXPECT_NEAR(planeBrightness("gradient x 1 frequency 2", 1), 0.5010, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 1 triangle_wave", 1, 0.35), 0.5010, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 1 triangle_wave", 1, 0.65), 0.8654, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 1 slope_map { [0 <0, 2>] [1 <2, 2>] }", 1), 0.5010, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 1 slope_map { [0 <0, 1>] [1 <1, 1>] }", 1), 0.6074, kMeasured);
    // Cubic between the entries, the slopes per unit of the segment (povray at x = 0.05 ... 0.45;
    // where the curve bends, the sampled gradients differ by up to 3e-3).
    const std::string smooth = "gradient x 1 slope_map { [0 <0, 0>] [1 <1, 0>] }";
    EXPECT_NEAR(planeBrightness(smooth, 1, 0.05), 0.6773, 4e-3);
    EXPECT_NEAR(planeBrightness(smooth, 1, 0.45), 0.5561, 4e-3);
    const std::string tri = "gradient x 1 slope_map { [0 <0, 1>] [0.5 <1, 1>] [0.5 <1, -1>] [1 <0, -1>] }";
    EXPECT_NEAR(planeBrightness(tri, 1, 0.15), 0.5010, kMeasured);
    EXPECT_NEAR(planeBrightness(tri, 1, 0.85), 0.8654, kMeasured);
    const std::string ends = "gradient x 1 slope_map { [0 <0, 5>] [1 <0, 5>] }";
    EXPECT_NEAR(planeBrightness(ends, 1, 0.45), 0.8910, 4e-3);
    // A uniform scale keeps the depth; a scale along x steepens it (povray).
    EXPECT_NEAR(planeBrightness("gradient x 1 scale 0.5", 1), 0.6074, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 1 scale <0.5, 1, 1>", 1), 0.5010, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient y 1", 1), 0.7009, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient <1, 1, 0> 1", 1), 0.6348, kMeasured);
}

TEST(PovNormal, NoBumpScaleTiltsByTheWorldGradient) {
    // povray 3.7, gradient x 0.5 lit from <-1, 0, -1>: 0.75257 plain (a tilt of 1/15), scaled
    // 0.25 with no_bump_scale 0.86543 (4/15), scaled 2 with it 0.73027 (1/30); a scale along x
    // steepens it with or without (0.79435, 2/15); unscaled it changes nothing.
    EXPECT_NEAR(planeBrightness("gradient x 0.5 scale 0.25", -1), 0.75257, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 0.5 scale 0.25 no_bump_scale", -1), 0.86543, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 0.5 scale 2 no_bump_scale", -1), 0.73027, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 0.5 scale <0.5, 1, 1> no_bump_scale", -1), 0.79435, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 0.5 scale <1, 0.5, 1> no_bump_scale", -1), 0.75257, kMeasured);
    EXPECT_NEAR(planeBrightness("gradient x 0.5 no_bump_scale", -1), 0.75257, kMeasured);
    // The object's scale counts as the normal's own (povray: 0.75257 without, 0.86543 with).
    for (const bool flag : {false, true}) {
        const Loaded l = load(std::string("light_source { <-1, 0, -1>*1000 color 1 parallel point_at 0 }\n") +
                              "plane { -z, -2 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { gradient x 0.5 " +
                              (flag ? "no_bump_scale" : "") + " } scale 0.25 }\n");
        EXPECT_NEAR(seen(l.scene, 0.35, 0.2).x, flag ? 0.86543 : 0.75257, kMeasured) << flag;
    }
}

TEST(PovNormal, IdentifiersBumpSizeAndPlacesOfTheNormal) {
    const std::string light = "light_source { <1, 0, -1>*1000 color 1 parallel point_at 0 }\n";
    const std::string plane = "plane { -z, -0.5 ";
    const std::string fin = " finish { ambient 0 diffuse 1 } ";
    // #declare, bump_size overriding the identifier's amount, inside a texture, directly on the object.
    const Loaded a = load("#declare N = normal { gradient x 1 }\n" + light + plane + "pigment { rgb 1 }" + fin +
                          "normal { N bump_size 2 } }\n");
    EXPECT_NEAR(seen(a.scene, 0.35, 0.2).x, 0.5010, kMeasured);
    const Loaded b = load(light + plane + "texture { pigment { rgb 1 } normal { gradient x 1 }" + fin + "} }\n");
    EXPECT_NEAR(seen(b.scene, 0.35, 0.2).x, 0.6074, kMeasured);
    // Transformations after the normal (in the texture, on the object) move it too.
    const Loaded c = load(light + plane + "texture { pigment { rgb 1 } normal { gradient x 1 }" + fin +
                          "scale <0.5, 1, 1> } }\n");
    EXPECT_NEAR(seen(c.scene, 0.35, 0.2).x, 0.5010, kMeasured);
    for (const Loaded* l : {&a, &b, &c})
        for (const std::string& w : l->warnings) EXPECT_EQ(w.find("normal"), std::string::npos) << w;
}

TEST(PovNormal, UnrenderedNormalsAreNotedAndDrawnSmooth) {
    const Loaded l = load("light_source { <1, 0, -1>*1000 color 1 parallel point_at 0 }\n"
                          "plane { -z, -0.5 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { tiling 26 } }\n");
    ASSERT_EQ(l.warnings.size(), 1u);
    EXPECT_EQ(l.warnings[0], "scene.pov:4:76: warning: not rendered yet: normal pattern tiling 26 (drawn smooth)");
    EXPECT_NEAR(seen(l.scene, 0.35, 0.2).x, std::sqrt(0.5), 1e-9);
}

TEST(PovNormal, QuiltedTiltsAlongTheOffsetFromTheCubesCentreAsPovRayDoes) {
    // povray 3.7 (measured on the lit plane): the normal plus amount·B(|d|)·d·2/√3, d the point's
    // offset from its unit cube's centre, B the control0/control1 curve.
    EXPECT_NEAR(planeBrightness("quilted 1", 1, 0.35), 0.59858, kMeasured);
    EXPECT_NEAR(planeBrightness("quilted 1", 1, 0.9), 0.88621, kMeasured);
    EXPECT_NEAR(planeBrightness("quilted 1", 1, -0.3), 0.79115, kMeasured);
    EXPECT_NEAR(planeBrightness("quilted 1", 0, 0.05), 0.87100, kMeasured);
    EXPECT_NEAR(planeBrightness("quilted 2 control0 0.5 control1 1", 1, 0.7), 0.80459, kMeasured);
    EXPECT_NEAR(planeBrightness("quilted 1 translate z*0.2", -1, 0.35), 0.76323, kMeasured);
    EXPECT_NEAR(planeBrightness("quilted 0.6 scale 0.5", 1, 0.35), 0.77037, kMeasured);
    EXPECT_TRUE(load(litPlane("quilted 1", 1)).warnings.empty());
}

TEST(PovNormal, SpiralsTakeTheirAmountAfterTheArms) {
    // povray 3.7 on the lit plane: `spiral2 5, 1.0` as `spiral2 5 1.0`; without an amount 0.5. The
    // five arms' steep, kinked value makes the sampled gradients differ by up to 2e-3 (the amounts'
    // pixels are 5e-3 apart).
    constexpr double kSampled = 2.5e-3;
    EXPECT_NEAR(planeBrightness("spiral2 5, 1.0", 1, 0.35), 0.78102, kSampled);
    EXPECT_NEAR(planeBrightness("spiral2 5 1.0", 1, 0.35), 0.78102, kSampled);
    EXPECT_NEAR(planeBrightness("spiral2 5", 1, 0.35), 0.78579, kSampled);
    EXPECT_GT(planeBrightness("spiral2 5", 1, 0.35) - planeBrightness("spiral2 5, 1.0", 1, 0.35), 4e-3);
}

TEST(PovNormal, ASurfaceSeenFromBehindTiltsAsOneSeenFromTheFront) {
    // POV-Ray tilts the normal facing the viewer: plane { z, 0.5 } (its normal pointing away from
    // the camera) gives the pixels of plane { -z, -0.5 } (povray 3.7: 0.6074 for both, gradient and
    // quilted; 0.8836 at x = 0.9, y = 0.3 for quilted).
    for (const char* plane : {"plane { -z, -0.5 ", "plane { z, 0.5 ", "plane { z, 0.5 clipped_by { box { -10, 10 } } "}) {
        auto at = [&](const std::string& normal, double x, double y) {
            const Loaded l = load(std::string("light_source { <1, 0, -1>*1000 color 1 parallel point_at 0 }\n") + plane +
                                  "pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { " + normal + " } }\n");
            return seen(l.scene, x, y).x;
        };
        EXPECT_NEAR(at("gradient x 1", 0.35, 0.2), 0.6074, kMeasured) << plane;
        EXPECT_NEAR(at("quilted 1 translate z*0.2", 0.35, 0.2), 0.6074, kMeasured) << plane;
        EXPECT_NEAR(at("quilted 1 translate z*0.2", 0.9, 0.3), 0.8836, kMeasured) << plane;
    }
}

TEST(PovNormal, SphereWithATransformedGradientMatchesPovRaysPixels) {
    // povray 3.7, 8×8 orthographic render of x, y in [−1, 1]; 0 where the ray misses.
    const Loaded l = load(
        "light_source { <-2, 3, -4>*100 color 1 }\n"
        "sphere { 0, 1 pigment { rgb 1 } finish { ambient 0 diffuse 0.8 phong 0.5 }\n"
        "  normal { gradient x 3 translate 0.5*x scale <3,1.5,3> rotate z*30 } }\n");
    const double pov[8][8] = {{0, 0, 0.6905, 0.7558, 0.7390, 0.6140, 0, 0},
                              {0, 0.6869, 0.7686, 0.7946, 0.7986, 0.7224, 0.5513, 0},
                              {0.5167, 0.6641, 0.7173, 0.7360, 0.9003, 0.6633, 0.5284, 0.1600},
                              {0.4759, 0.5818, 0.6242, 0.6327, 0.6096, 0.5457, 0.4132, 0.1193},
                              {0.3707, 0.4702, 0.5071, 0.5088, 0.4769, 0.4019, 0.2581, 0},
                              {0.2074, 0.3315, 0.3681, 0.3641, 0.3223, 0.2328, 0.0686, 0},
                              {0, 0.1457, 0.1967, 0.1896, 0.1360, 0.0250, 0, 0},
                              {0, 0, 0, 0, 0, 0, 0, 0}};
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) {
            if (pov[j][i] == 0) continue;
            const double x = -1 + (i + 0.5) / 4, y = 1 - (j + 0.5) / 4;
            // The finite-difference gradient and povray's agree to about 1e-3 (stated tolerance).
            EXPECT_NEAR(seen(l.scene, x, y).x, pov[j][i], 2e-3) << i << "," << j;
        }
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

// The mean absolute deviation from the median of the lit plane's brightness (light from <1,0,-1>)
// over a 48×48 grid of x, y in [−3, 3]: how strongly a noise-like normal tilts.
double tiltSpread(const std::string& normal) {
    const Loaded l = load("light_source { <1, 0, -1>*1000 color 1 parallel point_at 0 }\n"
                          "plane { -z, -0.37 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { " + normal + " } }\n");
    const Bvh bvh(l.scene.objects);
    const RenderSettings rs;
    const Tracer tracer(l.scene, bvh, rs);
    std::vector<double> v;
    for (int j = 0; j < 48; ++j)
        for (int i = 0; i < 48; ++i) {
            TraceContext ctx;
            v.push_back(tracer.tracePrimary(Ray{{-3 + i / 8.0, -3 + j / 8.0, -5}, {0, 0, 1}}, ctx).x);
        }
    std::vector<double> sorted = v;
    std::sort(sorted.begin(), sorted.end());
    const double median = sorted[sorted.size() / 2];
    double mad = 0;
    for (double x : v) mad += std::fabs(x - median);
    return mad / double(v.size());
}

// The shading normal's x and y over an n × n grid of the plane z = 0 (facing −z), `step` apart from
// (x0, y0), recovered from three parallel lights as povray's normals were measured: along the view
// (brightness −n_z) and from 45° towards +x and +y ((n_x − n_z)/√2, (n_y − n_z)/√2).
struct NormalField {
    std::vector<double> x, y;
};
NormalField normalField(const std::string& normal, int n, double step, double x0 = -24, double y0 = -24) {
    const char* lights[3] = {"<0, 0, -1000>", "<1000, 0, -1000>", "<0, 1000, -1000>"};
    std::vector<double> b[3];
    for (int l = 0; l < 3; ++l) {
        const Loaded s = load(std::string("light_source { ") + lights[l] + " color 1 parallel point_at 0 }\n" +
                              "plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { " + normal + " } }\n");
        const Bvh bvh(s.scene.objects);
        const RenderSettings rs;
        const Tracer tracer(s.scene, bvh, rs);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                TraceContext ctx;
                b[l].push_back(tracer.tracePrimary(Ray{{x0 + i * step, y0 + j * step, -5}, {0, 0, 1}}, ctx).x);
            }
    }
    NormalField f;
    for (size_t k = 0; k < b[0].size(); ++k) {
        f.x.push_back(std::sqrt(2.0) * b[1][k] - b[0][k]);
        f.y.push_back(std::sqrt(2.0) * b[2][k] - b[0][k]);
    }
    return f;
}

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / double(v.size());
}

// bumps, dents and wrinkles add a vector noise to the normal (bumps: the noise itself, so the tilt
// keeps its direction over half a unit, where a gradient's turns round; dents: times the noise
// cubed; wrinkles: ten octaves of its components' absolute values, leaning one way). povray 3.7,
// a 480 × 480 orthographic view of 48 × 48 units (256 × 256 of 8 × 8 for the correlation), the
// normal recovered per pixel from the same three lights: bumps 1 tilts by 0.327 on average,
// bumps 0.5's x tilt correlates 0.48 with itself half a unit along x, dents 1 tilts by 0.055 on
// average, wrinkles 1 leans to n_x 0.508 and n_y 0.505.
TEST(PovNormal, NoiseNormalsTiltAsPovRaysDoOnAverage) {
    auto meanTilt = [](const NormalField& f) {
        double s = 0;
        for (size_t k = 0; k < f.x.size(); ++k) s += std::hypot(f.x[k], f.y[k]);
        return s / double(f.x.size());
    };
    EXPECT_NEAR(meanTilt(normalField("bumps 1", 96, 0.5)), 0.327, 0.05);
    EXPECT_NEAR(meanTilt(normalField("dents 1", 96, 0.5)), 0.055, 0.015);
    const NormalField wrinkles = normalField("wrinkles 1", 64, 0.75);
    EXPECT_NEAR(mean(wrinkles.x), 0.508, 0.08);
    EXPECT_NEAR(mean(wrinkles.y), 0.505, 0.08);
    // Correlation of the x tilt with itself half a unit along x (16 of 32 points a unit).
    const int n = 64;
    const NormalField b = normalField("bumps 0.5", n, 1.0 / 32, -1, -1);
    const double m = mean(b.x);
    double cov = 0, var = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double a = b.x[size_t(j * n + i)] - m;
            var += a * a;
            if (i + 16 < n) cov += a * (b.x[size_t(j * n + i + 16)] - m) * double(n) / double(n - 16);
        }
    EXPECT_GT(cov / var, 0.2);
}

TEST(PovNormal, SpecialisedNormalsTiltAboutAsMuchAsPovRays) {
    // povray 3.7, the same plane seen by a 64×64 perspective camera at −5z (mean |b − median|).
    // Rays' noise is not POV-Ray's: only the strength is compared (±30%). (Ripples and waves are
    // POV-Ray's point for point: RipplesAndWavesTiltAsPovRaysPointForPoint.)
    const struct {
        const char* normal;
        double pov;
    } cases[] = {{"bumps 1", 0.1436}, {"dents 1", 0.0251}, {"wrinkles 1", 0.0894}, {"ripples 1", 0.0982},
                 {"waves 1", 0.2173}, {"bumps 0.3 scale 0.2", 0.0457}, {"granite 1", 0.2126},
                 {"bumps 1 turbulence 0.5", 0.1420},
                 // povray 3.7, a 48×48 orthographic view of the same grid (8-bit, sRGB decoded):
                 // waves' tilt at small amounts, where the brightness follows it linearly
                 {"waves 0.1", 0.0211}, {"waves 0.1 frequency 4", 0.0218}};
    for (const auto& c : cases) EXPECT_NEAR(tiltSpread(c.normal), c.pov, 0.3 * c.pov) << c.normal;
    // ripples' and waves' tilt does not grow with the frequency: rings a world unit apart from a
    // huge scale and frequency stay calm (povray: 0.0549; Rays' centres interfere otherwise).
    const double huge = tiltSpread("ripples 1 scale 100000 frequency 100000");
    EXPECT_GT(huge, 0.0549 / 3);
    EXPECT_LT(huge, 0.0549 * 3);
}


// povray 3.7: a white plane z = 0 seen by an orthographic camera from −z, lit along the view by a
// light at <0, 0, −10⁶> (diffuse 1, 16-bit linear output): the brightness is the cosine of the
// tilt. Ripples with number_of_waves 1 and waves with the default ten sources, at two pixels.
TEST(PovNormal, RipplesAndWavesTiltAsPovRaysPointForPoint) {
    const auto at = [](const std::string& settings, const std::string& normal, double x, double y) {
        const Loaded l = load(settings + "light_source { <0, 0, -1e6> color 1 }\n"
                                         "plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } normal { " +
                              normal + " } }\n");
        return seen(l.scene, x, y).x;
    };
    const std::string oneWave = "global_settings { number_of_waves 1 }\n";
    EXPECT_NEAR(at(oneWave, "ripples 1", 0.02, -0.02), 0.992950, kMeasured);
    EXPECT_NEAR(at(oneWave, "ripples 1", 2.02, 2.5), 0.755947, kMeasured);
    EXPECT_NEAR(at("", "waves 1", 0.02, -0.02), 0.854124, kMeasured);
    EXPECT_NEAR(at("", "waves 1", 2.02, 2.5), 0.979950, kMeasured);
}

// A normal block without a pattern of its own modifies the normal the look already has (the
// default texture's here). povray 3.7, the plane of litPlane seen at (0.35, 0.2) under
// `#default { normal { gradient x 1 } }`: `normal { }` and `normal { scale 0.5 }` 0.6074 (the
// default's), `normal { slope_map { [0 <0,-1>] [1 <1,-1>] } }` 0.5284.
TEST(PovNormal, ABlockWithoutAPatternModifiesTheNormalBelow) {
    const std::string light = "light_source { <1, 0, -1>*1000 color 1 parallel point_at 0 }\n";
    const std::string plane = "plane { -z, -0.5 pigment { rgb 1 } finish { ambient 0 diffuse 1 } ";
    const auto brightness = [&](const std::string& normal) {
        const Loaded l = load("#default { normal { gradient x 1 } }\n" + light + plane + "normal { " + normal + " } }\n");
        return seen(l.scene, 0.35, 0.2).x;
    };
    EXPECT_NEAR(brightness(""), 0.6074, kMeasured);
    EXPECT_NEAR(brightness("scale 0.5"), 0.6074, kMeasured);
    const std::string slopeMap = "slope_map { [0 <0,-1>] [1 <1,-1>] }";
    // (a bending cubic between the entries: sampled gradients differ by up to 3e-3, as above)
    EXPECT_NEAR(brightness(slopeMap), 0.5284, 4e-3);
    // Each object's block modifies its own copy: the second object is not drawn with the first's.
    const Loaded two = load("#default { normal { gradient x 1 } }\n" + light + plane + "normal { } translate 10*z }\n" +
                            plane + "normal { " + slopeMap + " } }\n");
    EXPECT_NEAR(seen(two.scene, 0.35, 0.2).x, 0.5284, 4e-3);
    // A block with its own pattern replaces the normal below.
    EXPECT_NEAR(brightness("gradient x 2"), 0.5010, kMeasured);
}

// A block with a pattern but no amount of its own keeps the amount of the normal it replaces
// (povray 3.7: under `#default { normal { bump_size 1.5 } }`, `normal { gradient x }` gives the same
// image as `normal { gradient x 1.5 }`, 196 of 255 against 212 without the default). An amount
// written in the block wins.
TEST(PovNormal, APatternWithoutAnAmountKeepsTheAmountBelow) {
    const std::string light = "light_source { <1, 0, -1>*1000 color 1 parallel point_at 0 }\n";
    const std::string plane = "plane { -z, -0.5 pigment { rgb 1 } finish { ambient 0 diffuse 1 } ";
    const auto brightness = [&](const std::string& defaults, const std::string& normal) {
        const Loaded l = load(defaults + light + plane + "normal { " + normal + " } }\n");
        return seen(l.scene, 0.35, 0.2).x;
    };
    const std::string bigger = "#default { normal { bump_size 1.5 } }\n";
    EXPECT_NEAR(brightness(bigger, "gradient x"), brightness("", "gradient x 1.5"), 1e-12);
    EXPECT_NEAR(brightness(bigger, "gradient x 0.5"), brightness("", "gradient x 0.5"), 1e-12);
    EXPECT_NEAR(brightness("", "gradient x"), brightness("", "gradient x 0.5"), 1e-12);
    EXPECT_GT(std::fabs(brightness("", "gradient x 1.5") - brightness("", "gradient x 0.5")), 0.01);
    // A normal_map's entries without amounts keep it too (povray: 196 at x = 0.875, 212 without
    // the default); the map's own bump_size does not scale them.
    const auto at = [&](const std::string& defaults, const std::string& normal) {
        const Loaded l = load(defaults + light + plane + "normal { " + normal + " } }\n");
        return seen(l.scene, 0.875, 0.2).x;
    };
    const std::string map = "gradient x normal_map { [0.3 gradient y] [0.7 gradient x] }";
    EXPECT_NEAR(at(bigger, map), at("", "gradient x 1.5"), 1e-12);
    EXPECT_NEAR(at("", map), at("", "gradient x 0.5"), 1e-12);
    EXPECT_NEAR(at("", "gradient x bump_size 1.5 normal_map { [0.3 gradient y] [0.7 gradient x] }"),
                at("", "gradient x 0.5"), 1e-12);
}

// A 5 × 5 black image with one white texel (2, 2) (top row first).
std::string dotImage(const test::TempDir& dir) {
    Image8 img(5, 5, 1);
    img.pixels[12] = 255;
    const std::string path = (dir.path() / "dot.png").string();
    writeImage(path, img);
    return path;
}

// The normal of the plane's bump_map at (x, y) for the surface normal n0 (the plane through the origin).
Vec3 bumpNormal(const std::string& bumpMap, double x, double y, Vec3 n0 = {0, 0, -1}) {
    const Loaded l = load("plane { -z, 0 pigment { rgb 1 } normal { bump_map { " + bumpMap + " } } }");
    const PovSurface& s = l.scene.povSurfaces.at(size_t(l.scene.objects.at(0).material.pov));
    EXPECT_GE(s.normal, 0);
    EXPECT_TRUE(l.warnings.empty());
    if (s.normal < 0) return n0;
    n0 = normalize(n0);
    const double z = -(n0.x * x + n0.y * y) / n0.z;
    return l.scene.normals.atRoot(l.scene.pigments, s.normal, {x, y, z}, n0);
}

void expectNormal(Vec3 n, Vec3 want, double tol = 1e-4) {
    EXPECT_NEAR(n.x, want.x, tol);
    EXPECT_NEAR(n.y, want.y, tol);
    EXPECT_NEAR(n.z, want.z, tol);
}

// Normals measured with POV-Ray 3.7 on a plane facing −z lit in turn by three parallel lights
// (16-bit output, 10 × 10 pixels over the unit square; texel (2, 2) is white).
TEST(PovNormal, BumpMapTiltsByThreeTapsOneTexelApart) {
    test::TempDir dir;
    const std::string png = "png \"" + dotImage(dir) + "\" ";
    // The white texel itself, and the texels up-left and up-right of it (it is one row down, one
    // column across from them); the texels beside and above it stay flat.
    expectNormal(bumpNormal(png + "bump_size 0.5", 0.55, 0.45), {0, -0.44721, -0.89442});
    expectNormal(bumpNormal(png + "bump_size 0.5", 0.35, 0.65), {-0.23570, 0.23570, -0.94281});
    expectNormal(bumpNormal(png + "bump_size 0.5", 0.75, 0.65), {0.23570, 0.23570, -0.94281});
    expectNormal(bumpNormal(png + "bump_size 0.5", 0.35, 0.45), {0, 0, -1});
    expectNormal(bumpNormal(png + "bump_size 0.5", 0.55, 0.65), {0, 0, -1});
    // bump_size 1 (tilt 1) and its default, 0.5.
    expectNormal(bumpNormal(png + "bump_size 1", 0.55, 0.45), {0, -0.70711, -0.70711});
    expectNormal(bumpNormal(png, 0.55, 0.45), {0, -0.44721, -0.89442});
    // interpolate 2: the three heights interpolated bilinearly (POV-Ray's pixel (3, 3), (1, 1), (1, 2)).
    expectNormal(bumpNormal(png + "bump_size 0.5 interpolate 2", 0.35, 0.65), {-0.138, 0.108, -0.984}, 1.5e-3);
    expectNormal(bumpNormal(png + "bump_size 0.5 interpolate 2", 0.15, 0.85), {-0.016, 0.016, -1.000}, 1.5e-3);
    expectNormal(bumpNormal(png + "bump_size 0.5 interpolate 2", 0.35, 0.45), {0, -0.093, -0.996}, 1.5e-3);
}

TEST(PovNormal, BumpMapTiltsInTheTangentPlaneAlongTheTexturesY) {
    test::TempDir dir;
    const std::string bump = "png \"" + dotImage(dir) + "\" bump_size 0.5";
    // Planes tilted about y, x and both (POV-Ray's normals at the same pixels as above).
    expectNormal(bumpNormal(bump, 0.55, 0.45, {0.3, 0, -1}), {0.257, -0.447, -0.857}, 1e-3);
    expectNormal(bumpNormal(bump, 0.35, 0.65, {0.3, 0, -1}), {0.045, 0.236, -0.971}, 1e-3);
    expectNormal(bumpNormal(bump, 0.55, 0.45, {0, 0.3, -1}), {0, -0.171, -0.985}, 1e-3);
    expectNormal(bumpNormal(bump, 0.55, 0.45, {0.3, 0.3, -1}), {0.28250, -0.18279, -0.94168}, 1e-4);
    expectNormal(bumpNormal(bump, 0.35, 0.65, {0.3, 0.3, -1}), {0.01592, 0.48692, -0.87330}, 1e-4);
    expectNormal(bumpNormal(bump, 0.75, 0.65, {0.3, 0.3, -1}), {0.46743, 0.48692, -0.73785}, 1e-4);
    expectNormal(bumpNormal(bump, 0.35, 0.65, {0.6, -0.4, -1}), {0.29605, -0.08295, -0.95157}, 1e-4);
}

TEST(PovNormal, BumpMapHeightsAreGreyBytesOrPaletteIndices) {
    test::TempDir dir;
    // A red texel reads as 0.297 (tilt 0.297), grey 128 as 128/255 (no gamma), a palette texel with
    // use_index as its index itself: 5 tilts by atan 5 (all at bump_size 1, POV-Ray's centre normals).
    Image8 red(5, 5, 3);
    red.pixels[12 * 3] = 255;
    writeImage((dir.path() / "red.png").string(), red);
    Image8 grey(5, 5, 1);
    grey.pixels[12] = 128;
    writeImage((dir.path() / "g128.png").string(), grey);
    std::vector<uint8_t> idx(25, 0);
    idx[12] = 5;
    test::Palette pal(16, {0, 0, 0});
    pal[5] = {255, 255, 255};
    test::writePalettePng((dir.path() / "pal5.png").string(), 5, 5, idx, pal, 4);
    const auto file = [&](const char* name) { return "png \"" + (dir.path() / name).string() + "\" bump_size 1 "; };
    expectNormal(bumpNormal(file("red.png"), 0.55, 0.45), {0, -0.28471, -0.95862});
    expectNormal(bumpNormal(file("g128.png"), 0.55, 0.45), {0, -0.44860, -0.89372});
    // interpolate 4: the three heights by image_map's normalised distance.
    expectNormal(bumpNormal(file("g128.png") + "interpolate 4", 0.55, 0.45), {0, -0.31524, -0.94900});
    expectNormal(bumpNormal(file("g128.png") + "interpolate 4", 0.35, 0.65), {-0.16253, 0.12640, -0.97858});
    expectNormal(bumpNormal(file("pal5.png") + "use_index", 0.55, 0.45), {0, -0.98058, -0.19612});
    expectNormal(bumpNormal(file("pal5.png"), 0.55, 0.45), {0, -0.70711, -0.70711});
}

// The direction a ray leaves along, read from a sky coloured by direction: (d + 1)/2 per channel,
// traced from `from` along elevation `degrees` in the yz plane (up when up is true).
Vec3 leavingDirection(const std::string& surface, Vec3 from, double degrees, bool up) {
    const Loaded l = load(
        "sky_sphere { pigment { average pigment_map {\n"
        "  [1 function { (x + 1) / 2 } color_map { [0 rgb 0] [1 rgb <3, 0, 0>] }]\n"
        "  [1 function { (y + 1) / 2 } color_map { [0 rgb 0] [1 rgb <0, 3, 0>] }]\n"
        "  [1 function { (z + 1) / 2 } color_map { [0 rgb 0] [1 rgb <0, 0, 3>] }] } } }\n" + surface);
    const Bvh bvh(l.scene.objects);
    const RenderSettings rs;
    TraceContext ctx;
    const double a = degrees * std::numbers::pi / 180;
    const Vec3 d{0, (up ? 1 : -1) * std::sin(a), std::cos(a)};
    return 2.0 * Tracer(l.scene, bvh, rs).tracePrimary(Ray{from, d}, ctx) - Vec3(1.0);
}

// A normal pattern can tilt the normal so far that the mirrored ray would go into the surface, or
// that the tilted normal faces away from the ray. POV-Ray 3.7's directions (measured: 16-bit renders
// of these scenes, the sky read one channel at a time) keep every ray on the viewer's side: the
// mirrored ray is mirrored back about the surface's plane, a ray meeting the tilted surface from
// behind mirrors about the untilted normal and refracts about the tilted one turned to face it.
TEST(PovNormal, TiltedMirrorsAndGlassSendRaysBackToTheViewersSide) {
    const std::string mirror = "plane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } "
                               "normal { gradient z bump_size B } }";
    auto mirrorY = [&](const char* bump, double degrees) {
        std::string m = mirror;
        m.replace(m.find(" B }"), 2, std::string(" ") + bump);
        return leavingDirection(m, {0, -1, 0}, degrees, true).y;
    };
    EXPECT_NEAR(mirrorY("1", 10), -0.4256, 2e-3);   // tilted towards the ray: steeper
    EXPECT_NEAR(mirrorY("-1", 10), -0.0904, 2e-3);  // mirrored into the plane (+0.0904), then back
    EXPECT_NEAR(mirrorY("-1", 8), -0.1251, 2e-3);
    EXPECT_NEAR(mirrorY("-1", 5), -0.0871, 2e-3);   // seen from behind: as if flat, −sin 5°

    const std::string glass = "plane { y, 0 hollow pigment { rgbt 1 } finish { ambient 0 diffuse 0 } "
                              "interior { ior 1.5 } normal { gradient z bump_size -1 } }";
    const Vec3 front = leavingDirection(glass, {0, 1, 0}, 10, false);
    EXPECT_NEAR(front.y, -0.8274, 2e-3);
    EXPECT_NEAR(front.z, 0.5617, 2e-3);
    const Vec3 behind = leavingDirection(glass, {0, 1, 0}, 5, false);  // back up, above the glass
    EXPECT_NEAR(behind.y, 0.6514, 2e-3);
    EXPECT_NEAR(behind.z, 0.7587, 2e-3);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
