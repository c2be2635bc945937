// `rays compare` through the real binary: the output layout, exit codes (0, 1 with --fail-ssim,
// 2 for errors), the diff image, and the refusals (different sizes, unreadable files, a diff
// path naming an input, bad options).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "rays/image/image.h"
#include "rays/io/image_io.h"
#include "support/process.h"

namespace fs = std::filesystem;
using rays::Image8;
using rays::test::ProcessResult;
using rays::test::runProcess;
using rays::test::TempDir;

namespace { namespace RAYS_TEST_UNIT {

class CompareCli : public ::testing::Test {
protected:
    TempDir dir;

    ProcessResult run(const std::vector<std::string>& args) {
        std::vector<std::string> all = {"compare"};
        all.insert(all.end(), args.begin(), args.end());
        return runProcess(RAYS_BINARY, all, dir.path().string(), std::chrono::seconds(60));
    }
    std::string path(const std::string& name) const { return (dir.path() / name).string(); }
    std::string bytes(const std::string& name) const {
        std::ifstream in(path(name), std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
};

// A 16×8 gradient; b adds `offset` to the left half's red channel.
Image8 gradient(int offset = 0) {
    Image8 img(16, 8, 3);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) {
            uint8_t* p = img.row(y) + 3 * x;
            p[0] = uint8_t(10 * x + (x < 8 ? offset : 0));
            p[1] = uint8_t(20 * y);
            p[2] = 128;
        }
    return img;
}

// "key rest-of-line" for every output line.
std::map<std::string, std::string> figures(const std::string& out) {
    std::map<std::string, std::string> m;
    std::istringstream in(out);
    std::string line;
    while (std::getline(in, line)) {
        const size_t space = line.find(' ');
        m[line.substr(0, space)] = space == std::string::npos ? "" : line.substr(space + 1);
    }
    return m;
}

int lineCount(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

TEST_F(CompareCli, IdenticalImagesPrintTheExactLayout) {
    rays::writeImage(path("a.png"), gradient());
    rays::writeImage(path("b.ppm"), gradient());
    const ProcessResult r = run({"a.png", "b.ppm"});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    EXPECT_EQ(r.out,
              "ssim 1.000000\n"
              "ssim_rgb 1.000000 1.000000 1.000000\n"
              "ssim_luma 1.000000\n"
              "psnr inf\n"
              "mean 0.000\n"
              "max 0\n"
              "over 0 0.00% threshold 5\n"
              "size 16x8\n");
    EXPECT_EQ(r.err, "");
}

TEST_F(CompareCli, DifferentImagesGiveTheirFigures) {
    rays::writeImage(path("a.png"), gradient());
    rays::writeImage(path("b.png"), gradient(8));  // 64 pixels differ by 8 in red
    ProcessResult r = run({"a.png", "b.png"});
    ASSERT_TRUE(r.ok()) << r.err;
    auto f = figures(r.out);
    EXPECT_EQ(f["max"], "8");
    EXPECT_EQ(f["mean"], "1.333");  // 64 · 8 / (128 · 3)
    EXPECT_EQ(f["psnr"], "37.85");  // 10·log10(255² / (64 · 64 / 384))
    EXPECT_EQ(f["over"], "64 50.00% threshold 5");
    EXPECT_LT(std::stod(f["ssim"]), 1.0);
    EXPECT_EQ(f["ssim_rgb"].substr(9), "1.000000 1.000000");  // green and blue are equal
    EXPECT_EQ(f["size"], "16x8");
    r = run({"a.png", "b.png", "--threshold", "8"});
    EXPECT_EQ(figures(r.out)["over"], "0 0.00% threshold 8");
    r = run({"a.png", "b.png", "--threshold", "7.5"});
    EXPECT_EQ(figures(r.out)["over"], "64 50.00% threshold 7.5");
}

TEST_F(CompareCli, FailSsimSetsTheExitStatus) {
    rays::writeImage(path("a.png"), gradient());
    rays::writeImage(path("b.png"), gradient(40));
    ProcessResult r = run({"a.png", "b.png", "--fail-ssim", "0.999"});
    EXPECT_EQ(r.exitCode, 1) << r.summary();
    EXPECT_EQ(lineCount(r.out), 8);  // the figures are still printed
    EXPECT_NE(r.err.find("below 0.999"), std::string::npos) << r.err;
    r = run({"a.png", "b.png", "--fail-ssim", "0.1"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    r = run({"a.png", "a.png", "--fail-ssim", "1"});  // equal to S is not below it
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST_F(CompareCli, WritesTheScaledDifferenceImage) {
    rays::writeImage(path("a.png"), gradient());
    rays::writeImage(path("b.png"), gradient(8));
    ProcessResult r = run({"a.png", "b.png", "--diff", "d.png", "--scale", "4"});
    ASSERT_TRUE(r.ok()) << r.err;
    const Image8 d = rays::readImage(path("d.png"));
    ASSERT_EQ(d.width, 16);
    ASSERT_EQ(d.height, 8);
    ASSERT_EQ(d.channels, 3);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) {
            const uint8_t* p = d.row(y) + 3 * x;
            EXPECT_EQ(int(p[0]), x < 8 ? 32 : 0) << x << "," << y;
            EXPECT_EQ(int(p[1]), 0);
            EXPECT_EQ(int(p[2]), 0);
        }
    r = run({"a.png", "b.png", "--diff", "d.png", "--scale", "100"});  // clamped
    ASSERT_TRUE(r.ok()) << r.err;
    EXPECT_EQ(int(rays::readImage(path("d.png")).row(0)[0]), 255);
    for (const auto& e : fs::directory_iterator(dir.path()))  // no temporary file left behind
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST_F(CompareCli, DifferentSizesAreRefusedNamingBothFiles) {
    rays::writeImage(path("a.png"), gradient());
    rays::writeImage(path("small.png"), Image8(8, 8, 3));
    const ProcessResult r = run({"a.png", "small.png", "--diff", "d.png"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "rays: error: compare: images differ in size: a.png is 16x8, small.png is 8x8\n");
    EXPECT_FALSE(fs::exists(path("d.png")));
}

TEST_F(CompareCli, UnreadableFilesAreNamed) {
    rays::writeImage(path("a.png"), gradient());
    std::ofstream(path("junk.png")) << "not an image";
    ProcessResult r = run({"a.png", "missing.png"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lineCount(r.err), 1);
    EXPECT_EQ(r.err.rfind("missing.png: error: cannot read image", 0), 0u) << r.err;
    r = run({"junk.png", "a.png"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err.rfind("junk.png: error:", 0), 0u) << r.err;
}

TEST_F(CompareCli, DiffPathNamingAnInputIsRefused) {
    rays::writeImage(path("a.png"), gradient());
    rays::writeImage(path("b.png"), gradient(8));
    const std::string before = bytes("b.png");
    for (const std::string& diff : std::vector<std::string>{"b.png", "./b.png", path("b.png"), "a.png"}) {
        const ProcessResult r = run({"a.png", "b.png", "--diff", diff});
        EXPECT_EQ(r.exitCode, 2) << diff;
        const std::string input = diff == "a.png" ? "a.png" : "b.png";
        EXPECT_EQ(r.err, diff + ": error: output would overwrite the input file '" + input + "'\n");
        EXPECT_EQ(r.out, "");
    }
    EXPECT_EQ(bytes("b.png"), before);
    fs::create_symlink(path("b.png"), path("link.png"));
    EXPECT_EQ(run({"a.png", "b.png", "--diff", "link.png"}).exitCode, 2);
    EXPECT_EQ(bytes("b.png"), before);
}

TEST_F(CompareCli, BadOptionsAndHelp) {
    rays::writeImage(path("a.png"), gradient());
    for (const std::vector<std::string>& bad :
         {std::vector<std::string>{"a.png"}, {"a.png", "a.png", "--threshold", "300"}, {"a.png", "a.png", "--scale", "-1"},
          {"a.png", "a.png", "--fail-ssim", "2"}, {"a.png", "a.png", "--bogus"}, {"a.png", "a.png", "--diff", "d.gif"}}) {
        const ProcessResult r = run(bad);
        EXPECT_EQ(r.exitCode, 2) << bad.back();
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
    }
    EXPECT_FALSE(fs::exists(path("d.gif")));
    const ProcessResult help = run({"--help"});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("--fail-ssim"), std::string::npos);
    const ProcessResult unknown = runProcess(RAYS_BINARY, {"bogus"}, dir.path().string(), std::chrono::seconds(60));
    EXPECT_NE(unknown.err.find("filter, compare"), std::string::npos) << unknown.err;
}

}}  // namespace RAYS_TEST_UNIT, namespace
