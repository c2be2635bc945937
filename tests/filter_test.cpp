// Image filters (src/rays/image/{kernels,convolve,filter}): kernel specs and files, impulse
// responses, the fast paths (separable, running sums, median network) against a plain per-pixel
// reference convolution, border modes on hand-computed images, 8-bit rounding and alpha, thread
// independence. Images are tiny; the whole file runs in well under a second.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "rays/error.h"
#include "rays/image/convolve.h"
#include "rays/image/filter.h"
#include "rays/image/kernels.h"
#include "rays/image/parallel.h"
#include "support/error_text.h"
#include "support/process.h"

namespace fs = std::filesystem;
using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

const BorderMode kModes[] = {BorderMode::Clamp, BorderMode::Zero, BorderMode::White, BorderMode::Reflect};

// Deterministic pseudo-random values in [0, 1).
PlanarImage noise(int w, int h, int c, uint32_t seed = 1) {
    PlanarImage img(w, h, c);
    uint32_t s = seed * 2654435761u + 12345u;
    for (float& v : img.data) {
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        v = float(s % 10007u) / 10007.0f;
    }
    return img;
}

PlanarImage constantImage(int w, int h, float v) {
    PlanarImage img(w, h, 1);
    std::fill(img.data.begin(), img.data.end(), v);
    return img;
}

// The reference: out(x, y) = Σ K[j][i] · in(x + rx − i, y + ry − j), border by border mode, in double.
PlanarImage reference(const PlanarImage& src, const std::vector<double>& k, int kw, int kh, BorderMode mode,
                      bool absolute = false) {
    PlanarImage out(src.width, src.height, src.channels);
    const int rx = kw / 2, ry = kh / 2;
    const double constant = mode == BorderMode::White ? 1.0 : 0.0;
    const bool isConst = mode == BorderMode::Zero || mode == BorderMode::White;
    for (int c = 0; c < src.channels; ++c)
        for (int y = 0; y < src.height; ++y)
            for (int x = 0; x < src.width; ++x) {
                double sum = 0;
                for (int j = 0; j < kh; ++j)
                    for (int i = 0; i < kw; ++i) {
                        const int sx = x + rx - i, sy = y + ry - j;
                        const bool inside = sx >= 0 && sx < src.width && sy >= 0 && sy < src.height;
                        const double v = inside    ? src.at(c, sx, sy)
                                         : isConst ? constant
                                                   : src.at(c, borderIndex(sx, src.width, mode), borderIndex(sy, src.height, mode));
                        sum += k[size_t(j) * size_t(kw) + size_t(i)] * v;
                    }
                out.at(c, x, y) = float(absolute ? std::fabs(sum) : sum);
            }
    return out;
}

void expectNear(const PlanarImage& a, const PlanarImage& b, double tol, const std::string& what) {
    ASSERT_EQ(a.width, b.width) << what;
    ASSERT_EQ(a.height, b.height) << what;
    ASSERT_EQ(a.channels, b.channels) << what;
    int reported = 0;
    for (int c = 0; c < a.channels; ++c)
        for (int y = 0; y < a.height; ++y)
            for (int x = 0; x < a.width; ++x)
                if (!(std::fabs(a.at(c, x, y) - b.at(c, x, y)) <= tol) && reported++ < 5)
                    ADD_FAILURE() << what << ": at (" << x << ", " << y << ", channel " << c << ") " << a.at(c, x, y)
                                  << " vs " << b.at(c, x, y);
}

PlanarImage run(const std::string& spec, const PlanarImage& src, BorderMode mode, int threads = 2) {
    PlanarImage dst;
    applyKernel(parseKernelSpec(spec), src, dst, mode, threads);
    return dst;
}

std::string errorOf(const std::string& spec) {
    return rays::test::errorText([&] { parseKernelSpec(spec); });
}

std::string writeText(const fs::path& dir, const std::string& name, const std::string& text) {
    const fs::path p = dir / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
}

// ---- kernel specs --------------------------------------------------------------------------------

TEST(FilterKernels, OriginalCoefficientsExactly) {
    const KernelSpec e1 = parseKernelSpec("edge_detect_1");
    EXPECT_EQ(e1.kind, KernelKind::EdgeDetect1);
    EXPECT_TRUE(e1.absolute);
    EXPECT_EQ(e1.weights, (std::vector<double>{0, -0.25, 0, -0.25, 1, -0.25, 0, -0.25, 0}));

    const KernelSpec e2 = parseKernelSpec("edge_detect_2");
    EXPECT_TRUE(e2.absolute);
    EXPECT_EQ(e2.weights, (std::vector<double>{-0.125, -0.125, -0.125, -0.125, 1, -0.125, -0.125, -0.125, -0.125}));

    const KernelSpec box = parseKernelSpec("box_blur_5");
    EXPECT_EQ(box.width, 5);
    EXPECT_EQ(box.weights, std::vector<double>(25, 1.0 / 25));

    EXPECT_EQ(parseKernelSpec("brighten_1.5").factor, 1.5);
    EXPECT_EQ(parseKernelSpec("brighten_2").factor, 2.0);
    EXPECT_EQ(parseKernelSpec("sharpen").weights, (std::vector<double>{0, -1, 0, -1, 5, -1, 0, -1, 0}));
    EXPECT_EQ(parseKernelSpec("emboss").weights, (std::vector<double>{-2, -1, 0, -1, 1, 1, 0, 1, 2}));
    EXPECT_FALSE(parseKernelSpec("sharpen").absolute);
    EXPECT_EQ(parseKernelSpec("median_5").width, 5);
    EXPECT_EQ(parseKernelSpec("sobel").kind, KernelKind::Sobel);
}

TEST(FilterKernels, GaussianWeightsSumToOneAndSigmaDefaultsToNOverSix) {
    const KernelSpec g = parseKernelSpec("gaussian_blur_9");
    EXPECT_DOUBLE_EQ(g.sigma, 1.5);
    EXPECT_DOUBLE_EQ(parseKernelSpec("gaussian_blur_33").sigma, 5.5);
    EXPECT_DOUBLE_EQ(parseKernelSpec("gaussian_blur_9:2.5").sigma, 2.5);
    double sum2d = 0;
    for (double w : g.weights) sum2d += w;
    EXPECT_NEAR(sum2d, 1.0, 1e-12);

    for (int n : {1, 3, 9, 33}) {
        const std::vector<double> w = gaussianWeights(n, n / 6.0);
        double sum = 0;
        for (double v : w) sum += v;
        EXPECT_NEAR(sum, 1.0, 1e-12) << n;
        const int r = n / 2;
        for (int i = 0; i < r; ++i) {
            EXPECT_DOUBLE_EQ(w[size_t(i)], w[size_t(n - 1 - i)]);  // symmetric
            // w(d) ∝ exp(-d²/2σ²)
            const double d = r - i;
            EXPECT_NEAR(w[size_t(i)] / w[size_t(r)], std::exp(-d * d / (2 * (n / 6.0) * (n / 6.0))), 1e-12);
        }
    }
    // The 2-D kernel is the outer product of the 1-D weights.
    const std::vector<double> g1 = gaussianWeights(9, 1.5);
    EXPECT_NEAR(g.weights[2 * 9 + 7], g1[2] * g1[7], 1e-15);
}

TEST(FilterKernels, BadSpecsThrowWithTheExpectedMessages) {
    EXPECT_EQ(errorOf("box_blur_4"), "rays: error: kernel 'box_blur_4': the size must be odd and positive, got 4");
    EXPECT_EQ(errorOf("box_blur_0"), "rays: error: kernel 'box_blur_0': the size must be odd and positive, got 0");
    EXPECT_EQ(errorOf("box_blur_-3"), "rays: error: kernel 'box_blur_-3': the size must be odd and positive, got -3");
    EXPECT_EQ(errorOf("box_blur_x"), "rays: error: kernel 'box_blur_x': the size must be an odd positive integer, got 'x'");
    EXPECT_EQ(errorOf("box_blur_"), "rays: error: kernel 'box_blur_': the size must be an odd positive integer, got ''");
    EXPECT_EQ(errorOf("box_blur_3.0"), "rays: error: kernel 'box_blur_3.0': the size must be an odd positive integer, got '3.0'");
    EXPECT_EQ(errorOf("gaussian_blur_8"), "rays: error: kernel 'gaussian_blur_8': the size must be odd and positive, got 8");
    EXPECT_EQ(errorOf("gaussian_blur_5:0"), "rays: error: kernel 'gaussian_blur_5:0': sigma must be a positive number, got '0'");
    EXPECT_EQ(errorOf("gaussian_blur_5:abc"), "rays: error: kernel 'gaussian_blur_5:abc': sigma must be a positive number, got 'abc'");
    EXPECT_EQ(errorOf("median_2"), "rays: error: kernel 'median_2': the size must be odd and positive, got 2");
    EXPECT_EQ(errorOf("median_99"), "rays: error: kernel 'median_99': the size must be at most 51, got 99");
    EXPECT_EQ(errorOf("box_blur_99999999999"), "rays: error: kernel 'box_blur_99999999999': the size must be at most 1001, got 99999999999");
    EXPECT_EQ(errorOf("brighten_x"), "rays: error: kernel 'brighten_x': the factor must be a non-negative number, got 'x'");
    EXPECT_EQ(errorOf("brighten_-1"), "rays: error: kernel 'brighten_-1': the factor must be a non-negative number, got '-1'");
    EXPECT_EQ(errorOf("kernel:"), "rays: error: kernel 'kernel:': missing file name (kernel:FILE)");
    const std::string valid = "(valid: " + validKernelNames() + ")";
    EXPECT_EQ(errorOf("blur"), "rays: error: unknown kernel 'blur' " + valid);
    EXPECT_EQ(errorOf("edge_detect_3"), "rays: error: unknown kernel 'edge_detect_3' " + valid);
    EXPECT_EQ(errorOf("Sobel"), "rays: error: unknown kernel 'Sobel' " + valid);
    for (const char* name : {"box_blur_N", "gaussian_blur_N", "edge_detect_1", "edge_detect_2", "brighten_X", "sobel",
                             "sharpen", "emboss", "median_N", "kernel:FILE"})
        EXPECT_NE(valid.find(name), std::string::npos) << name;
}

TEST(FilterKernels, ListsSplitAtCommas) {
    EXPECT_EQ(splitKernelList("box_blur_3,gaussian_blur_5:1.5,sobel"),
              (std::vector<std::string>{"box_blur_3", "gaussian_blur_5:1.5", "sobel"}));
    EXPECT_EQ(splitKernelList("sharpen"), (std::vector<std::string>{"sharpen"}));
    EXPECT_THROW(splitKernelList("sharpen,,sobel"), Error);
    EXPECT_THROW(splitKernelList(""), Error);
    EXPECT_EQ(parseKernelList({"sharpen", "median_3"}).size(), 2u);
    EXPECT_THROW(parseKernelList({"sharpen", "median_4"}), Error);
}

TEST(FilterKernels, BorderModeNames) {
    for (BorderMode m : kModes) EXPECT_EQ(parseBorderMode(borderModeName(m)), m);
    try {
        parseBorderMode("mirror");
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "rays: error: unknown border mode 'mirror' (use clamp, zero, white or reflect)");
    }
}

// ---- custom kernel files ---------------------------------------------------------------------------

TEST(FilterKernelFile, RoundTripWithCommentsDivisorAndAbsolute) {
    test::TempDir dir;
    const std::string path = writeText(dir.path(), "k.txt",
                                       "# an asymmetric 3x5 kernel\n"
                                       "\n"
                                       "divisor 4   # every weight / 4\n"
                                       "  1 2 3 4 5\n"
                                       "\t0 0 -8 0 0\r\n"
                                       "-1 -2 -3 -4 -5.5 # trailing comment\n"
                                       "absolute\n");
    const KernelSpec k = parseKernelSpec("kernel:" + path);
    EXPECT_EQ(k.kind, KernelKind::Custom);
    EXPECT_EQ(k.text, "kernel:" + path);
    EXPECT_EQ(k.file, path);
    EXPECT_EQ(k.width, 5);
    EXPECT_EQ(k.height, 3);
    EXPECT_TRUE(k.absolute);
    EXPECT_EQ(k.weights, (std::vector<double>{0.25, 0.5, 0.75, 1, 1.25, 0, 0, -2, 0, 0, -0.25, -0.5, -0.75, -1, -1.375}));

    // The impulse response is the kernel itself (absolute values here).
    PlanarImage img(11, 9, 1);
    img.at(0, 5, 4) = 1;
    const PlanarImage out = run("kernel:" + path, img, BorderMode::Zero);
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 11; ++x) {
            const int i = x - 5 + 2, j = y - 4 + 1;
            const double want = (i >= 0 && i < 5 && j >= 0 && j < 3) ? std::fabs(k.weights[size_t(j * 5 + i)]) : 0.0;
            EXPECT_NEAR(out.at(0, x, y), want, 1e-6) << x << "," << y;
        }
}

TEST(FilterKernelFile, ErrorsNameTheFileAndLine) {
    test::TempDir dir;
    auto errorFor = [&](const std::string& text) {
        const std::string p = writeText(dir.path(), "bad.txt", text);
        try {
            parseKernelSpec("kernel:" + p);
        } catch (const Error& e) {
            const std::string msg = e.what();
            EXPECT_EQ(msg.rfind(p, 0), 0u) << msg;  // starts with the file's path
            return msg.substr(p.size());
        }
        return std::string("(no error)");
    };
    EXPECT_EQ(errorFor("1 2 3\n4 5\n7 8 9\n"),
              ":2:1: error: ragged kernel: this row has 2 values but the first row (line 1) has 3");
    EXPECT_EQ(errorFor("# c\n1 2\n3 4\n"), ":2:1: error: kernel rows have 2 values; the width must be odd");
    EXPECT_EQ(errorFor("1 2 3\n4 5 6\n"), ":2:1: error: kernel has 2 rows; the number of rows must be odd");
    EXPECT_EQ(errorFor("1 2 3\n4 x 6\n7 8 9\n"), ":2:3: error: expected a number, 'divisor D' or 'absolute', got 'x'");
    EXPECT_EQ(errorFor("divisor 0\n1\n"), ":1:9: error: the divisor must not be zero");
    EXPECT_EQ(errorFor("divisor\n1\n"), ":1:1: error: expected 'divisor D' with one number D");
    EXPECT_EQ(errorFor("divisor 2\ndivisor 3\n1\n"), ":2:1: error: 'divisor' given twice (first on line 1)");
    EXPECT_EQ(errorFor("# nothing\n\n"), ": error: kernel file has no rows of numbers");

    const std::string missing = (dir.path() / "missing.txt").string();
    try {
        parseKernelSpec("kernel:" + missing);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), missing + ": error: cannot read kernel file: No such file or directory");
    }
}

// ---- impulse responses -----------------------------------------------------------------------------

TEST(FilterImpulse, ResponseEqualsTheKernelForEveryLinearKind) {
    test::TempDir dir;
    // Asymmetric, not separable: catches a flipped (correlation) implementation.
    const std::string asym = writeText(dir.path(), "asym.txt", "1 2 0\n0 3 0\n0 0 -4\n");
    // Asymmetric and separable (rank 1), 5x5: takes the separable path.
    const std::string rank1 = writeText(dir.path(), "rank1.txt",
                                        "1 2 3 4 5\n2 4 6 8 10\n0 0 0 0 0\n-1 -2 -3 -4 -5\n3 6 9 12 15\ndivisor 10\n");
    const int w = 41, h = 37, cx = 20, cy = 18;
    PlanarImage img(w, h, 2);
    img.at(0, cx, cy) = 1;
    img.at(1, cx, cy) = 0.5f;
    for (const std::string& spec : std::vector<std::string>{"box_blur_5", "box_blur_1", "gaussian_blur_7", "gaussian_blur_7:1", "gaussian_blur_15",
                                   "edge_detect_1", "edge_detect_2", "sharpen", "emboss", "kernel:" + asym,
                                   "kernel:" + rank1}) {
        const KernelSpec k = parseKernelSpec(spec);
        ASSERT_TRUE(isConvolution(k)) << spec;
        for (BorderMode mode : {BorderMode::Zero, BorderMode::Clamp, BorderMode::Reflect}) {
            const PlanarImage out = run(spec, img, mode);
            for (int c = 0; c < 2; ++c)
                for (int y = 0; y < h; ++y)
                    for (int x = 0; x < w; ++x) {
                        const int i = x - cx + k.width / 2, j = y - cy + k.height / 2;
                        double want = (i >= 0 && i < k.width && j >= 0 && j < k.height)
                                          ? k.weights[size_t(j) * size_t(k.width) + size_t(i)] * (c == 0 ? 1.0 : 0.5)
                                          : 0.0;
                        if (k.absolute) want = std::fabs(want);
                        ASSERT_NEAR(out.at(c, x, y), want, 1e-6) << spec << " at " << x << "," << y << " channel " << c;
                    }
        }
    }
}

TEST(FilterImpulse, SobelBrightenAndMedian) {
    const int w = 9, h = 7, cx = 4, cy = 3;
    PlanarImage img(w, h, 1);
    img.at(0, cx, cy) = 1;
    // Sobel: |(Gx, Gy)| of the two 3x3 kernels: √2 at the corners, 2 at the edge centres, 0 in the middle.
    const PlanarImage s = run("sobel", img, BorderMode::Zero);
    const double r2 = std::sqrt(2.0);
    const double want[3][3] = {{r2, 2, r2}, {2, 0, 2}, {r2, 2, r2}};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int i = x - cx + 1, j = y - cy + 1;
            const double v = (i >= 0 && i < 3 && j >= 0 && j < 3) ? want[j][i] : 0.0;
            EXPECT_NEAR(s.at(0, x, y), v, 1e-6) << x << "," << y;
        }
    // Brighten: the impulse scaled.
    const PlanarImage b = run("brighten_2.5", img, BorderMode::Zero);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) EXPECT_EQ(b.at(0, x, y), (x == cx && y == cy) ? 2.5f : 0.0f);
    // Median: a single bright pixel disappears.
    for (const char* spec : {"median_3", "median_5"}) {
        const PlanarImage m = run(spec, img, BorderMode::Zero);
        for (float v : m.data) EXPECT_EQ(v, 0.0f) << spec;
    }
}

TEST(FilterImpulse, SobelOfAUnitStepIsFour) {
    PlanarImage img(8, 5, 1);
    for (int y = 0; y < 5; ++y)
        for (int x = 4; x < 8; ++x) img.at(0, x, y) = 1;
    const PlanarImage s = run("sobel", img, BorderMode::Clamp);
    for (int y = 0; y < 5; ++y) {
        EXPECT_NEAR(s.at(0, 3, y), 4.0f, 1e-6);
        EXPECT_NEAR(s.at(0, 4, y), 4.0f, 1e-6);
        EXPECT_NEAR(s.at(0, 1, y), 0.0f, 1e-6);
        EXPECT_NEAR(s.at(0, 6, y), 0.0f, 1e-6);
    }
}

// ---- fast paths against the reference ---------------------------------------------------------------

TEST(FilterPaths, SeparableRunningSumAndDirectMatchTheReference) {
    // 70 wide: one full vectorised block and an overlapping or scalar tail; 280 tall: more than
    // one band of rows for every filter (bands restart the running sums).
    const PlanarImage src = noise(70, 280, 2);
    for (BorderMode mode : kModes) {
        const std::string m = borderModeName(mode);
        for (int n : {1, 3, 9, 21}) {
            const std::vector<double> box(size_t(n) * size_t(n), 1.0 / (n * n));
            const PlanarImage want = reference(src, box, n, n, mode);
            PlanarImage running, separable, direct;
            boxBlur(src, running, n, mode, 3);
            convolveSeparable(src, separable, std::vector<float>(size_t(n), 1.0f / float(n)),
                              std::vector<float>(size_t(n), 1.0f / float(n)), mode, false, 3);
            const std::vector<float> boxF(box.begin(), box.end());
            convolveDirect(src, direct, boxF.data(), n, n, mode, false, 3);
            expectNear(running, want, 1e-5, "running-sum box " + std::to_string(n) + " " + m);
            expectNear(separable, want, 1e-5, "separable box " + std::to_string(n) + " " + m);
            expectNear(direct, want, 1e-5, "direct box " + std::to_string(n) + " " + m);
            expectNear(running, direct, 1e-5, "running-sum vs direct " + std::to_string(n) + " " + m);
        }
        for (const char* spec : {"gaussian_blur_11", "gaussian_blur_5:3"}) {
            const KernelSpec k = parseKernelSpec(spec);
            const PlanarImage got = run(spec, src, mode);
            const std::vector<float> kf(k.weights.begin(), k.weights.end());
            PlanarImage direct;
            convolveDirect(src, direct, kf.data(), k.width, k.height, mode, false, 2);
            expectNear(got, direct, 1e-5, std::string(spec) + " separable vs direct " + m);
            expectNear(got, reference(src, k.weights, k.width, k.height, mode), 1e-5, std::string(spec) + " " + m);
        }
        for (const char* spec : {"edge_detect_1", "edge_detect_2", "sharpen", "emboss"}) {
            const KernelSpec k = parseKernelSpec(spec);
            expectNear(run(spec, src, mode), reference(src, k.weights, 3, 3, mode, k.absolute), 1e-5, std::string(spec) + " " + m);
        }
        // Sobel against two reference convolutions.
        const std::vector<double> gx = {-1, 0, 1, -2, 0, 2, -1, 0, 1}, gy = {-1, -2, -1, 0, 0, 0, 1, 2, 1};
        const PlanarImage rx = reference(src, gx, 3, 3, mode), ry = reference(src, gy, 3, 3, mode);
        PlanarImage mag(src.width, src.height, src.channels);
        for (size_t i = 0; i < mag.data.size(); ++i) mag.data[i] = std::hypot(rx.data[i], ry.data[i]);
        expectNear(run("sobel", src, mode), mag, 1e-5, "sobel " + m);
    }
}

TEST(FilterPaths, StripsOfColumnsJoinSeamlessly) {
    // Wider than one strip of columns (512): 1030 = 512 + 512 + 6, so a window's halo reaches
    // across strips and past the narrow last strip.
    const PlanarImage src = noise(1030, 7, 1, 5);
    for (BorderMode mode : kModes) {
        const std::string m = borderModeName(mode);
        for (const char* spec : {"gaussian_blur_9", "gaussian_blur_41:20", "edge_detect_2", "emboss"}) {
            const KernelSpec k = parseKernelSpec(spec);
            expectNear(run(spec, src, mode), reference(src, k.weights, k.width, k.height, mode, k.absolute), 1e-5,
                       std::string(spec) + " " + m);
        }
        const std::vector<double> gx = {-1, 0, 1, -2, 0, 2, -1, 0, 1}, gy = {-1, -2, -1, 0, 0, 0, 1, 2, 1};
        const PlanarImage rx = reference(src, gx, 3, 3, mode), ry = reference(src, gy, 3, 3, mode);
        PlanarImage mag(src.width, src.height, 1);
        for (size_t i = 0; i < mag.data.size(); ++i) mag.data[i] = std::hypot(rx.data[i], ry.data[i]);
        expectNear(run("sobel", src, mode), mag, 1e-5, "sobel " + m);
        PlanarImage m3;
        medianFilter(src, m3, 3, mode, 2);
        for (int y = 0; y < src.height; ++y)
            for (int x = 0; x < src.width; ++x) {
                std::vector<float> win;
                for (int j = -1; j <= 1; ++j)
                    for (int i = -1; i <= 1; ++i) {
                        const int sx = x + i, sy = y + j;
                        if (sx >= 0 && sx < src.width && sy >= 0 && sy < src.height) win.push_back(src.at(0, sx, sy));
                        else if (mode == BorderMode::Zero || mode == BorderMode::White) win.push_back(borderConstant(mode));
                        else win.push_back(src.at(0, borderIndex(sx, src.width, mode), borderIndex(sy, src.height, mode)));
                    }
                std::nth_element(win.begin(), win.begin() + 4, win.end());
                ASSERT_EQ(m3.at(0, x, y), win[4]) << m << " " << x << "," << y;
            }
    }
}

TEST(FilterPaths, KernelsWiderThanTheImage) {
    const PlanarImage src = noise(5, 4, 1, 7);
    for (BorderMode mode : kModes) {
        const std::vector<double> box(31 * 31, 1.0 / (31 * 31));
        const PlanarImage want = reference(src, box, 31, 31, mode);
        expectNear(run("box_blur_31", src, mode), want, 1e-5, std::string("box_blur_31 ") + borderModeName(mode));
        const KernelSpec g = parseKernelSpec("gaussian_blur_13");
        expectNear(run("gaussian_blur_13", src, mode), reference(src, g.weights, 13, 13, mode), 1e-5,
                   std::string("gaussian_blur_13 ") + borderModeName(mode));
    }
}

TEST(FilterPaths, MedianMatchesSortingEveryWindow) {
    const PlanarImage src = noise(69, 20, 1, 3);
    for (BorderMode mode : kModes)
        for (int n : {3, 5}) {
            PlanarImage got;
            medianFilter(src, got, n, mode, 2);
            const int r = n / 2;
            for (int y = 0; y < src.height; ++y)
                for (int x = 0; x < src.width; ++x) {
                    std::vector<float> win;
                    for (int j = -r; j <= r; ++j)
                        for (int i = -r; i <= r; ++i) {
                            const int sx = x + i, sy = y + j;
                            if (sx >= 0 && sx < src.width && sy >= 0 && sy < src.height) win.push_back(src.at(0, sx, sy));
                            else if (mode == BorderMode::Zero) win.push_back(0);
                            else if (mode == BorderMode::White) win.push_back(1);
                            else win.push_back(src.at(0, borderIndex(sx, src.width, mode), borderIndex(sy, src.height, mode)));
                        }
                    std::sort(win.begin(), win.end());
                    ASSERT_EQ(got.at(0, x, y), win[win.size() / 2]) << "median_" << n << " at " << x << "," << y;
                }
        }
}

TEST(FilterPaths, MedianRemovesASingleOutlier) {
    PlanarImage img = constantImage(80, 10, 0.3f);
    img.at(0, 40, 5) = 1.0f;
    img.at(0, 0, 0) = 0.0f;  // in the corner too
    for (const char* spec : {"median_3", "median_5"})
        for (float v : run(spec, img, BorderMode::Clamp).data) EXPECT_EQ(v, 0.3f) << spec;
}

TEST(FilterPaths, ResultsDoNotDependOnTheThreadCount) {
    const PlanarImage src = noise(131, 300, 3, 11);
    for (const char* spec : {"box_blur_9", "gaussian_blur_7", "edge_detect_2", "sobel", "median_3", "brighten_1.5"}) {
        PlanarImage one, many;
        applyKernel(parseKernelSpec(spec), src, one, BorderMode::Reflect, 1);
        applyKernel(parseKernelSpec(spec), src, many, BorderMode::Reflect, 5);
        EXPECT_TRUE(one.data == many.data) << spec;
    }
}

TEST(FilterPaths, SplitSeparable) {
    std::vector<float> h, v;
    EXPECT_TRUE(splitSeparable({1, 2, 1, 2, 4, 2, 1, 2, 1}, 3, 3, h, v));
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(v[size_t(j)] * h[size_t(i)], float((j == 1 ? 2 : 1) * (i == 1 ? 2 : 1)));
    EXPECT_FALSE(splitSeparable({0, -1, 0, -1, 4, -1, 0, -1, 0}, 3, 3, h, v));
    EXPECT_TRUE(splitSeparable({0, 0, 0}, 3, 1, h, v));
}

// ---- border modes on a hand-computed image ---------------------------------------------------------

TEST(FilterBorder, EachModeOnAKnownImage) {
    // One row [0, 0.5, 1] blurred with 3x3 box (sum of 9 values / 9):
    //  clamp:   rows above/below repeat the row; x = -1 is 0, x = 3 is 1     -> 0.5/3, 1.5/3, 2.5/3
    //  zero:    only the row itself counts; outside is 0                      -> 0.5/9, 1.5/9, 1.5/9
    //  white:   six 1s from the rows above and below, outside columns are 1   -> 7.5/9, 7.5/9, 8.5/9
    //  reflect: a single row mirrors onto itself; x = -1 is 0.5, x = 3 is 0.5 -> 1/3, 1.5/3, 2/3
    const float want[4][3] = {{0.5f / 3, 0.5f, 2.5f / 3}, {0.5f / 9, 1.5f / 9, 1.5f / 9}, {7.5f / 9, 7.5f / 9, 8.5f / 9},
                              {1.0f / 3, 0.5f, 2.0f / 3}};
    PlanarImage row(3, 1, 1), col(1, 3, 1);
    row.data = col.data = {0.0f, 0.5f, 1.0f};
    for (int m = 0; m < 4; ++m) {
        const BorderMode mode = kModes[m];
        PlanarImage a, b, c;
        boxBlur(row, a, 3, mode, 1);
        convolveSeparable(row, b, {1 / 3.f, 1 / 3.f, 1 / 3.f}, {1 / 3.f, 1 / 3.f, 1 / 3.f}, mode, false, 1);
        const std::vector<float> k(9, 1 / 9.f);
        convolveDirect(row, c, k.data(), 3, 3, mode, false, 1);
        PlanarImage t;
        boxBlur(col, t, 3, mode, 1);  // the same image standing up
        for (int x = 0; x < 3; ++x) {
            EXPECT_NEAR(a.data[size_t(x)], want[m][x], 1e-6) << borderModeName(mode) << " running sum x=" << x;
            EXPECT_NEAR(b.data[size_t(x)], want[m][x], 1e-6) << borderModeName(mode) << " separable x=" << x;
            EXPECT_NEAR(c.data[size_t(x)], want[m][x], 1e-6) << borderModeName(mode) << " direct x=" << x;
            EXPECT_NEAR(t.data[size_t(x)], want[m][x], 1e-6) << borderModeName(mode) << " vertical y=" << x;
        }
    }
    // A 5-wide 1-D mean on [0, 0.5, 1] with reflect sees 1 0.5 | 0 0.5 1 | 0.5 0.
    PlanarImage r;
    convolveSeparable(row, r, std::vector<float>(5, 0.2f), {1.0f}, BorderMode::Reflect, false, 1);
    EXPECT_NEAR(r.data[0], (1 + 0.5 + 0 + 0.5 + 1) / 5, 1e-6);
    EXPECT_NEAR(r.data[1], (0.5 + 0 + 0.5 + 1 + 0.5) / 5, 1e-6);
    EXPECT_NEAR(r.data[2], (0 + 0.5 + 1 + 0.5 + 0) / 5, 1e-6);
}

TEST(FilterBorder, ReflectAndClampIndices) {
    // reflect: ... 0 1 2 3 2 1 | 0 1 2 3 | 2 1 0 1 ...
    const int want[] = {0, 1, 2, 3, 2, 1, 0, 1, 2, 3, 2, 1, 0};
    for (int i = -6; i <= 6; ++i) EXPECT_EQ(borderIndex(i, 4, BorderMode::Reflect), want[i + 6]) << i;
    EXPECT_EQ(borderIndex(-5, 1, BorderMode::Reflect), 0);
    EXPECT_EQ(borderIndex(-5, 4, BorderMode::Clamp), 0);
    EXPECT_EQ(borderIndex(9, 4, BorderMode::Clamp), 3);
}

TEST(FilterEdge, EdgeKernelsGiveZeroOnFlatImages) {
    for (const char* spec : {"edge_detect_1", "edge_detect_2", "sobel"}) {
        for (BorderMode mode : {BorderMode::Clamp, BorderMode::Reflect})
            for (float v : run(spec, constantImage(75, 9, 0.6f), mode).data) ASSERT_NEAR(v, 0.0f, 1e-6) << spec;
        // With a constant border equal to the image, too.
        for (float v : run(spec, constantImage(75, 9, 1.0f), BorderMode::White).data) ASSERT_NEAR(v, 0.0f, 1e-6) << spec;
        for (float v : run(spec, constantImage(75, 9, 0.0f), BorderMode::Zero).data) ASSERT_NEAR(v, 0.0f, 1e-6) << spec;
    }
    // ...but not at the edge of a grey image padded with white (the original's behaviour): |0.6 - 1| / 4 · 2.
    const PlanarImage e = run("edge_detect_1", constantImage(5, 5, 0.6f), BorderMode::White);
    EXPECT_NEAR(e.at(0, 0, 0), 0.2f, 1e-6);
    EXPECT_NEAR(e.at(0, 2, 0), 0.1f, 1e-6);
    EXPECT_NEAR(e.at(0, 2, 2), 0.0f, 1e-6);
}

// ---- 8-bit and float images ------------------------------------------------------------------------

TEST(FilterImage8, AlphaIsKeptAndColourFiltered) {
    for (int channels : {2, 4}) {
        Image8 img(67, 19, channels);
        for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = uint8_t((i * 37 + i / 7) % 256);
        const Image8 out = applyFilters(img, parseKernelList({"box_blur_3", "sobel", "brighten_0.7"}), BorderMode::White, 2);
        ASSERT_EQ(out.channels, channels);
        ASSERT_EQ(out.width, img.width);
        ASSERT_EQ(out.height, img.height);
        bool colourChanged = false;
        for (size_t p = 0; p < size_t(img.width) * size_t(img.height); ++p) {
            const size_t a = p * size_t(channels) + size_t(channels - 1);
            ASSERT_EQ(out.pixels[a], img.pixels[a]) << "alpha of pixel " << p;
            colourChanged = colourChanged || out.pixels[a - 1] != img.pixels[a - 1];
        }
        EXPECT_TRUE(colourChanged);
    }
}

TEST(FilterImage8, MatchesTheFloatFilterRoundedOnce) {
    Image8 img(70, 12, 3);
    for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = uint8_t((i * 53) % 251);
    const auto kernels = parseKernelList({"gaussian_blur_5", "sharpen"});
    const Image8 out = applyFilters(img, kernels, BorderMode::Reflect, 2);
    PlanarImage p(70, 12, 3);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 70; ++x)
            for (int c = 0; c < 3; ++c) p.at(c, x, y) = img.pixels[size_t((y * 70 + x) * 3 + c)] / 255.0f;
    applyFilters(p, kernels, BorderMode::Reflect, 1);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 70; ++x)
            for (int c = 0; c < 3; ++c) {
                const double v = std::clamp(double(p.at(c, x, y)) * 255.0, 0.0, 255.0);
                ASSERT_LE(std::fabs(out.pixels[size_t((y * 70 + x) * 3 + c)] - v), 0.5 + 1e-3);
            }
    // No kernels: the same image.
    EXPECT_EQ(applyFilters(img, {}, BorderMode::Clamp, 1).pixels, img.pixels);
    // Rounded once at the end: 3 · 0.5 · 2 stays 3 (rounding after each kernel would give 2 · 2 = 4).
    Image8 three(1, 1, 1);
    three.pixels = {3};
    EXPECT_EQ(applyFilters(three, parseKernelList({"brighten_0.5", "brighten_2"})).pixels[0], 3);
    // Out-of-range results clamp.
    three.pixels = {200};
    EXPECT_EQ(applyFilters(three, parseKernelList({"brighten_2"})).pixels[0], 255);
}

TEST(FilterImageF, FloatImagesAreNotClamped) {
    ImageF img(70, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 70; ++x) img.at(x, y) = Vec3(0.8, 0.25 * y, x / 70.0);
    const ImageF out = applyFilters(img, parseKernelList({"brighten_2"}), BorderMode::Clamp, 2);
    ASSERT_EQ(out.width, 70);
    ASSERT_EQ(out.height, 3);
    EXPECT_NEAR(out.at(5, 2).x, 1.6, 1e-6);
    EXPECT_NEAR(out.at(5, 2).y, 1.0, 1e-6);
    EXPECT_NEAR(out.at(35, 1).z, 1.0, 1e-6);
    const ImageF blurred = applyFilters(img, parseKernelList({"box_blur_3"}), BorderMode::Clamp, 2);
    EXPECT_NEAR(blurred.at(10, 1).y, 0.25, 1e-6);
    EXPECT_NEAR(blurred.at(10, 0).y, (0 + 0 + 0.25) / 3, 1e-6);
    EXPECT_TRUE(applyFilters(img, {}, BorderMode::Clamp, 2).pixels == img.pixels);
}

TEST(FilterParallel, ParallelForRunsEveryIndexOnceAndRethrows) {
    std::vector<int> hits(1000, 0);
    parallelFor(1000, 4, [&](int i) { hits[size_t(i)]++; });
    EXPECT_TRUE(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }));
    EXPECT_THROW(parallelFor(100, 3, [](int i) {
                     if (i == 42) throw Error("boom");
                 }),
                 Error);
    parallelFor(0, 4, [](int) { ADD_FAILURE(); });
    EXPECT_EQ(parallelThreadCount(3), 3);
    EXPECT_GE(parallelThreadCount(0), 1);
}

}}  // namespace RAYS_TEST_UNIT, namespace
