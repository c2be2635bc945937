// POV-Ray's focal blur: the lens size `aperture` stands for, and the adaptive stop of
// `blur_samples MIN, MAX` with `confidence` and `variance`, against POV-Ray 3.7.0.10's renders.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rays/render/tracer.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

using test::buildPov;

// A white wall 20 units away whose left edge is on the axis, black beyond it, the camera at the
// origin focused 10 units away: the edge's circle of confusion is aperture/2 · (20 − 10)/20 units
// wide on the focal plane (measured: POV-Ray 3.7 blurs it over 6 of 320 pixels with aperture 1,
// 4/3 · 10 units across; with aperture 2 over 12, at any scale, zoom and blur_samples count).
std::string edgeScene(const std::string& camera) {
    return "global_settings { assumed_gamma 1 }\n"
           "camera { location 0 direction z right x*4/3 up y focal_point <0,0,10> " + camera + " }\n"
           "box { <0,-100,20>, <100,100,21> pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n"
           "background { rgb 0 }\n";
}

// Columns of row y whose brightness is strictly between lo and hi.
int rampWidth(const ImageF& img, int y, double lo, double hi) {
    int n = 0;
    for (int x = 0; x < img.width; ++x) {
        const double v = img.at(x, y).x;
        n += v > lo && v < hi;
    }
    return n;
}

TEST(PovFocalBlur, ApertureIsFourTimesTheLensRadius) {
    const Camera c = buildPov(edgeScene("aperture 2 blur_samples 20")).cameras.at(0);
    EXPECT_DOUBLE_EQ(c.aperture, 0.5);
    // The blurred edge spans the circle of confusion: aperture 4 → 1 unit → 24 of 320 pixels.
    const ImageF img = test::renderPov(buildPov(edgeScene("aperture 4 blur_samples 400, 400")), 320, 24);
    const int w = rampWidth(img, 12, 0.01, 0.99);
    EXPECT_GE(w, 20);
    EXPECT_LE(w, 25);
}

TEST(PovFocalBlur, AdaptiveSettings) {
    const Camera d = buildPov(edgeScene("aperture 1 blur_samples 40")).cameras.at(0);
    EXPECT_EQ(d.blurSamples, 40);
    EXPECT_EQ(d.blurMinSamples, 16);                  // our default minimum
    EXPECT_NEAR(d.blurZ2, 1.6448536 * 1.6448536, 1e-6);  // confidence 0.9, two-sided
    EXPECT_DOUBLE_EQ(d.blurVariance, 1.0 / 128);
    const Camera c = buildPov(edgeScene("aperture 1 blur_samples 8, 40 confidence 0.95 variance 1/64")).cameras.at(0);
    EXPECT_EQ(c.blurMinSamples, 8);
    EXPECT_NEAR(c.blurZ2, 1.959964 * 1.959964, 1e-5);
    EXPECT_DOUBLE_EQ(c.blurVariance, 1.0 / 64);
    // A confidence of 1 or more takes the default (POV-Ray warns and does the same).
    EXPECT_NEAR(buildPov(edgeScene("aperture 1 confidence 1")).cameras.at(0).blurZ2, d.blurZ2, 1e-9);
    // Fewer samples than the minimum: the minimum is the count.
    EXPECT_EQ(buildPov(edgeScene("aperture 1 blur_samples 5")).cameras.at(0).blurMinSamples, 5);
}

// Primary rays of a render of the scene at 64×48.
uint64_t primaryRays(const std::string& text) {
    const Scene s = buildPov(text);
    RenderSettings settings;
    settings.width = 64;
    settings.height = 48;
    settings.threads = 1;
    const Bvh bvh(s.objects);
    TraceStats stats;
    render(s, bvh, settings, stats);
    return stats.primaryRays;
}

TEST(PovFocalBlur, SamplingStopsWhereTheSamplesAgree) {
    // Far from the blurred edge every sample agrees: those pixels stop at the minimum; pixels on
    // the edge go on. With variance 0 only pixels whose samples are all equal stop early.
    const int pixels = 64 * 48;
    const uint64_t adaptive = primaryRays(edgeScene("aperture 1 blur_samples 16, 100"));
    const uint64_t strict = primaryRays(edgeScene("aperture 1 blur_samples 16, 100 variance 0"));
    const uint64_t all = primaryRays(edgeScene("aperture 1 blur_samples 100 confidence 0"));
    EXPECT_LT(adaptive, uint64_t(pixels) * 30);  // nearly every pixel stops at 16 samples
    EXPECT_GT(adaptive, uint64_t(pixels) * 16);  // the edge's do not
    EXPECT_GE(strict, adaptive);
    // confidence 0 → z = 0: the test passes at the minimum (16) everywhere.
    EXPECT_EQ(all, uint64_t(pixels) * 16);
}

TEST(PovFocalBlur, EarlyStopKeepsTheBlurredEdge) {
    // Stopping early changes each edge pixel by little: the mean over the edge's columns stays
    // within 2 % of taking every sample.
    const std::string cam = "aperture 4 blur_samples 16, 400";
    const ImageF a = test::renderPov(buildPov(edgeScene(cam)), 320, 24);
    const ImageF b = test::renderPov(buildPov(edgeScene(cam + " variance 0")), 320, 24);
    double sa = 0, sb = 0;
    for (int x = 140; x < 180; ++x) sa += a.at(x, 12).x, sb += b.at(x, 12).x;
    EXPECT_NEAR(sa, sb, 0.02 * sb);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
