// Distribution effects: anti-aliasing modes, area lights, depth of field, edge-guided AA, GI.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "rays/accel/bvh.h"
#include "rays/error.h"
#include "rays/io/scene_parser.h"
#include "rays/render/renderer.h"
#include "support/pov_scene.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

Scene sceneFrom(const std::string& text) {
    ParseOptions opt;
    opt.warn = [](const std::string&) {};
    return parseScene(text, "t.pov", opt);
}

ImageF renderScene(const Scene& scene, const RenderSettings& s) {
    const Bvh bvh(scene.objects);
    TraceStats stats;
    return render(scene, bvh, s, stats);
}

// The render and the pixels adaptive AA supersampled (render's edgePixels).
ImageF renderMarked(const Scene& scene, const RenderSettings& s, std::vector<uint8_t>& marked) {
    const Bvh bvh(scene.objects);
    TraceStats stats;
    return render(scene, bvh, s, stats, {}, &marked);
}

double luminance(Vec3 c) { return (c.x + c.y + c.z) / 3; }

// Number of pixels along row y whose luminance is strictly between 10 % and 90 % of the way
// from lo to hi: the width of a blurred transition.
int transitionWidth(const ImageF& img, int y, double lo, double hi) {
    int n = 0;
    for (int x = 0; x < img.width; ++x) {
        const double v = (luminance(img.at(x, y)) - lo) / (hi - lo);
        if (v > 0.1 && v < 0.9) ++n;
    }
    return n;
}

double rmse(const ImageF& a, const ImageF& b) {
    double sum = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const Vec3 d = a.pixels[i] - b.pixels[i];
        sum += dot(d, d) / 3;
    }
    return std::sqrt(sum / double(a.pixels.size()));
}

// A floor seen from straight above (from below the occluder, 48 units across), an occluder edge
// halfway between the floor and an area light of the given width (along x) above the edge.
std::string penumbraScene(double lightSize) {
    return "camera { location <0, 3, 0> up <0, 0, -0.8> right <16, 0, 0> look_at <0, 0, 0> }\n"
           "light_source { <0, 10, 0> color rgb 1 area_light <" + std::to_string(lightSize) +
           ", 0, 0>, <0, 0, 0.5>, 16, 2 }\n"
           "plane { <0, 1, 0>, 0 pigment { color rgb 1 } finish { diffuse 1 } }\n"
           // An occluder covering x < 0, high enough to cast a wide penumbra.
           "box { <-50, 4.9, -50>, <0, 5, 50> pigment { color rgb 1 } }\n";
}

TEST(Distribution, PenumbraWidthGrowsWithLightSize) {
    RenderSettings s;
    s.width = 400;
    s.height = 20;
    int previous = -1;
    for (double size : {0.5, 2.0, 4.0}) {
        // Visibility = shaded / unshadowed, so the falloff of N·L across the floor cancels.
        const std::string scene = penumbraScene(size);
        const ImageF lit = renderScene(sceneFrom(scene.substr(0, scene.find("box {"))), s);
        const ImageF img = renderScene(sceneFrom(scene), s);
        int w = 0;
        for (int x = 0; x < s.width; ++x) {
            const double v = luminance(img.at(x, 10)) / luminance(lit.at(x, 10));
            if (v > 0.1 && v < 0.9) ++w;
        }
        EXPECT_GT(w, previous) << "light size " << size;
        previous = w;
    }
    // The penumbra of a 4-unit light with the occluder at half height is 4 units wide: 33 px at
    // 0.12 units per pixel, of which the 10–90 % band is 80 %.
    EXPECT_GE(previous, 24);
    EXPECT_LE(previous, 30);
}

TEST(Distribution, GridAntiAliasingGivesExactCoverage) {
    // A white half plane x > 0.25 px into pixel 10 (flat shading, black background): a 4×4 grid
    // covers 3 of 4 sample columns.
    // Camera: 20 px across 20 world units at the box face, so pixel 10 spans x ∈ [0, 1).
    const Scene scene = sceneFrom(
        "camera { location <0, 0, 10> up <0, 0.2, 0> right <2, 0, 0> look_at <0, 0, 0> }\n"
        "box { <0.25, -100, -1>, <100, 100, 0> pigment { color rgb 1 } }\n");
    RenderSettings s;
    s.width = 20;
    s.height = 2;
    s.shading = ShadingModel::Flat;
    s.aa = AaMode::Grid;
    s.spp = 16;
    const ImageF img = renderScene(scene, s);
    EXPECT_NEAR(img.at(10, 0).x, 0.75, 1e-12);
    EXPECT_NEAR(img.at(9, 0).x, 0.0, 1e-12);
    EXPECT_NEAR(img.at(11, 0).x, 1.0, 1e-12);
}

TEST(Distribution, ErrorFallsAsSamplesRise) {
    const Scene scene = sceneFrom(penumbraScene(3.0) + "sphere { <3, 1, 0>, 1 pigment { color rgb <1, 0.2, 0.2> } finish { ambient 0.1 diffuse 0.8 } }\n");
    RenderSettings s;
    s.width = 80;
    s.height = 20;
    s.aa = AaMode::Stratified;
    s.spp = 256;
    const ImageF reference = renderScene(scene, s);
    double previous = 1e9;
    for (int spp : {1, 4, 16, 64}) {
        s.spp = spp;
        const double e = rmse(renderScene(scene, s), reference);
        EXPECT_LT(e, previous) << spp << " samples";
        previous = e;
    }
}

TEST(Distribution, FocalPlaneStaysSharpWhileBlurGrowsWithAperture) {
    // Two vertical black/white edges: one on the focal plane (z = 0, 10 units away), one 6 units
    // behind it. Image rows 0..9 see the near edge, rows 10..19 the far one; 0.05 units per
    // pixel on the focal plane, where the far edge's circle of confusion is 2·A·6/16 units.
    const std::string base =
        "camera { location <0, 0, 10> up <0, 2, 0> right <0.8, 0, 0> look_at <0, 0, 0> focal_point <0, 0, 0> blur_samples 64 aperture ";
    const std::string objects =
        "}\nbox { <0, 0, -1>, <50, 50, 0> pigment { color rgb 1 } }\n"
        "box { <-2.5, -50, -7>, <50, 0, -6> pigment { color rgb 1 } }\n";
    RenderSettings s;
    s.width = 160;
    s.height = 20;
    s.shading = ShadingModel::Flat;
    int previousFar = -1;
    for (const char* aperture : {"0", "0.3", "0.8"}) {
        const ImageF img = renderScene(sceneFrom(base + aperture + objects), s);
        const int nearWidth = transitionWidth(img, 4, 0, 1);   // top half: y > 0, the near box
        const int farWidth = transitionWidth(img, 16, 0, 1);   // bottom half: the far box
        EXPECT_LE(nearWidth, 1) << "aperture " << aperture;
        EXPECT_GT(farWidth, previousFar) << "aperture " << aperture;
        previousFar = farWidth;
    }
    EXPECT_GT(previousFar, 5);
}

TEST(Distribution, EdgeGuidedAaTouchesOnlyEdgePixelsAndMatchesFullAa) {
    const Scene scene = sceneFrom(
        "camera { location <0, 1, 8> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }\n"
        "light_source { <5, 10, 5> color rgb 1 }\n"
        "plane { <0, 1, 0>, -1 pigment { color rgb 1 } finish { ambient 0.2 diffuse 0.7 } }\n"
        "sphere { <0, 0, 0>, 1 pigment { color rgb <1, 0, 0> } finish { ambient 0.2 diffuse 0.7 } }\n");
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.aa = AaMode::Stratified;
    s.spp = 16;
    const ImageF full = renderScene(scene, s);
    RenderSettings one = s;
    one.aa = AaMode::Grid;
    one.spp = 1;
    const ImageF single = renderScene(scene, one);
    s.aaEdges = true;
    std::vector<uint8_t> marked;
    const ImageF guided = renderMarked(scene, s, marked);
    int edges = 0;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const size_t i = size_t(y) * s.width + x;
            if (marked[i]) {
                ++edges;
                EXPECT_EQ(guided.pixels[i], full.pixels[i]);
            } else {
                EXPECT_EQ(guided.pixels[i], single.pixels[i]);
            }
        }
    EXPECT_GT(edges, 50);                      // the sphere outline and its shadow
    EXPECT_LT(edges, s.width * s.height / 4);  // but only a small part of the image
}

// POV-Ray's method 1 (+A0.3): the pixels supersampled are those whose colour differs from the
// left or upper neighbour's by more than the threshold, and that neighbour; the difference is
// |Δr| + |Δg| + |Δb| of the linear colours raised to 1/2.5 (Antialias_Gamma). Worked out here
// from the one-sample image (sRGB-decoded by the IEC formula); pixels within 1e-4 of the threshold
// are left out (float rounding).
TEST(Distribution, PovRayThresholdAaSupersamplesWhereColoursChange) {
    // A checker whose squares differ by little (0.05 in red: below 0.3) and a sphere that
    // differs from them by much.
    const Scene scene = test::buildPov(
        "global_settings { assumed_gamma 1 }\n"
        "camera { location <0, 2, -8> look_at <0, 0, 0> }\n"
        "light_source { <5, 10, -5> color rgb 1 }\n"
        "plane { y, -1 pigment { checker rgb <0.60, 0.5, 0.5> rgb <0.65, 0.5, 0.5> } }\n"
        "sphere { 0, 1 pigment { rgb <0, 0, 1> } }\n");
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.aa = AaMode::Stratified;
    s.spp = 9;
    RenderSettings one = s;
    one.aa = AaMode::Grid;
    one.spp = 1;
    const ImageF single = renderScene(scene, one);
    s.aaEdges = true;
    s.aaThreshold = 0.3;
    s.aaGamma = 2.5;
    std::vector<uint8_t> marked;
    const ImageF img = renderMarked(scene, s, marked);
    auto look = [&](int x, int y) {
        Vec3 r;
        for (int k = 0; k < 3; ++k) {
            const double e = single.at(x, y)[k];
            const double linear = e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
            r[k] = std::pow(linear, 1 / 2.5);
        }
        return r;
    };
    auto diff = [&](int x0, int y0, int x1, int y1) {
        const Vec3 d = look(x0, y0) - look(x1, y1);
        return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
    };
    int want = 0, checked = 0;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            double most = 0;  // the largest difference to a 4-neighbour
            if (x > 0) most = std::max(most, diff(x, y, x - 1, y));
            if (y > 0) most = std::max(most, diff(x, y, x, y - 1));
            if (x + 1 < s.width) most = std::max(most, diff(x, y, x + 1, y));
            if (y + 1 < s.height) most = std::max(most, diff(x, y, x, y + 1));
            if (std::fabs(most - 0.3) < 1e-4) continue;
            ++checked;
            want += most > 0.3;
            const size_t i = size_t(y) * s.width + x;
            EXPECT_EQ(marked[i], most > 0.3 ? 1 : 0) << x << "," << y << " difference " << most;
            if (!marked[i]) {
                EXPECT_EQ(img.pixels[i], single.pixels[i]) << x << "," << y;
            }
        }
    EXPECT_GT(checked, s.width * s.height * 9 / 10);
    EXPECT_GT(want, 40);                       // the sphere's outline
    EXPECT_LT(want, s.width * s.height / 4);  // not the checker's squares
}

// Focal blur samples every pixel whatever the anti-aliasing rule (as POV-Ray's does): a sharp
// first pass would leave the unmarked pixels in focus.
TEST(Distribution, AdaptiveAaLeavesFocalBlurToEveryPixel) {
    const Scene scene = test::buildPov(
        "camera { location <0, 2, -8> look_at <0, 0, 0> aperture 0.8 focal_point <0, 0, 4> blur_samples 16 }\n"
        "light_source { <5, 10, -5> color rgb 1 }\n"
        "plane { y, -1 pigment { checker rgb 1 rgb 0 } }\n"
        "sphere { 0, 1 pigment { rgb <0, 0, 1> } }\n");
    RenderSettings s;
    s.width = 32;
    s.height = 24;
    s.aa = AaMode::Stratified;
    s.spp = 9;
    const ImageF full = renderScene(scene, s);
    s.aaEdges = true;
    s.aaThreshold = 0.3;
    std::vector<uint8_t> marked;
    const ImageF adaptive = renderMarked(scene, s, marked);
    EXPECT_EQ(adaptive.pixels, full.pixels);
    ASSERT_EQ(marked.size(), size_t(s.width * s.height));
    for (uint8_t m : marked) EXPECT_EQ(m, 1);
}

TEST(Distribution, SameImageForAnyThreadCount) {
    const Scene scene = sceneFrom(
        "camera { location <0, 1, 8> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> aperture 0.2 blur_samples 8 }\n"
        "light_source { <5, 10, 5> color rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 3, 3 jitter }\n"
        "light_source { <-5, 10, 5> color rgb 0.3 parallel point_at <0, 0, 0> }\n"
        "plane { <0, 1, 0>, -1 pigment { color rgb 1 } finish { ambient 0.2 diffuse 0.7 } }\n"
        "sphere { <0, 0, 0>, 1 pigment { color rgbf <1, 0.5, 0.5, 0.5> } finish { ambient 0.2 diffuse 0.7 reflection 0.3 ior 1.4 } }\n");
    RenderSettings s;
    s.width = 40;
    s.height = 30;
    s.gi = true;
    s.giSamples[0] = 4;
    s.giSamples[1] = 2;
    s.threads = 1;
    const ImageF a = renderScene(scene, s);
    s.threads = 3;
    const ImageF b = renderScene(scene, s);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    for (size_t i = 0; i < a.pixels.size(); ++i) ASSERT_EQ(a.pixels[i], b.pixels[i]) << "pixel " << i;
}

TEST(Distribution, GlobalIlluminationBringsColourBleeding) {
    // A white floor next to a lit red wall: with -gi the floor near the wall turns red.
    const Scene scene = sceneFrom(
        "camera { location <0, 6, 6> up <0, 1, 0> right <1, 0, 0> look_at <0, 0, 0> }\n"
        "light_source { <3, 5, 3> color rgb 1 }\n"
        "plane { <0, 1, 0>, 0 pigment { color rgb 1 } finish { ambient 0.1 diffuse 0.8 } }\n"
        "box { <-5, 0, -5>, <-0.5, 5, 5> pigment { color rgb <1, 0, 0> } finish { ambient 0.1 diffuse 0.8 } }\n");
    RenderSettings s;
    s.width = 32;
    s.height = 32;
    const ImageF plain = renderScene(scene, s);
    s.gi = true;
    s.giSamples[0] = 64;
    s.giSamples[1] = 4;
    s.giBounces = 1;
    const ImageF gi = renderScene(scene, s);
    // Floor just right of the wall: x a little > −0.5, near the middle row.
    const Vec3 p = plain.at(18, 16), g = gi.at(18, 16);
    EXPECT_GT(g.x - g.y, p.x - p.y + 0.01) << "plain " << p.x << "," << p.y << " gi " << g.x << "," << g.y;
}

TEST(Distribution, ParallelLightIsTheSameEverywhere) {
    const Scene scene = sceneFrom(
        "camera { location <0, 20, 0> up <0, 0, -1> right <1, 0, 0> look_at <0, 0, 0> }\n"
        "light_source { <0, 100, 0> color rgb 1 parallel point_at <0, 0, 0> }\n"
        "plane { <0, 1, 0>, 0 pigment { color rgb 1 } finish { diffuse 1 } }\n"
        "sphere { <3, 2, 0>, 1 pigment { color rgb 1 } }\n");
    RenderSettings s;
    s.width = 40;
    s.height = 40;
    const ImageF img = renderScene(scene, s);
    // Straight-down light: the floor is lit at exactly N·L = 1 everywhere it is not shadowed,
    // and the shadow is directly below the sphere (not spread as a point light would).
    EXPECT_NEAR(img.at(5, 20).x, 1.0, 1e-9);
    EXPECT_NEAR(img.at(35, 35).x, 1.0, 1e-9);
}

TEST(Distribution, BadValuesAreErrors) {
    auto err = [](const std::string& body) -> std::string {
        try {
            sceneFrom(body);
        } catch (const Error& e) {
            return e.what();
        }
        return "(no error)";
    };
    const std::string cam = "camera { location <0,0,5> up <0,1,0> right <1,0,0> look_at <0,0,0> ";
    EXPECT_NE(err(cam + "aperture -1 }").find("aperture must not be negative"), std::string::npos);
    EXPECT_NE(err(cam + "blur_samples 0 }").find("blur_samples must be"), std::string::npos);
    EXPECT_NE(err(cam + "}\nlight_source { <0,5,0> color rgb 1 area_light <1,0,0>, <2,0,0>, 4, 4 }")
                  .find("area_light axes are degenerate"), std::string::npos);
    EXPECT_NE(err(cam + "}\nlight_source { <0,5,0> color rgb 1 area_light <1,0,0>, <0,0,1>, 0, 4 }")
                  .find("sample counts must be whole numbers"), std::string::npos);
    EXPECT_NE(err(cam + "}\nlight_source { <0,5,0> color rgb 1 parallel point_at <0,5,0> }")
                  .find("point_at equals"), std::string::npos);
}

}}  // namespace RAYS_TEST_UNIT, namespace
