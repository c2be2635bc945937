// Image comparison (src/rays/image/{ssim,compare}): SSIM against hand-computed cases and against a
// plain double-precision per-window reference, the clipped window of small images, symmetry,
// monotonic response to noise, PSNR / mean / max / threshold counts of known differences, grey
// images, and the difference image. Images are tiny; the file runs in milliseconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "rays/error.h"
#include "rays/image/compare.h"
#include "rays/image/ssim.h"
#include "support/error_text.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;

// Deterministic pseudo-random bytes (xorshift).
std::vector<uint8_t> noiseBytes(size_t n, uint32_t seed) {
    std::vector<uint8_t> v(n);
    uint32_t s = seed * 2654435761u + 12345u;
    for (uint8_t& b : v) {
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        b = uint8_t(s >> 24);
    }
    return v;
}

Image8 randomImage(int w, int h, uint32_t seed, int channels = 3) {
    Image8 img(w, h, channels);
    img.pixels = noiseBytes(img.pixels.size(), seed);
    return img;
}

Image8 constantImage(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
    Image8 img(w, h, 3);
    for (size_t i = 0; i < img.pixels.size(); i += 3) {
        img.pixels[i] = r;
        img.pixels[i + 1] = g;
        img.pixels[i + 2] = b;
    }
    return img;
}

std::vector<float> toPlane(const std::vector<uint8_t>& bytes) {
    std::vector<float> p(bytes.size());
    for (size_t i = 0; i < bytes.size(); ++i) p[i] = float(bytes[i]) / 255.0f;
    return p;
}

// SSIM the slow way: every window position inside the image, weights w[j]·w[i] from ssimWindow,
// moments and the formula in double.
double referenceSsim(const std::vector<float>& a, const std::vector<float>& b, int width, int height) {
    const std::vector<double> wx = ssimWindow(width), wy = ssimWindow(height);
    const int nx = int(wx.size()), ny = int(wy.size());
    double total = 0;
    int count = 0;
    for (int oy = 0; oy + ny <= height; ++oy)
        for (int ox = 0; ox + nx <= width; ++ox) {
            double ma = 0, mb = 0, saa = 0, sbb = 0, sab = 0;
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i) {
                    const double w = wy[size_t(j)] * wx[size_t(i)];
                    const size_t k = size_t(oy + j) * size_t(width) + size_t(ox + i);
                    const double x = a[k], y = b[k];
                    ma += w * x;
                    mb += w * y;
                    saa += w * x * x;
                    sbb += w * y * y;
                    sab += w * x * y;
                }
            const double va = saa - ma * ma, vb = sbb - mb * mb, cov = sab - ma * mb;
            total += ((2 * ma * mb + kC1) * (2 * cov + kC2)) / ((ma * ma + mb * mb + kC1) * (va + vb + kC2));
            ++count;
        }
    return total / count;
}

TEST(CompareSsim, WindowIsTheNormalisedGaussianClippedToSmallSides) {
    const std::vector<double> w = ssimWindow(500);
    ASSERT_EQ(w.size(), 11u);
    double sum = 0;
    for (double v : w) sum += v;
    EXPECT_NEAR(sum, 1.0, 1e-6);
    for (int i = 0; i < 11; ++i) EXPECT_DOUBLE_EQ(w[size_t(i)], w[size_t(10 - i)]);
    EXPECT_NEAR(w[5] / w[4], std::exp(1.0 / (2 * 1.5 * 1.5)), 1e-5);  // σ = 1.5
    EXPECT_NEAR(w[5] / w[0], std::exp(25.0 / (2 * 1.5 * 1.5)), 1e-2);
    const std::vector<double> eight = ssimWindow(8);
    ASSERT_EQ(eight.size(), 8u);
    EXPECT_DOUBLE_EQ(eight[3], eight[4]);  // centred between the two middle pixels
    EXPECT_NEAR(eight[4] / eight[5], std::exp((1.5 * 1.5 - 0.5 * 0.5) / (2 * 1.5 * 1.5)), 1e-5);
    EXPECT_EQ(ssimWindow(1), std::vector<double>{1.0});
}

TEST(CompareSsim, IdenticalImagesGiveExactlyOne) {
    for (const auto& [w, h] : {std::pair{37, 29}, std::pair{8, 8}, std::pair{1, 1}, std::pair{100, 3}}) {
        const Image8 img = randomImage(w, h, 7);
        const SsimRgb s = ssimRgb(img, img);
        EXPECT_EQ(s.mean(), 1.0) << w << "x" << h;
        EXPECT_EQ(s.luma, 1.0);
    }
}

TEST(CompareSsim, OnePixelImagesByHand) {
    // One pixel: μ = the values, σ = 0, so SSIM = (2ab + C1) / (a² + b² + C1).
    const float white = 1.0f, black = 0.0f, grey = 0.5f;
    EXPECT_NEAR(ssim(&white, &black, 1, 1), kC1 / (1 + kC1), 1e-15);
    EXPECT_NEAR(ssim(&white, &grey, 1, 1), (1 + kC1) / (1.25 + kC1), 1e-12);
}

TEST(CompareSsim, TwoPixelImageByHand) {
    // a = (0, 1), b = (1, 0); equal weights 1/2: μa = μb = 1/2, σa² = σb² = 1/4, σab = 0 − 1/4.
    const float a[2] = {0, 1}, b[2] = {1, 0};
    const double expected = ((0.5 + kC1) * (-0.5 + kC2)) / ((0.5 + kC1) * (0.5 + kC2));
    EXPECT_NEAR(ssim(a, b, 2, 1), expected, 1e-12);
    EXPECT_NEAR(ssim(a, b, 1, 2), expected, 1e-12);  // the same as a column
    EXPECT_LT(expected, -0.99);                     // perfectly anti-correlated
}

TEST(CompareSsim, ConstantOffsetKeepsOnlyTheLuminanceTerm) {
    // Constant images: σ = 0 everywhere, so every window gives (2ab + C1) / (a² + b² + C1).
    const Image8 a = constantImage(40, 30, 100, 100, 100), b = constantImage(40, 30, 110, 110, 110);
    const double x = 100 / 255.0, y = 110 / 255.0;
    const double expected = (2 * x * y + kC1) / (x * x + y * y + kC1);
    const SsimRgb s = ssimRgb(a, b);
    for (double c : s.channel) EXPECT_NEAR(c, expected, 1e-12);
    EXPECT_NEAR(s.luma, expected, 1e-12);
    EXPECT_LT(expected, 1.0);
}

TEST(CompareSsim, MatchesThePerWindowReference) {
    // Full windows, both sides clipped, one side clipped; sizes around the block width of 16.
    for (const auto& [w, h] : {std::pair{23, 17}, std::pair{8, 8}, std::pair{30, 5}, std::pair{4, 40}, std::pair{41, 33}}) {
        const size_t n = size_t(w) * size_t(h);
        const std::vector<float> a = toPlane(noiseBytes(n, 3));
        std::vector<float> b = toPlane(noiseBytes(n, 4));
        for (size_t i = 0; i < n; ++i) b[i] = 0.7f * a[i] + 0.3f * b[i];  // correlated, so SSIM is far from 0
        const double expected = referenceSsim(a, b, w, h);
        EXPECT_NEAR(ssim(a.data(), b.data(), w, h), expected, 1e-12) << w << "x" << h;
        EXPECT_GT(expected, 0.2) << w << "x" << h;
    }
}

TEST(CompareSsim, IsSymmetric) {
    const Image8 a = randomImage(45, 31, 1), b = randomImage(45, 31, 2);
    const SsimRgb ab = ssimRgb(a, b), ba = ssimRgb(b, a);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ab.channel[c], ba.channel[c], 1e-15);
    EXPECT_NEAR(ab.luma, ba.luma, 1e-15);
}

TEST(CompareSsim, FallsMonotonicallyWithTheAmountOfNoise) {
    // A smooth image plus the same noise pattern at growing amplitudes (levels, clamped).
    const int w = 64, h = 48;
    Image8 base(w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) base.row(y)[3 * x + c] = uint8_t(60 + x + y + 20 * c);
    const std::vector<uint8_t> noise = noiseBytes(base.pixels.size(), 9);
    double previous = 1.0;
    for (int amplitude : {2, 4, 8, 16, 32, 64}) {
        Image8 noisy = base;
        for (size_t i = 0; i < noisy.pixels.size(); ++i)
            noisy.pixels[i] = uint8_t(std::clamp(int(base.pixels[i]) + (int(noise[i]) - 128) * amplitude / 128, 0, 255));
        const double s = ssimRgb(base, noisy).mean();
        EXPECT_LT(s, previous) << "amplitude " << amplitude;
        previous = s;
    }
    EXPECT_LT(previous, 0.5);
}

TEST(CompareSsim, LumaWeighsBlueLeast) {
    // Only blue differs: R and G are identical; luma sees a 0.114-weighted change.
    const Image8 a = randomImage(32, 32, 5);
    Image8 b = a;
    const std::vector<uint8_t> noise = noiseBytes(b.pixels.size(), 6);
    for (size_t i = 2; i < b.pixels.size(); i += 3) b.pixels[i] = noise[i];
    const SsimRgb s = ssimRgb(a, b);
    EXPECT_EQ(s.channel[0], 1.0);
    EXPECT_EQ(s.channel[1], 1.0);
    EXPECT_LT(s.channel[2], 0.5);
    EXPECT_GT(s.luma, s.channel[2]);
    EXPECT_LT(s.luma, 1.0);
}

TEST(CompareFigures, IdenticalImages) {
    const Image8 img = randomImage(20, 10, 11);
    const ImageComparison r = compareImages(img, img);
    EXPECT_EQ(r.psnr, std::numeric_limits<double>::infinity());
    EXPECT_EQ(r.mse, 0.0);
    EXPECT_EQ(r.meanAbs, 0.0);
    EXPECT_EQ(r.maxAbs, 0);
    EXPECT_EQ(r.pixelsOver, 0u);
    EXPECT_EQ(r.ssim.mean(), 1.0);
    EXPECT_EQ(r.width, 20);
    EXPECT_EQ(r.height, 10);
}

TEST(CompareFigures, PsnrOfAKnownMse) {
    // Half the pixels differ by 4 in every channel, the rest not at all: MSE = 16 / 2 = 8.
    const Image8 a = constantImage(10, 4, 50, 60, 70);
    Image8 b = a;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 10 * 3; ++x) b.row(y)[x] = uint8_t(b.row(y)[x] + 4);
    const ImageComparison r = compareImages(a, b);
    EXPECT_DOUBLE_EQ(r.mse, 8.0);
    EXPECT_NEAR(r.psnr, 10 * std::log10(255.0 * 255.0 / 8.0), 1e-12);
    EXPECT_DOUBLE_EQ(r.meanAbs, 2.0);
    EXPECT_EQ(r.maxAbs, 4);
    EXPECT_EQ(r.pixelsOver, 0u);  // 4 is not over 5
}

TEST(CompareFigures, ThresholdCountsPixelsWhoseLargestChannelDifferenceExceedsIt) {
    Image8 a = constantImage(4, 1, 100, 100, 100), b = a;
    b.row(0)[0] = 105;            // pixel 0: 5 (not over 5)
    b.row(0)[3 + 2] = 106;        // pixel 1: 6 in blue
    b.row(0)[6 + 1] = 90;         // pixel 2: 10 in green
    b.row(0)[9] = b.row(0)[10] = b.row(0)[11] = 103;  // pixel 3: 3 everywhere
    ImageComparison r = compareImages(a, b, 5);
    EXPECT_EQ(r.pixelsOver, 2u);
    EXPECT_DOUBLE_EQ(r.percentOver(), 50.0);
    EXPECT_EQ(r.maxAbs, 10);
    EXPECT_DOUBLE_EQ(r.meanAbs, (5 + 6 + 10 + 9) / 12.0);
    EXPECT_EQ(compareImages(a, b, 0).pixelsOver, 4u);
    EXPECT_EQ(compareImages(a, b, 9.5).pixelsOver, 1u);
    EXPECT_EQ(compareImages(a, b, 255).pixelsOver, 0u);
}

TEST(CompareFigures, GreyCountsAsEqualChannelsAndAlphaIsIgnored) {
    const Image8 grey = randomImage(13, 9, 21, 1);
    Image8 rgba(13, 9, 4);
    for (size_t i = 0; i < grey.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) rgba.pixels[4 * i + size_t(c)] = grey.pixels[i];
        rgba.pixels[4 * i + 3] = uint8_t(i);  // any alpha
    }
    const ImageComparison r = compareImages(grey, rgba);
    EXPECT_EQ(r.maxAbs, 0);
    EXPECT_EQ(r.ssim.mean(), 1.0);
    EXPECT_EQ(r.psnr, std::numeric_limits<double>::infinity());
}

TEST(CompareFigures, DifferentSizesAreAnError) {
    const Image8 a(10, 10, 3), b(10, 11, 3);
    EXPECT_EQ(test::errorText([&] { compareImages(a, b); }), "rays: error: images differ in size (10x10 and 10x11)");
    EXPECT_NE(test::errorText([&] { differenceImage(a, b); }), "(no error)");
    EXPECT_NE(test::errorText([&] { ssimRgb(a, b); }), "(no error)");
}

TEST(CompareDiff, AbsoluteDifferenceScaledRoundedAndClamped) {
    Image8 a = constantImage(2, 1, 10, 200, 0), b = constantImage(2, 1, 20, 190, 0);
    b.row(0)[3 + 2] = 100;  // second pixel: blue differs by 100
    const Image8 d1 = differenceImage(a, b, 1);
    ASSERT_EQ(d1.channels, 3);
    EXPECT_EQ(d1.pixels, (std::vector<uint8_t>{10, 10, 0, 10, 10, 100}));
    EXPECT_EQ(differenceImage(a, b, 3).pixels, (std::vector<uint8_t>{30, 30, 0, 30, 30, 255}));
    EXPECT_EQ(differenceImage(a, b, 0.25).pixels, (std::vector<uint8_t>{3, 3, 0, 3, 3, 25}));  // 2.5 rounds up
    EXPECT_EQ(differenceImage(a, b, 0).pixels, (std::vector<uint8_t>(6, 0)));
    EXPECT_EQ(differenceImage(b, a, 1).pixels, d1.pixels);
}

}}  // namespace RAYS_TEST_UNIT, namespace
