// End-to-end tests of the `rays` program: every test runs the real binary (RAYS_BINARY) with
// runProcess in a fresh TempDir holding the scene files it writes itself (nothing from ../shared).
// Covers scene errors (exit 2, one "FILE:LINE:COL: error: ..." line, no image, no temporary
// files), warnings for unsupported POV-Ray keywords, preservation of existing output on failure,
// output formats, the course commands and flags, the positional form, the modern options and
// image-size checks. Images are small (64x48) so the whole suite runs in a few seconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/files.h"
#include "support/image_compare.h"
#include "support/process.h"

namespace fs = std::filesystem;
using rays::test::loadPngRgb;
using rays::test::ProcessResult;
using rays::test::readFile;
using rays::test::RgbImage;
using rays::test::runProcess;
using rays::test::TempDir;
using rays::test::writeFile;

namespace { namespace RAYS_TEST_UNIT {

constexpr auto kTimeout = std::chrono::seconds(60);

// The camera of every scene here: course convention, 4:3, looking down -z from z = 14.
const std::string kCamera =
    "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n";
const std::string kLight = "light_source { <10,10,10> color rgb <1,1,1> }\n";

// A red sphere in the middle of the picture, lit: renders quickly and has edges to jitter.
const std::string kRedSphereScene =
    kCamera + kLight +
    "sphere { <0,0,0>, 2\n"
    "  pigment { color rgb <1,0,0> }\n"
    "  finish { ambient 0.2 diffuse 0.6 specular 0.3 roughness 0.1 }\n"
    "}\n";

// Reflection and refraction (and a floor), for the determinism tests.
const std::string kGlassScene =
    kCamera + kLight +
    "plane { <0,1,0>, -3 pigment { color rgb <0.2,0.6,0.2> } finish { ambient 0.2 diffuse 0.8 reflection 0.3 } }\n"
    "sphere { <-2,0,0>, 2 pigment { color rgb <0.9,0.9,0.9> }\n"
    "  finish { ambient 0.1 diffuse 0.3 specular 0.5 roughness 0.05 reflection 0.7 } }\n"
    "sphere { <2.5,0,2>, 1.5 pigment { color rgbf <1,1,1,0.9> }\n"
    "  finish { ambient 0.1 diffuse 0.2 ior 1.5 refraction 1.0 } }\n";

// ---- small helpers -----------------------------------------------------------------------------

/// Sorted names of the entries of dir.
std::vector<std::string> listDir(const fs::path& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string joinNames(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return "[" + s + "]";
}

/// Runs `rays args...` with dir as the working directory.
ProcessResult runRays(const fs::path& dir, const std::vector<std::string>& args) {
    return runProcess(RAYS_BINARY, args, dir.string(), kTimeout);
}

/// The command line and how it ended, for failure messages.
std::string describeRun(const std::vector<std::string>& args, const ProcessResult& r) {
    std::string cmd = "rays";
    for (const auto& a : args) cmd += " " + a;
    return cmd + "\n  -> " + r.summary() + "\n  stdout: " + r.out + "\n  stderr: " + r.err;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::vector<std::string> splitLines(const std::string& s) {
    std::vector<std::string> lines;
    std::istringstream in(s);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

/// The RGB of pixel (x, y), y counted from the top row of the file.
struct Rgb {
    int r, g, b;
};
Rgb pixelAt(const RgbImage& img, int x, int y) {
    const size_t i = (size_t(y) * size_t(img.width) + size_t(x)) * 3;
    return {img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]};
}

/// A scene text with one '@' marking where the fault is: the text without the marker and the
/// 1-based line and column of the character that followed it.
struct PlacedFault {
    std::string text;
    int line = 0, col = 0;
};
PlacedFault placeFault(const std::string& marked) {
    PlacedFault p;
    const size_t at = marked.find('@');
    if (at == std::string::npos || marked.find('@', at + 1) != std::string::npos) return p;  // line 0: bad case
    p.text = marked.substr(0, at) + marked.substr(at + 1);
    size_t lineStart = 0;
    p.line = 1;
    for (size_t i = 0; i < at; ++i)
        if (marked[i] == '\n') {
            ++p.line;
            lineStart = i + 1;
        }
    p.col = int(at - lineStart) + 1;
    return p;
}

/// Checks the common contract of a user error: exit status 2, nothing on stdout, stderr exactly one
/// line starting with `prefix` and containing every key word.
void expectOneLineError(const ProcessResult& r, const std::string& prefix, const std::vector<std::string>& keys,
                        const std::string& context) {
    SCOPED_TRACE(context);
    EXPECT_EQ(r.exitCode, 2) << r.summary();
    EXPECT_TRUE(r.out.empty()) << "stdout should be empty";
    EXPECT_TRUE(startsWith(r.err, prefix)) << "stderr should start with \"" << prefix << "\"";
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "stderr should be exactly one line";
    EXPECT_TRUE(!r.err.empty() && r.err.back() == '\n') << "stderr should end with a newline";
    const std::string first = r.err.substr(0, r.err.find('\n'));
    for (const auto& k : keys) EXPECT_TRUE(contains(first, k)) << "message should contain \"" << k << "\"";
}

// ---- 1. bad scene input --------------------------------------------------------------------------

struct BadScene {
    std::string name;
    std::string marked;             ///< scene text with '@' at the fault
    std::vector<std::string> keys;  ///< stable words of the message
};

void PrintTo(const BadScene& c, std::ostream* os) { *os << c.name; }

std::vector<BadScene> badScenes() {
    return {
        {"UnknownKeyword", kCamera + kLight + "@spher { <0,0,0>, 1 }\n", {"unknown keyword", "'spher'"}},
        {"UnknownKeywordInBlock",
         kCamera + "sphere { <0,0,0>, 1\n  @pigmnt { color rgb <1,0,0> }\n}\n",
         {"unknown keyword", "'pigmnt'"}},
        {"UnclosedObjectBlock",
         kCamera + kLight + "\nsphere @{ <0,0,0>, 1\n  pigment { color rgb <1,0,0> }\n  finish { ambient 0.2 }\n",
         {"never closed", "sphere"}},
        {"UnclosedCameraBlock",
         kLight + "sphere { <0,0,0>, 1 }\ncamera   @{ location <0,0,14> up <0,1,0>\n  right <1.33333,0,0> look_at <0,0,0>\n",
         {"never closed", "camera"}},
        {"StrayClosingBrace", kCamera + "sphere { <0,0,0>, 1 }\n  @}\n", {"'}'", "unbalanced"}},
        {"MalformedNumberTwoDots", kCamera + "sphere {\n  <0,0,0>, @1.2.3\n}\n", {"malformed number", "1.2.3"}},
        {"MalformedNumberExponent", kCamera + "sphere { <0,0,0>, @3e }\n", {"malformed number", "3e"}},
        {"VectorTooShort", kCamera + "\n\nsphere { @<1, 2>, 1 }\n", {"vector", "sphere centre", "2 components"}},
        {"VectorMissingCommas", kCamera + "sphere { <1 @2 3>, 1 }\n", {"expected ','", "vector"}},
        {"SphereWithoutRadius", kCamera + "sphere { <0,0,0> @}\n", {"expected sphere radius"}},
        {"NegativeRadius", kCamera + "sphere { <0,0,0>, @-1 }\n", {"radius", "greater than 0"}},
        {"ZeroRadius", kCamera + "sphere {\n    <0,0,0>,\n    @0\n}\n", {"radius", "greater than 0"}},
        {"ZeroPlaneNormal", kCamera + "plane { @<0,0,0>, 1 pigment { color rgb <1,1,1> } }\n", {"plane normal", "zero"}},
        {"CameraUpParallelToView",
         kLight + "\n  @camera { location <0,0,14> up <0,0,1> right <1.33333,0,0> look_at <0,0,0> }\n",
         {"camera", "up", "parallel"}},
        {"UnterminatedComment",
         kCamera + "sphere { <0,0,0>, 1 } @/* this comment never ends\nsphere { <1,0,0>, 1 }\n",
         {"unterminated", "comment"}},
    };
}

class CliBadScene : public ::testing::TestWithParam<BadScene> {};

TEST_P(CliBadScene, ReportsLineAndColumnAndWritesNothing) {
    const BadScene& c = GetParam();
    const PlacedFault fault = placeFault(c.marked);
    ASSERT_GT(fault.line, 0) << "test case needs exactly one '@' marker";
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "bad.pov", fault.text);

    const std::vector<std::string> args = {"render", "bad.pov", "64", "48"};
    const ProcessResult r = runRays(tmp.path(), args);
    const std::string prefix = "bad.pov:" + std::to_string(fault.line) + ":" + std::to_string(fault.col) + ": error: ";
    expectOneLineError(r, prefix, c.keys, describeRun(args, r));
    EXPECT_EQ(listDir(tmp.path()), std::vector<std::string>{"bad.pov"})
        << "no output.png and no temporary files may be left: " << joinNames(listDir(tmp.path()));
}

INSTANTIATE_TEST_SUITE_P(Cli, CliBadScene, ::testing::ValuesIn(badScenes()),
                         [](const ::testing::TestParamInfo<BadScene>& info) { return info.param.name; });

TEST(CliBadSceneFile, ErrorNamesThePathAsGiven) {
    // The location prefix uses the path exactly as written on the command line, here with a directory.
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    fs::create_directory(tmp.path() / "scenes");
    const PlacedFault fault = placeFault(kCamera + "sphere { <0,0,0>, @1.2.3 }\n");
    writeFile(tmp.path() / "scenes" / "bad.pov", fault.text);

    const std::string rel = "scenes/bad.pov";
    std::vector<std::string> args = {"render", rel, "64", "48"};
    ProcessResult r = runRays(tmp.path(), args);
    expectOneLineError(r, rel + ":" + std::to_string(fault.line) + ":" + std::to_string(fault.col) + ": error: ",
                       {"malformed number"}, describeRun(args, r));

    const std::string abs = (tmp.path() / "scenes" / "bad.pov").string();
    args = {"render", abs, "64", "48"};
    r = runRays(tmp.path(), args);
    expectOneLineError(r, abs + ":" + std::to_string(fault.line) + ":" + std::to_string(fault.col) + ": error: ",
                       {"malformed number"}, describeRun(args, r));
    EXPECT_EQ(listDir(tmp.path()), std::vector<std::string>{"scenes"}) << joinNames(listDir(tmp.path()));
    EXPECT_EQ(listDir(tmp.path() / "scenes"), std::vector<std::string>{"bad.pov"});
}

TEST(CliBadSceneFile, MissingSceneFileFails) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    const std::vector<std::string> args = {"render", "no-such-scene.pov", "64", "48"};
    const ProcessResult r = runRays(tmp.path(), args);
    expectOneLineError(r, "no-such-scene.pov: error: ", {"cannot open"}, describeRun(args, r));
    EXPECT_TRUE(listDir(tmp.path()).empty()) << joinNames(listDir(tmp.path()));
}

TEST(CliBadSceneFile, SceneWithoutCameraFails) {
    // No line to point at: the message names the file only.
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "bad.pov", kLight + "sphere { <0,0,0>, 1 pigment { color rgb <1,0,0> } }\n");
    const std::vector<std::string> args = {"render", "bad.pov", "64", "48"};
    const ProcessResult r = runRays(tmp.path(), args);
    expectOneLineError(r, "bad.pov: error: ", {"no camera"}, describeRun(args, r));
    EXPECT_EQ(listDir(tmp.path()), std::vector<std::string>{"bad.pov"}) << joinNames(listDir(tmp.path()));
}

// ---- 2. valid but unsupported POV-Ray keywords ------------------------------------------------------

void expectWarningAndImage(const std::string& marked, const std::string& keyword) {
    const PlacedFault at = placeFault(marked);
    ASSERT_GT(at.line, 0);
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "w.pov", at.text);
    const std::vector<std::string> args = {"render", "w.pov", "64", "48"};
    const ProcessResult r = runRays(tmp.path(), args);
    SCOPED_TRACE(describeRun(args, r));
    EXPECT_TRUE(r.ok()) << r.summary();
    const std::string prefix = "w.pov:" + std::to_string(at.line) + ":" + std::to_string(at.col) + ": warning: ";
    bool found = false;
    for (const auto& line : splitLines(r.err))
        if (startsWith(line, prefix) && contains(line, "'" + keyword + "'")) found = true;
    EXPECT_TRUE(found) << "stderr should have a line starting \"" << prefix << "\" naming '" << keyword << "'";
    EXPECT_FALSE(contains(r.err, "error:"));
    const RgbImage img = loadPngRgb((tmp.path() / "output.png").string());
    ASSERT_TRUE(img.ok()) << img.error;
    EXPECT_EQ(img.width, 64);
    EXPECT_EQ(img.height, 48);
}

TEST(CliUnsupportedKeyword, PhongInFinishWarnsAndRenders) {
    expectWarningAndImage(kCamera + kLight +
                              "sphere { <0,0,0>, 2 pigment { color rgb <1,0,0> }\n"
                              "  finish { ambient 0.2 diffuse 0.6 @phong 0.5 } }\n",
                          "phong");
}

TEST(CliUnsupportedKeyword, TorusObjectWarnsAndRenders) {
    expectWarningAndImage(kCamera + kLight + "sphere { <0,0,0>, 2 pigment { color rgb <1,0,0> } }\n@torus { 1, 0.25 }\n",
                          "torus");
}

// ---- 3. existing output is preserved on failure ------------------------------------------------------

const std::string kKnownBytes = std::string("not an image \x89PNG\r\n\x1a\n", 21) + std::string("\0\xff\x01 keep me", 11);

TEST(CliOutputPreserved, FailingRenderLeavesExistingOutputUnchanged) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "output.png", kKnownBytes);
    writeFile(tmp.path() / "bad.pov", kCamera + "spher { <0,0,0>, 1 }\n");
    writeFile(tmp.path() / "good.pov", kRedSphereScene);
    const std::vector<std::string> before = listDir(tmp.path());

    const std::vector<std::vector<std::string>> failing = {
        {"render", "bad.pov", "64", "48", "-o", "output.png"},           // parse error
        {"render", "missing.pov", "64", "48", "-o", "output.png"},       // no scene file
        {"render", "good.pov", "64", "48", "-o", "output.png", "--camera", "3"},  // fails after parsing
        {"render", "good.pov", "100000", "100000", "-o", "output.png"},  // bad size
        {"64", "48", "bad.pov", "output.png", "0", "1", "3"},           // positional form
        {"64", "48", "good.pov", "output.png", "0", "1", "3", "missing.obj"},
    };
    for (const auto& args : failing) {
        const ProcessResult r = runRays(tmp.path(), args);
        SCOPED_TRACE(describeRun(args, r));
        EXPECT_EQ(r.exitCode, 2) << r.summary();
        EXPECT_EQ(readFile(tmp.path() / "output.png"), kKnownBytes) << "output.png was changed";
        EXPECT_EQ(listDir(tmp.path()), before) << joinNames(listDir(tmp.path()));
    }
}

TEST(CliOutputPreserved, OutputOntoTheSceneFileIsRefused) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    // A scene file whose name has an image extension, so only the same-file check can refuse it.
    writeFile(tmp.path() / "scene.png", kRedSphereScene);
    const std::vector<std::string> before = listDir(tmp.path());

    const std::vector<std::vector<std::string>> refused = {
        {"render", "scene.pov", "64", "48", "-o", "scene.pov"},
        {"render", "scene.png", "64", "48", "-o", "scene.png"},
        {"render", "scene.png", "64", "48", "-o", "./scene.png"},
        {"render", "scene.png", "64", "48", "-o", (tmp.path() / "scene.png").string()},
        {"raycast", "scene.png", "64", "48", "-o", "scene.png"},
        {"64", "48", "scene.png", "scene.png", "0", "1", "3"},
    };
    for (const auto& args : refused) {
        const ProcessResult r = runRays(tmp.path(), args);
        SCOPED_TRACE(describeRun(args, r));
        EXPECT_TRUE(r.startError.empty() && !r.timedOut && r.termSignal == 0 && r.exitCode != 0) << r.summary();
        EXPECT_TRUE(contains(r.err, "error:"));
        EXPECT_EQ(readFile(tmp.path() / "scene.pov"), kRedSphereScene) << "scene.pov was changed";
        EXPECT_EQ(readFile(tmp.path() / "scene.png"), kRedSphereScene) << "scene.png was changed";
        EXPECT_EQ(listDir(tmp.path()), before) << joinNames(listDir(tmp.path()));
    }
}

// ---- 4. output formats ---------------------------------------------------------------------------

TEST(CliOutputFormat, EachExtensionWritesItsFormat) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    for (const std::string ext : {"png", "jpg", "ppm", "tga", "bmp"}) {
        const std::string name = "out." + ext;
        const std::vector<std::string> args = {"render", "scene.pov", "64", "48", "-q", "-o", name};
        const ProcessResult r = runRays(tmp.path(), args);
        SCOPED_TRACE(describeRun(args, r));
        ASSERT_TRUE(r.ok()) << r.summary();
        const std::string bytes = readFile(tmp.path() / name);
        ASSERT_GE(bytes.size(), 18u) << name << " is empty or truncated";
        const auto u = [&](size_t i) { return unsigned(uint8_t(bytes[i])); };
        if (ext == "png") {
            EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
        } else if (ext == "jpg") {
            EXPECT_EQ(u(0), 0xFFu);
            EXPECT_EQ(u(1), 0xD8u);
            EXPECT_EQ(u(2), 0xFFu);
        } else if (ext == "ppm") {
            EXPECT_EQ(bytes.substr(0, 2), "P6");
            EXPECT_TRUE(bytes[2] == '\n' || bytes[2] == ' ' || bytes[2] == '\t' || bytes[2] == '\r');
        } else if (ext == "tga") {
            // No magic number: colour-map type 0, true-colour image type (2, or 10 RLE), 64x48 little endian.
            EXPECT_EQ(u(1), 0u);
            EXPECT_TRUE(u(2) == 2 || u(2) == 10) << "image type " << u(2);
            EXPECT_EQ(u(12) | (u(13) << 8), 64u);
            EXPECT_EQ(u(14) | (u(15) << 8), 48u);
        } else {
            EXPECT_EQ(bytes.substr(0, 2), "BM");
        }
        const RgbImage img = loadPngRgb((tmp.path() / name).string());
        ASSERT_TRUE(img.ok()) << img.error;
        EXPECT_EQ(img.width, 64);
        EXPECT_EQ(img.height, 48);
    }
    EXPECT_EQ(listDir(tmp.path()),
              (std::vector<std::string>{"out.bmp", "out.jpg", "out.png", "out.ppm", "out.tga", "scene.pov"}))
        << joinNames(listDir(tmp.path()));
}

// A PNG is compressed by the render's threads while rows finish (PngStream); the pixels must be
// those of the finished image, as another format writes it afterwards.
TEST(CliOutputFormat, PngCompressedDuringTheRenderHasTheFinishedPixels) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kGlassScene);
    for (const std::string name : {"out.png", "out.ppm"}) {
        const std::vector<std::string> args = {"render", "scene.pov", "200", "150", "--threads", "3", "-q", "-o", name};
        const ProcessResult r = runRays(tmp.path(), args);
        ASSERT_TRUE(r.ok()) << describeRun(args, r);
    }
    const RgbImage png = loadPngRgb((tmp.path() / "out.png").string());
    const RgbImage ppm = loadPngRgb((tmp.path() / "out.ppm").string());
    ASSERT_TRUE(png.ok()) << png.error;
    ASSERT_TRUE(ppm.ok()) << ppm.error;
    EXPECT_EQ(png.width, 200);
    EXPECT_EQ(png.height, 150);
    EXPECT_TRUE(png.pixels == ppm.pixels) << "the PNG's pixels differ from the PPM's";
}

TEST(CliOutputFormat, UnknownExtensionFails) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    const std::vector<std::string> args = {"render", "scene.pov", "64", "48", "-o", "out.xyz"};
    const ProcessResult r = runRays(tmp.path(), args);
    expectOneLineError(r, "out.xyz: error: ", {"unsupported", "format"}, describeRun(args, r));
    EXPECT_EQ(listDir(tmp.path()), std::vector<std::string>{"scene.pov"}) << joinNames(listDir(tmp.path()));
}

// ---- 5. course form --------------------------------------------------------------------------------

TEST(CliCourseForm, RenderWritesOutputPng) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    const std::vector<std::string> args = {"render", "scene.pov", "64", "48"};
    const ProcessResult r = runRays(tmp.path(), args);
    ASSERT_TRUE(r.ok()) << describeRun(args, r);
    const RgbImage img = loadPngRgb((tmp.path() / "output.png").string());
    ASSERT_TRUE(img.ok()) << img.error;
    EXPECT_EQ(img.width, 64);
    EXPECT_EQ(img.height, 48);
    EXPECT_EQ(listDir(tmp.path()), (std::vector<std::string>{"output.png", "scene.pov"}));
}

TEST(CliCourseForm, RaycastWritesFlatColours) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    const std::vector<std::string> args = {"raycast", "scene.pov", "64", "48"};
    const ProcessResult r = runRays(tmp.path(), args);
    ASSERT_TRUE(r.ok()) << describeRun(args, r);
    const RgbImage img = loadPngRgb((tmp.path() / "output.png").string());
    ASSERT_TRUE(img.ok()) << img.error;
    ASSERT_EQ(img.width, 64);
    ASSERT_EQ(img.height, 48);
    const Rgb centre = pixelAt(img, 32, 24);
    EXPECT_EQ(centre.r, 255);
    EXPECT_EQ(centre.g, 0);
    EXPECT_EQ(centre.b, 0);
    for (const auto& [x, y] : std::vector<std::pair<int, int>>{{0, 0}, {63, 0}, {0, 47}, {63, 47}}) {
        const Rgb c = pixelAt(img, x, y);
        EXPECT_TRUE(c.r == 0 && c.g == 0 && c.b == 0) << "corner (" << x << ", " << y << ") is " << c.r << " " << c.g
                                                      << " " << c.b;
    }
    // Flat shading: every pixel is exactly the pigment or the black background.
    int red = 0, black = 0, other = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const Rgb c = pixelAt(img, x, y);
            if (c.r == 255 && c.g == 0 && c.b == 0) ++red;
            else if (c.r == 0 && c.g == 0 && c.b == 0) ++black;
            else ++other;
        }
    EXPECT_GT(red, 0);
    EXPECT_GT(black, 0);
    EXPECT_EQ(other, 0) << "pixels neither pigment red nor black";
}

TEST(CliCourseForm, AcceptsOneDashCourseFlags) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kGlassScene);
    const std::vector<std::string> args = {"render", "scene.pov", "64",    "48",   "-altbrdf",
                                           "-fresnel",  "-beers",    "-ss=2", "-sds"};
    const ProcessResult r = runRays(tmp.path(), args);
    ASSERT_TRUE(r.ok()) << describeRun(args, r);
    EXPECT_FALSE(contains(r.err, "error")) << r.err;
    const RgbImage img = loadPngRgb((tmp.path() / "output.png").string());
    ASSERT_TRUE(img.ok()) << img.error;
    EXPECT_EQ(img.width, 64);
    EXPECT_EQ(img.height, 48);
}

// ---- 6. debug commands -------------------------------------------------------------------------------

const std::string kTinyScene = kCamera + "sphere { <0,0,0>, 2 }\n";

TEST(CliDebugCommands, PixelRayPrintsCourseText) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "s.pov", kTinyScene);
    const std::vector<std::string> args = {"pixelray", "s.pov", "640", "480", "320", "240"};
    const ProcessResult r = runRays(tmp.path(), args);
    ASSERT_TRUE(r.ok()) << describeRun(args, r);
    EXPECT_EQ(r.out, "Pixel: [320, 240] Ray: {0.0000 0.0000 14.0000} -> {0.0010 0.0010 -1.0000}\n");
    EXPECT_EQ(listDir(tmp.path()), std::vector<std::string>{"s.pov"});
}

TEST(CliDebugCommands, FirstHitPrintsDistanceAndType) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "s.pov", kTinyScene);
    const std::vector<std::string> args = {"firsthit", "s.pov", "640", "480", "320", "240"};
    const ProcessResult r = runRays(tmp.path(), args);
    ASSERT_TRUE(r.ok()) << describeRun(args, r);
    const std::vector<std::string> lines = splitLines(r.out);
    EXPECT_NE(std::find(lines.begin(), lines.end(), "T = 12.0001"), lines.end()) << r.out;
    EXPECT_NE(std::find(lines.begin(), lines.end(), "Object Type: Sphere"), lines.end()) << r.out;
    EXPECT_EQ(listDir(tmp.path()), std::vector<std::string>{"s.pov"});
}

// A POV-Ray scene whose camera's aspect comes from image_width / image_height.
const std::string kAspectScene =
    "#version 3.7;\n"
    "camera { location <0,0,-10> look_at <0,0,0> right x*image_width/image_height }\n"
    "sphere { 0, 1 pigment { rgb 1 } }\n";

TEST(CliDebugCommands, PixelRaySeesTheImageSizeAsRenderDoes) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "s.pov", kAspectScene);
    // 200x100: right = 2, so the left column's centre ray has x/z = (0.5/200 − 0.5)·2 = −0.995
    // (with the default 640x480 the camera would be 4:3 and x/z −0.663).
    const std::vector<std::string> args = {"pixelray", "s.pov", "200", "100", "0", "50"};
    const ProcessResult r = runRays(tmp.path(), args);
    ASSERT_TRUE(r.ok()) << describeRun(args, r);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(-> \{(\S+) (\S+) (\S+)\})"))) << r.out;
    EXPECT_NEAR(std::stod(m[1]) / std::stod(m[3]), -0.995, 0.002) << r.out;
}

// Lit by its ambient term alone: the traced colour is 0.2, the image's sRGB(0.2) = 124 of 255.
const std::string kAmbientPovScene =
    "#version 3.7;\n"
    "global_settings { assumed_gamma 1 }\n"
    "camera { location <0,0,-10> look_at <0,0,0> }\n"
    "sphere { 0, 3 pigment { rgb 0.2 } finish { ambient 1 diffuse 0 } }\n";

TEST(CliDebugCommands, PixelColorOfAPovSceneIsTheImagesColour) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "s.pov", kAmbientPovScene);
    const std::vector<std::string> args = {"pixelcolor", "s.pov", "8", "6", "4", "3"};
    const ProcessResult r = runRays(tmp.path(), args);
    ASSERT_TRUE(r.ok()) << describeRun(args, r);
    const std::vector<std::string> lines = splitLines(r.out);
    EXPECT_NE(std::find(lines.begin(), lines.end(), "BRDF: POV-Ray 3.7"), lines.end()) << r.out;
    EXPECT_NE(std::find(lines.begin(), lines.end(), "Color: (124, 124, 124)"), lines.end()) << r.out;

    // The same pixel of the rendered image (row 3 from the bottom is file row 2).
    const std::vector<std::string> render = {"render", "s.pov", "8", "6", "-o", "out.png", "-q"};
    const ProcessResult rr = runRays(tmp.path(), render);
    ASSERT_TRUE(rr.ok()) << describeRun(render, rr);
    const RgbImage img = loadPngRgb((tmp.path() / "out.png").string());
    ASSERT_EQ(img.width, 8);
    const Rgb p = pixelAt(img, 4, 2);
    const std::string imageColor = "Color: (" + std::to_string(p.r) + ", " + std::to_string(p.g) + ", " + std::to_string(p.b) + ")";
    EXPECT_NE(std::find(lines.begin(), lines.end(), imageColor), lines.end()) << r.out << "image: " << imageColor;

    const std::vector<std::string> tree = {"printrays", "s.pov", "8", "6", "4", "3"};
    const ProcessResult pr = runRays(tmp.path(), tree);
    ASSERT_TRUE(pr.ok()) << describeRun(tree, pr);
    EXPECT_TRUE(startsWith(pr.out, "Pixel: [4, 3] Color: (124, 124, 124)\n")) << pr.out;
}

TEST(CliDebugCommands, PixelOutsideTheImageFails) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "s.pov", kTinyScene);
    const std::vector<std::vector<std::string>> outside = {
        {"pixelray", "s.pov", "640", "480", "640", "240"},
        {"firsthit", "s.pov", "640", "480", "640", "240"},
        {"pixelray", "s.pov", "640", "480", "320", "480"},
    };
    for (const auto& args : outside) {
        const ProcessResult r = runRays(tmp.path(), args);
        expectOneLineError(r, "rays: error: ", {"outside", "640x480"}, describeRun(args, r));
    }
    EXPECT_EQ(listDir(tmp.path()), std::vector<std::string>{"s.pov"});
}

// ---- 7. positional form ------------------------------------------------------------------------------

const std::string kTriangleObj =
    "# one triangle between the camera (z = 14) and the sphere\n"
    "v -3 -3 5\n"
    "v 3 -3 5\n"
    "v 0 3 5\n"
    "f 1 2 3\n";

TEST(CliPositional, WritesTheNamedImage) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    for (const std::string model : {"0", "1"}) {
        const std::string name = "out" + model + ".png";
        const std::vector<std::string> args = {"64", "48", "scene.pov", name, model, "1", "3"};
        const ProcessResult r = runRays(tmp.path(), args);
        ASSERT_TRUE(r.ok()) << describeRun(args, r);
        const RgbImage img = loadPngRgb((tmp.path() / name).string());
        ASSERT_TRUE(img.ok()) << img.error;
        EXPECT_EQ(img.width, 64);
        EXPECT_EQ(img.height, 48);
        const Rgb centre = pixelAt(img, 32, 24);
        EXPECT_GT(centre.r, 0) << "the red sphere should be visible with shading model " << model;
    }
    EXPECT_EQ(listDir(tmp.path()), (std::vector<std::string>{"out0.png", "out1.png", "scene.pov"}));
}

TEST(CliPositional, UnknownShadingModelFails) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    const std::vector<std::string> args = {"64", "48", "scene.pov", "out.png", "9", "1", "3"};
    const ProcessResult r = runRays(tmp.path(), args);
    expectOneLineError(r, "rays: error: ", {"SHADING_MODEL", "9"}, describeRun(args, r));
    EXPECT_EQ(listDir(tmp.path()), std::vector<std::string>{"scene.pov"});
}

TEST(CliPositional, ObjFileAddsItsTriangles) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    writeFile(tmp.path() / "tri.obj", kTriangleObj);
    const std::vector<std::string> plain = {"64", "48", "scene.pov", "plain.png", "0", "1", "3"};
    const std::vector<std::string> withObj = {"64", "48", "scene.pov", "obj.png", "0", "1", "3", "tri.obj"};
    ProcessResult r = runRays(tmp.path(), plain);
    ASSERT_TRUE(r.ok()) << describeRun(plain, r);
    r = runRays(tmp.path(), withObj);
    ASSERT_TRUE(r.ok()) << describeRun(withObj, r);
    const RgbImage a = loadPngRgb((tmp.path() / "plain.png").string());
    const RgbImage b = loadPngRgb((tmp.path() / "obj.png").string());
    ASSERT_TRUE(a.ok()) << a.error;
    ASSERT_TRUE(b.ok()) << b.error;
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    EXPECT_NE(a.pixels, b.pixels) << "the OBJ triangle should change the image";
    // The triangle covers the centre in front of the red sphere: the default OBJ material is grey.
    const Rgb c = pixelAt(b, 32, 24);
    EXPECT_TRUE(c.r == c.g && c.g == c.b) << "centre with the triangle: " << c.r << " " << c.g << " " << c.b;
}

TEST(CliPositional, MissingObjFileFails) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    const std::vector<std::string> args = {"64", "48", "scene.pov", "out.png", "0", "1", "3", "no-such-model.obj"};
    const ProcessResult r = runRays(tmp.path(), args);
    expectOneLineError(r, "no-such-model.obj: error: ", {"cannot open"}, describeRun(args, r));
    EXPECT_EQ(listDir(tmp.path()), std::vector<std::string>{"scene.pov"});
}

// ---- 8. modern options -------------------------------------------------------------------------------

TEST(CliOptions, WidthAndHeightFlagsSetTheSize) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    const std::vector<std::string> args = {"render", "scene.pov", "-W", "32", "-H", "24", "-o", "small.png"};
    const ProcessResult r = runRays(tmp.path(), args);
    ASSERT_TRUE(r.ok()) << describeRun(args, r);
    const RgbImage img = loadPngRgb((tmp.path() / "small.png").string());
    ASSERT_TRUE(img.ok()) << img.error;
    EXPECT_EQ(img.width, 32);
    EXPECT_EQ(img.height, 24);
}

TEST(CliOptions, NormalsShadingShowsTheNormal) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    // A big sphere, so the normal seen through the centre pixel (half a pixel off the axis) is
    // within a fraction of a level of (0, 0, 1).
    writeFile(tmp.path() / "scene.pov", kCamera + kLight + "sphere { <0,0,0>, 10 pigment { color rgb <1,0,0> } }\n");
    const std::vector<std::string> args = {"render", "scene.pov", "64", "48", "--shading", "normals"};
    const ProcessResult r = runRays(tmp.path(), args);
    ASSERT_TRUE(r.ok()) << describeRun(args, r);
    const RgbImage img = loadPngRgb((tmp.path() / "output.png").string());
    ASSERT_TRUE(img.ok()) << img.error;
    ASSERT_EQ(img.width, 64);
    ASSERT_EQ(img.height, 48);
    const Rgb c = pixelAt(img, 32, 24);  // normal ≈ (0, 0, 1) → (0.5, 0.5, 1)
    EXPECT_NEAR(c.r, 128, 2);
    EXPECT_NEAR(c.g, 128, 2);
    EXPECT_NEAR(c.b, 255, 2);
}

TEST(CliOptions, ThreadCountDoesNotChangeTheImage) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kGlassScene);
    for (const std::string threads : {"1", "3"}) {
        const std::vector<std::string> args = {"render", "scene.pov", "64", "48", "--spp", "4", "--seed", "7",
                                               "--threads", threads, "-q", "-o", "t" + threads + ".png"};
        const ProcessResult r = runRays(tmp.path(), args);
        ASSERT_TRUE(r.ok()) << describeRun(args, r);
    }
    const std::string a = readFile(tmp.path() / "t1.png");
    const std::string b = readFile(tmp.path() / "t3.png");
    ASSERT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << "--threads 1 and --threads 3 gave different files";
}

TEST(CliOptions, SeedDrivesTheJitter) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kGlassScene);
    const auto renderWithSeed = [&](const std::string& seed, const std::string& name) {
        const std::vector<std::string> args = {"render", "scene.pov", "64", "48", "--spp", "4",
                                               "--seed", seed, "-q", "-o", name};
        const ProcessResult r = runRays(tmp.path(), args);
        EXPECT_TRUE(r.ok()) << describeRun(args, r);
        return loadPngRgb((tmp.path() / name).string());
    };
    const RgbImage s1 = renderWithSeed("1", "s1.png");
    const RgbImage s1again = renderWithSeed("1", "s1b.png");
    const RgbImage s2 = renderWithSeed("2", "s2.png");
    ASSERT_TRUE(s1.ok() && s1again.ok() && s2.ok());
    EXPECT_EQ(s1.pixels, s1again.pixels) << "the same seed should give the same image";
    EXPECT_NE(s1.pixels, s2.pixels) << "different seeds should jitter the samples differently";
    EXPECT_EQ(readFile(tmp.path() / "s1.png"), readFile(tmp.path() / "s1b.png"));
}

TEST(CliOptions, QuietPrintsNothing) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    for (const std::string flag : {"--quiet", "-q"}) {
        const std::vector<std::string> args = {"render", "scene.pov", "64", "48", flag};
        const ProcessResult r = runRays(tmp.path(), args);
        ASSERT_TRUE(r.ok()) << describeRun(args, r);
        EXPECT_EQ(r.err, "") << flag;
        EXPECT_TRUE(fs::exists(tmp.path() / "output.png"));
    }
}

TEST(CliOptions, SummaryLineWithoutQuiet) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    const std::vector<std::string> args = {"render", "scene.pov", "64", "48"};
    const ProcessResult r = runRays(tmp.path(), args);
    ASSERT_TRUE(r.ok()) << describeRun(args, r);
    bool found = false;
    for (const auto& line : splitLines(r.err))
        if (contains(line, "parse") && contains(line, "build") && contains(line, "render") && contains(line, "Mrays/s"))
            found = true;
    EXPECT_TRUE(found) << "no summary line in stderr:\n" << r.err;
    EXPECT_FALSE(contains(r.err, "stats:")) << "stats lines only with --stats";
}

TEST(CliOptions, StatsAddsStatsLines) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    const std::vector<std::string> args = {"render", "scene.pov", "64", "48", "--stats"};
    const ProcessResult r = runRays(tmp.path(), args);
    ASSERT_TRUE(r.ok()) << describeRun(args, r);
    int stats = 0;
    for (const auto& line : splitLines(r.err))
        if (startsWith(line, "stats:")) ++stats;
    EXPECT_GE(stats, 1) << r.err;
}

TEST(CliOptions, HelpListsTheCommands) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    const ProcessResult r = runRays(tmp.path(), {"--help"});
    ASSERT_TRUE(r.ok()) << describeRun({"--help"}, r);
    EXPECT_TRUE(contains(r.out + r.err, "render")) << r.out;
    EXPECT_TRUE(contains(r.out + r.err, "raycast")) << r.out;
    EXPECT_TRUE(listDir(tmp.path()).empty());
}

TEST(CliOptions, VersionPrintsNameAndVersion) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    const ProcessResult r = runRays(tmp.path(), {"--version"});
    ASSERT_TRUE(r.ok()) << describeRun({"--version"}, r);
    EXPECT_TRUE(std::regex_search(r.out, std::regex("^rays [0-9]+\\.[0-9]+"))) << r.out;
#ifdef RAYS_VERSION
    EXPECT_EQ(r.out, std::string("rays ") + RAYS_VERSION + "\n");
#endif
}

// ---- 9. bad sizes ------------------------------------------------------------------------------------

void expectSizeRefused(const std::vector<std::string>& args, const std::vector<std::string>& keys) {
    TempDir tmp("rays-cli-");
    ASSERT_FALSE(tmp.path().empty());
    writeFile(tmp.path() / "scene.pov", kRedSphereScene);
    const ProcessResult r = runRays(tmp.path(), args);
    expectOneLineError(r, "rays: error: ", keys, describeRun(args, r));
    EXPECT_EQ(listDir(tmp.path()), std::vector<std::string>{"scene.pov"}) << joinNames(listDir(tmp.path()));
}

TEST(CliBadSize, ZeroWidthFails) {
    expectSizeRefused({"render", "scene.pov", "0", "48"}, {"image size", "0x48"});
    expectSizeRefused({"render", "scene.pov", "-W", "0", "-H", "48", "-o", "out.png"}, {"image size"});
    expectSizeRefused({"0", "48", "scene.pov", "out.png", "0", "1", "3"}, {"image size"});
}

TEST(CliBadSize, HugeSizeFails) {
    expectSizeRefused({"render", "scene.pov", "100000", "100000"}, {"too large", "100000x100000"});
    expectSizeRefused({"100000", "100000", "scene.pov", "out.png", "0", "1", "3"}, {"too large"});
}

TEST(CliBadSize, ZeroHeightFails) {
    // Zero height must be refused like zero width, not replaced by the default 480.
    expectSizeRefused({"render", "scene.pov", "64", "0"}, {"image size"});
    expectSizeRefused({"render", "scene.pov", "-W", "64", "-H", "0", "-o", "out.png"}, {"image size"});
}

TEST(CliBadSize, RaycastZeroSizeFails) {
    // raycast takes the size as required arguments: 0 is an error, not "use the default".
    expectSizeRefused({"raycast", "scene.pov", "0", "48"}, {"image size"});
    expectSizeRefused({"raycast", "scene.pov", "64", "0"}, {"image size"});
}

}}  // namespace RAYS_TEST_UNIT, namespace
