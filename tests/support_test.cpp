// Unit tests of the test-support helpers in tests/support/.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/image_compare.h"
#include "support/process.h"
#include "support/text_compare.h"

using namespace rays::test;

// ---- text_compare.h ----

TEST(TextCompare, NumbersWithinAbsoluteTolerance) {
    EXPECT_EQ(compareText("T = 12.0001", "T = 12.0010"), "");
    EXPECT_TRUE(tokensMatch("0.0000", "-0.0019"));
    EXPECT_FALSE(tokensMatch("0.0000", "0.0030"));
}

TEST(TextCompare, NumbersWithinRelativeTolerance) {
    // 0.1 % of 100 = 0.1 > 0.002.
    EXPECT_TRUE(tokensMatch("100.0000", "100.0900"));
    EXPECT_FALSE(tokensMatch("100.0000", "100.2000"));
}

TEST(TextCompare, RejectsNumberOutsideTolerance) {
    const std::string msg = compareText("T = 12.0", "T = 12.1");
    EXPECT_NE(msg, "");
    EXPECT_NE(msg.find("\"12.0\""), std::string::npos) << msg;
    EXPECT_NE(msg.find("\"12.1\""), std::string::npos) << msg;
}

TEST(TextCompare, IntegersWithinOne) {
    EXPECT_EQ(compareText("Color: (80, 80, 163)", "Color: (81, 79, 163)"), "");
    EXPECT_NE(compareText("Color: (80, 80, 163)", "Color: (82, 80, 163)"), "");
    EXPECT_TRUE(tokensMatch("80", "81"));
    EXPECT_FALSE(tokensMatch("80", "82"));
}

TEST(TextCompare, WordsMustBeEqual) {
    EXPECT_NE(compareText("Object Type: Sphere", "Object Type: Plane"), "");
    EXPECT_NE(compareText("(ID #1 - Sphere)", "(ID #2 - Sphere)"), "");
    EXPECT_FALSE(tokensMatch("-", "0"));
    EXPECT_FALSE(tokensMatch("nan", "nan1"));
}

TEST(TextCompare, TokenCountsMustBeEqual) {
    const std::string shorter = compareText("a b c", "a b");
    EXPECT_NE(shorter.find("ends early"), std::string::npos) << shorter;
    const std::string longer = compareText("a b", "a b c");
    EXPECT_NE(longer.find("extra"), std::string::npos) << longer;
    EXPECT_NE(compareText("x", ""), "");
}

TEST(TextCompare, WhitespaceAndPunctuationSpacingIgnored) {
    EXPECT_EQ(compareText("Pixel: [320, 240]\nT = 1.5\n", "Pixel:[320,240]   T=1.5"), "");
    EXPECT_EQ(compareText("a\r\nb\r\n", "a\nb"), "");
    // Punctuation is still compared as tokens.
    EXPECT_NE(compareText("{1 2 3}", "(1 2 3)"), "");
}

TEST(TextCompare, MismatchReportsLinesAndContext) {
    const std::string msg = compareText("Camera:\n- Location: {0 0 14}\n", "Camera:\n- Location: {0 0 15.5}\n");
    EXPECT_NE(msg.find("line 2"), std::string::npos) << msg;
    EXPECT_NE(msg.find("- Location: {0 0 15.5}"), std::string::npos) << msg;
}

TEST(TextCompare, ParseNumber) {
    double v = 0;
    bool isInt = false;
    EXPECT_TRUE(parseNumber("-0.0919", v, isInt));
    EXPECT_DOUBLE_EQ(v, -0.0919);
    EXPECT_FALSE(isInt);
    EXPECT_TRUE(parseNumber("+203", v, isInt));
    EXPECT_DOUBLE_EQ(v, 203);
    EXPECT_TRUE(isInt);
    EXPECT_TRUE(parseNumber("1e-3", v, isInt));
    EXPECT_FALSE(isInt);
    for (const char* s : {"", "-", ".", "e5", "1e", "0x10", "inf", "nan", "1.2.3", "->", "#1"})
        EXPECT_FALSE(parseNumber(s, v, isInt)) << s;
}

TEST(TextCompare, Tokenize) {
    const auto t = tokenizeText("Pixel: [320, 240]\n  T = 12.0001");
    std::vector<std::string> texts;
    for (const auto& tok : t) texts.push_back(tok.text);
    EXPECT_EQ(texts, (std::vector<std::string>{"Pixel", ":", "[", "320", ",", "240", "]", "T", "=", "12.0001"}));
    EXPECT_EQ(t.front().line, 1);
    EXPECT_EQ(t.back().line, 2);
}

// ---- image_compare.h ----

namespace { namespace RAYS_TEST_UNIT {
std::vector<uint8_t> gradient(int w, int h) {
    std::vector<uint8_t> px(size_t(w) * size_t(h) * 3);
    for (size_t i = 0; i < px.size(); ++i) px[i] = uint8_t((i * 7) % 251);
    return px;
}

TEST(ImageCompare, IdenticalMatches) {
    const auto a = gradient(100, 100);
    const ImageDiff d = compareRgb(a.data(), a.data(), 100 * 100);
    EXPECT_EQ(d.fractionOver, 0.0);
    EXPECT_EQ(d.meanAbs, 0.0);
    EXPECT_EQ(d.maxDiff, 0);
    EXPECT_TRUE(d.matches());
}

TEST(ImageCompare, OnePixelFarOffStillMatches) {
    std::vector<uint8_t> a(100 * 100 * 3, 20);
    auto b = a;
    b[3 * 4321 + 1] = 220;  // one pixel, one channel, off by 200
    const ImageDiff d = compareRgb(a.data(), b.data(), 100 * 100);
    EXPECT_DOUBLE_EQ(d.fractionOver, 1e-4);
    EXPECT_EQ(d.maxDiff, 200);
    EXPECT_TRUE(d.matches()) << d.describe();
}

TEST(ImageCompare, OnePercentOffByTenFails) {
    std::vector<uint8_t> a(100 * 100 * 3, 100);
    auto b = a;
    for (size_t p = 0; p < 100; ++p) b[3 * (p * 97)] = 110;  // 100 distinct pixels = 1 %
    const ImageDiff d = compareRgb(a.data(), b.data(), 100 * 100);
    EXPECT_DOUBLE_EQ(d.fractionOver, 0.01);
    EXPECT_FALSE(d.matches()) << d.describe();
}

TEST(ImageCompare, UniformOffsetOfTwoFailsOnMean) {
    std::vector<uint8_t> a(100 * 100 * 3, 100);
    std::vector<uint8_t> b(a.size(), 102);
    const ImageDiff d = compareRgb(a.data(), b.data(), 100 * 100);
    EXPECT_EQ(d.fractionOver, 0.0);  // 2 <= 5 levels
    EXPECT_NEAR(d.meanAbs, 2.0 / 255.0, 1e-12);
    EXPECT_FALSE(d.matches()) << d.describe();
}

TEST(ImageCompare, UniformOffsetOfOneMatches) {
    std::vector<uint8_t> a(10 * 10 * 3, 100);
    std::vector<uint8_t> b(a.size(), 99);
    EXPECT_TRUE(compareRgb(a.data(), b.data(), 10 * 10).matches());
}

TEST(ImageCompare, SizeMismatchNeverMatches) {
    RgbImage a{4, 4, std::vector<uint8_t>(4 * 4 * 3, 0), {}};
    RgbImage b{4, 3, std::vector<uint8_t>(4 * 3 * 3, 0), {}};
    const ImageDiff d = compareImages(a, b);
    EXPECT_FALSE(d.sameSize);
    EXPECT_FALSE(d.matches());
    EXPECT_TRUE(compareImages(a, a).matches());
}

TEST(ImageCompare, LoadMissingFileReportsError) {
    const RgbImage img = loadPngRgb("/nonexistent/rays-no-such-image.png");
    EXPECT_FALSE(img.ok());
    EXPECT_NE(img.error.find("/nonexistent/rays-no-such-image.png"), std::string::npos) << img.error;
}

TEST(ImageCompare, LoadShippedPng) {
    const std::filesystem::path png = std::filesystem::path(RAYS_SOURCE_DIR) / "scenes" / "textures" / "checker.png";
    const RgbImage img = loadPngRgb(png.string());
    ASSERT_TRUE(img.ok()) << img.error;
    EXPECT_EQ(img.width, 256);
    EXPECT_EQ(img.height, 256);
    EXPECT_EQ(img.pixels.size(), size_t(256) * 256 * 3);
}

// ---- process.h ----

TEST(Process, CapturesStdout) {
    const ProcessResult r = runProcess("/bin/echo", {"hello", "two words"});
    EXPECT_TRUE(r.ok()) << r.summary();
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, "hello two words\n");
    EXPECT_EQ(r.err, "");
}

TEST(Process, ReportsNonZeroExit) {
    const ProcessResult r = runProcess("/bin/false", {});
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_GT(r.exitCode, 0);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.summary(), "exit status " + std::to_string(r.exitCode));
}

TEST(Process, RunsInWorkingDirectory) {
    TempDir dir("rays-support-test-");
    ASSERT_FALSE(dir.path().empty());
    const ProcessResult r = runProcess("/bin/pwd", {}, dir.path().string());
    ASSERT_TRUE(r.ok()) << r.summary();
    const std::string cwd = r.out.substr(0, r.out.find('\n'));
    EXPECT_EQ(std::filesystem::canonical(cwd), std::filesystem::canonical(dir.path()));
}

TEST(Process, CapturesStderrSeparately) {
    const ProcessResult r = runProcess("/bin/ls", {"/nonexistent-rays-dir"});
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("nonexistent-rays-dir"), std::string::npos) << r.err;
}

TEST(Process, MissingProgramReportsStartError) {
    const ProcessResult r = runProcess("/nonexistent/rays-program", {});
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.startError.find("execv"), std::string::npos) << r.startError;
}

TEST(Process, MissingWorkingDirectoryReportsStartError) {
    const ProcessResult r = runProcess("/bin/pwd", {}, "/nonexistent/rays-dir");
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.startError.find("chdir"), std::string::npos) << r.startError;
}

TEST(Process, TimeoutKillsProgram) {
    const auto start = std::chrono::steady_clock::now();
    const ProcessResult r = runProcess("/bin/sleep", {"30"}, {}, std::chrono::milliseconds(300));
    const auto elapsed = std::chrono::steady_clock::now() - start;
    EXPECT_TRUE(r.timedOut);
    EXPECT_FALSE(r.ok());
    EXPECT_LT(elapsed, std::chrono::seconds(10));
}

TEST(Process, LargeOutputOnBothStreams) {
    // More than a pipe buffer on each stream must not deadlock.
    const ProcessResult r =
        runProcess("/bin/sh", {"-c", "head -c 300000 /dev/zero; head -c 200000 /dev/zero >&2"});
    ASSERT_TRUE(r.ok()) << r.summary();
    EXPECT_EQ(r.out.size(), 300000u);
    EXPECT_EQ(r.err.size(), 200000u);
}

TEST(Process, TempDirRemovedUnlessKept) {
    std::filesystem::path removed, kept;
    {
        TempDir a("rays-support-test-");
        removed = a.path();
        std::ofstream(a.path() / "f.txt") << "x";
        TempDir b("rays-support-test-");
        kept = b.path();
        b.keep();
    }
    EXPECT_FALSE(std::filesystem::exists(removed));
    EXPECT_TRUE(std::filesystem::exists(kept));
    std::filesystem::remove_all(kept);
}

}}  // namespace RAYS_TEST_UNIT, namespace
