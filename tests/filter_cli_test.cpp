// `rays filter` command, tested in-process through rays::cli::runFilterCommand with argument
// vectors and files in a TempDir: outputs in each format, alpha, border and thread options, and
// every kind of bad input (one-line rays::Error, the existing output file byte-identical, no
// temporary files left behind).
//
// rays_tests links rays_core only (the app's sources are not a library), so the command's source
// is compiled into this test directly.
#include "../apps/rays/filter_command.cpp"
#include "../apps/rays/subcommand_args.cpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "rays/error.h"
#include "rays/image/filter.h"
#include "rays/io/image_io.h"
#include "support/files.h"
#include "support/process.h"

namespace fs = std::filesystem;
using rays::Error;
using rays::Image8;
using rays::cli::runFilterCommand;

using rays::test::readFile;
using rays::test::writeFile;

namespace { namespace RAYS_TEST_UNIT {

std::vector<std::string> listDir(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

Image8 gradient(int w, int h, int channels) {
    Image8 img(w, h, channels);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < channels; ++c)
                img.row(y)[x * channels + c] = uint8_t(c == 3 ? (x * 7 + y * 3) % 256 : (x * 16 + y * 5 + c * 40) % 256);
    return img;
}

class FilterCli : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_FALSE(dir.path().empty());
        in = (dir.path() / "in.png").string();
        out = (dir.path() / "out.png").string();
        rays::writeImage(in, gradient(21, 13, 3));
    }
    std::string path(const std::string& name) const { return (dir.path() / name).string(); }

    // Runs the command expecting failure: returns the message; checks `out` was not touched and
    // that no temporary file was left.
    std::string failure(const std::vector<std::string>& args) {
        writeFile(out, "previous output");
        const auto before = listDir(dir.path());
        std::string msg = "(no error)";
        try {
            const int status = runFilterCommand(args);
            ADD_FAILURE() << "exit status " << status << " instead of an error";
        } catch (const Error& e) {
            msg = e.what();
        }
        EXPECT_EQ(readFile(out), "previous output") << msg;
        EXPECT_EQ(listDir(dir.path()), before) << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
        return msg;
    }

    rays::test::TempDir dir{"rays-filter-cli-"};
    std::string in, out;
};

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

TEST_F(FilterCli, WritesTheFilteredImage) {
    ASSERT_EQ(runFilterCommand({in, out, "brighten_2", "-q"}), 0);
    const Image8 src = rays::readImage(in), got = rays::readImage(out);
    ASSERT_EQ(got.width, 21);
    ASSERT_EQ(got.height, 13);
    ASSERT_EQ(got.channels, 3);
    for (size_t i = 0; i < got.pixels.size(); ++i) ASSERT_EQ(got.pixels[i], std::min(255, 2 * src.pixels[i])) << i;

    // Several kernels, in order, with options anywhere: the same as the library call.
    ASSERT_EQ(runFilterCommand({"-q", in, out, "gaussian_blur_5", "--border", "reflect", "edge_detect_2", "--threads", "2"}), 0);
    const Image8 want = rays::applyFilters(src, rays::parseKernelList({"gaussian_blur_5", "edge_detect_2"}),
                                           rays::BorderMode::Reflect, 1);
    EXPECT_EQ(rays::readImage(out).pixels, want.pixels);
}

TEST_F(FilterCli, BorderModeMatters) {
    ASSERT_EQ(runFilterCommand({in, out, "box_blur_5", "--border", "white", "-q"}), 0);
    const Image8 white = rays::readImage(out);
    ASSERT_EQ(runFilterCommand({in, out, "box_blur_5", "-q"}), 0);
    const Image8 clamp = rays::readImage(out);
    EXPECT_GT(white.pixels[0], clamp.pixels[0]);        // the corner sees white around it
    EXPECT_EQ(white.row(6)[30], clamp.row(6)[30]);      // the middle does not
}

TEST_F(FilterCli, FormatsAlphaAndCustomKernels) {
    const std::string rgba = path("rgba.png");
    rays::writeImage(rgba, gradient(19, 11, 4));
    for (const char* name : {"o.png", "o.bmp", "o.tga"}) {
        ASSERT_EQ(runFilterCommand({rgba, path(name), "sobel", "-q"}), 0) << name;
        const Image8 got = rays::readImage(path(name)), src = rays::readImage(rgba);
        ASSERT_EQ(got.channels, 4) << name;
        for (size_t p = 0; p < size_t(19 * 11); ++p) ASSERT_EQ(got.pixels[p * 4 + 3], src.pixels[p * 4 + 3]) << name;
    }
    // JPEG output (no alpha) with --quality; JPEG input.
    ASSERT_EQ(runFilterCommand({rgba, path("o.jpg"), "sharpen", "--quality", "75", "-q"}), 0);
    EXPECT_EQ(rays::readImage(path("o.jpg")).channels, 3);
    ASSERT_EQ(runFilterCommand({path("o.jpg"), path("o2.png"), "median_3", "-q"}), 0);
    // A custom kernel file.
    writeFile(path("k.txt"), "# identity\n0 0 0\n0 1 0\n0 0 0\n");
    ASSERT_EQ(runFilterCommand({in, out, "kernel:" + path("k.txt"), "-q"}), 0);
    EXPECT_EQ(rays::readImage(out).pixels, rays::readImage(in).pixels);
}

TEST_F(FilterCli, HelpExitsZero) {
    testing::internal::CaptureStdout();
    EXPECT_EQ(runFilterCommand({"--help"}), 0);
    const std::string help = testing::internal::GetCapturedStdout();
    EXPECT_NE(help.find("--border"), std::string::npos);
    EXPECT_NE(help.find("gaussian_blur_N"), std::string::npos);
}

TEST_F(FilterCli, BadKernelSizesAndNames) {
    EXPECT_EQ(failure({in, out, "box_blur_4", "-q"}),
              "rays: error: kernel 'box_blur_4': the size must be odd and positive, got 4");
    EXPECT_EQ(failure({in, out, "gaussian_blur_0"}),
              "rays: error: kernel 'gaussian_blur_0': the size must be odd and positive, got 0");
    EXPECT_EQ(failure({in, out, "median_-3"}), "rays: error: kernel 'median_-3': the size must be odd and positive, got -3");
    EXPECT_EQ(failure({in, out, "box_blur_five"}),
              "rays: error: kernel 'box_blur_five': the size must be an odd positive integer, got 'five'");
    EXPECT_EQ(failure({in, out, "sharpen", "blurry"}),
              "rays: error: unknown kernel 'blurry' (valid: " + rays::validKernelNames() + ")");
    EXPECT_EQ(failure({in, out, "brighten_lots"}),
              "rays: error: kernel 'brighten_lots': the factor must be a non-negative number, got 'lots'");
}

TEST_F(FilterCli, BadCustomKernelFiles) {
    writeFile(path("ragged.txt"), "1 1 1\n1 1\n1 1 1\n");
    EXPECT_EQ(failure({in, out, "kernel:" + path("ragged.txt")}),
              path("ragged.txt") + ":2:1: error: ragged kernel: this row has 2 values but the first row (line 1) has 3");
    writeFile(path("even.txt"), "# 2x2\n1 1\n1 1\n");
    EXPECT_EQ(failure({in, out, "kernel:" + path("even.txt")}),
              path("even.txt") + ":2:1: error: kernel rows have 2 values; the width must be odd");
    writeFile(path("rows.txt"), "1 1 1\n1 1 1\n");
    EXPECT_EQ(failure({in, out, "kernel:" + path("rows.txt")}),
              path("rows.txt") + ":2:1: error: kernel has 2 rows; the number of rows must be odd");
    EXPECT_EQ(failure({in, out, "kernel:" + path("nope.txt")}),
              path("nope.txt") + ": error: cannot read kernel file: No such file or directory");
}

TEST_F(FilterCli, UnreadableOrUnsupportedImages) {
    const std::string missing = path("missing.png");
    EXPECT_TRUE(startsWith(failure({missing, out, "sobel"}), missing + ": error: cannot read image"));
    writeFile(path("text.png"), "this is not a PNG file");
    EXPECT_TRUE(startsWith(failure({path("text.png"), out, "sobel"}), path("text.png") + ": error: cannot read image"));
    writeFile(path("pic.gif"), "GIF89a....");
    EXPECT_TRUE(startsWith(failure({path("pic.gif"), out, "sobel"}), path("pic.gif") + ": error: cannot read image"));
}

TEST_F(FilterCli, OutputsThatCannotBeWritten) {
    // Unsupported extension: nothing created.
    EXPECT_EQ(failure({in, path("out.gif"), "sobel"}),
              path("out.gif") + ": error: unsupported output image format (use .png, .jpg, .jpeg, .bmp, .tga or .ppm)");
    EXPECT_FALSE(fs::exists(path("out.gif")));
    // Missing directory.
    const std::string nodir = (dir.path() / "no" / "such" / "out.png").string();
    EXPECT_TRUE(startsWith(failure({in, nodir, "sobel"}), nodir + ": error: cannot write the image: directory"));
    // A directory.
    fs::create_directory(path("sub.png"));
    EXPECT_EQ(failure({in, path("sub.png"), "sobel"}), path("sub.png") + ": error: cannot write the image: is a directory");
}

TEST_F(FilterCli, BadOptionsAndArguments) {
    EXPECT_EQ(failure({in, out, "sobel", "--border", "mirror"}),
              "rays: error: unknown border mode 'mirror' (use clamp, zero, white or reflect)");
    for (const std::vector<std::string>& args :
         std::vector<std::vector<std::string>>{{in, out, "sobel", "--quality", "0"},
                                               {in, out, "sobel", "--quality", "high"},
                                               {in, out, "sobel", "--threads", "-1"},
                                               {in, out, "sobel", "--frobnicate"},
                                               {in, out},
                                               {}}) {
        const std::string msg = failure(args);
        EXPECT_TRUE(startsWith(msg, "rays: error: filter: ")) << msg;
        EXPECT_NE(msg.find("usage: rays filter INPUT OUTPUT KERNEL"), std::string::npos) << msg;
    }
}

}}  // namespace RAYS_TEST_UNIT, namespace
