// End-to-end tests of POV-Ray's command-line forms (docs/cli.md "POV-Ray switches and INI files"
// and "Animation"): the real binary (RAYS_BINARY) in a fresh TempDir holding a course scene it
// writes itself. Covers `rays +Iscene.pov ...`, INI files (sections, subfolders, errors with file
// and line, warnings), switches mixed with `rays render`'s own options in command-line order,
// POV-Ray's default output name, file types, and animations: numbered frames, subsets, --resume
// and +C. Images are tiny so the suite runs in about a second.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
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
using rays::test::runProcess;
using rays::test::TempDir;
using rays::test::writeFile;

namespace { namespace RAYS_TEST_UNIT {

constexpr auto kTimeout = std::chrono::seconds(60);

// A lit red sphere in the course dialect (the dialect that renders today).
const std::string kBall =
    "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n"
    "light_source { <10,10,10> color rgb <1,1,1> }\n"
    "sphere { <0,0,0>, 2 pigment { color rgb <1,0,0> } finish { ambient 0.2 diffuse 0.6 } }\n";

/// Sorted names of the entries of dir.
std::vector<std::string> listDir(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

/// A TempDir holding ball.pov.
struct SceneDir {
    TempDir tmp{"rays-pov-"};
    SceneDir() { writeFile(tmp.path() / "ball.pov", kBall); }
    fs::path operator/(const std::string& name) const { return tmp.path() / name; }
    ProcessResult run(const std::vector<std::string>& args) const {
        return runProcess(RAYS_BINARY, args, tmp.path().string(), kTimeout);
    }
    std::vector<std::string> files() const { return listDir(tmp.path()); }
};

std::string describe(const std::vector<std::string>& args, const ProcessResult& r) {
    std::string cmd = "rays";
    for (const auto& a : args) cmd += " " + a;
    return cmd + "\n  -> " + r.summary() + "\n  stderr: " + r.err;
}

/// Runs args in dir and expects success.
#define RUN_OK(dir, ...)                                         \
    [&] {                                                        \
        const std::vector<std::string> args_ = {__VA_ARGS__};    \
        const ProcessResult r_ = (dir).run(args_);               \
        EXPECT_TRUE(r_.ok()) << describe(args_, r_);             \
        return r_;                                               \
    }()

/// Width and height of an image file ({0, 0} when it cannot be read).
std::pair<int, int> sizeOf(const fs::path& p) {
    const auto img = loadPngRgb(p.string());
    return {img.width, img.height};
}
using Size = std::pair<int, int>;

// ---- POV-Ray's form ----------------------------------------------------------------------------

TEST(CliPovForm, SwitchesRenderTheNamedImage) {
    SceneDir d;
    RUN_OK(d, "+Iball.pov", "+W64", "+H48", "+Oout.png", "-D", "+V", "+Q9");
    EXPECT_EQ(sizeOf(d / "out.png"), Size(64, 48));
    EXPECT_EQ(d.files(), (std::vector<std::string>{"ball.pov", "out.png"}));
}

TEST(CliPovForm, OutputToFileOffRendersAndWritesNoImage) {
    SceneDir d;
    writeFile(d / "ball.png", "the user's own file");
    const ProcessResult r = RUN_OK(d, "+Iball.pov", "+W16", "+H12", "-F");
    EXPECT_EQ(readFile(d / "ball.png"), "the user's own file");  // not overwritten
    EXPECT_TRUE(contains(r.err, "rays: rendered, no image written (Output_to_File=off) (16x12)")) << r.err;
    writeFile(d / "quiet.ini", "Input_File_Name=ball.pov\nWidth=8\nHeight=6\nOutput_to_File=off\nFinal_Frame=2\n");
    const ProcessResult a = RUN_OK(d, "quiet.ini");
    EXPECT_EQ(d.files(), (std::vector<std::string>{"ball.png", "ball.pov", "quiet.ini"}));
    EXPECT_TRUE(contains(a.err, "rays: frame 2 of 2 (frame_number 2, clock 1): rendered in ")) << a.err;
    // Render's -o names a file: written, whatever came before it.
    RUN_OK(d, "render", "ball.pov", "8", "6", "-F", "-o", "named.png");
    EXPECT_EQ(sizeOf(d / "named.png"), Size(8, 6));
}

TEST(CliPovForm, SixteenBitsPerColourWriteA16BitPng) {
    SceneDir d;
    RUN_OK(d, "+Iball.pov", "+W16", "+H12", "+FN16", "+Oout16.png");
    RUN_OK(d, "+Iball.pov", "+W16", "+H12", "+Oout8.png");
    const std::string png = readFile(d / "out16.png");
    ASSERT_GT(png.size(), 26u);
    EXPECT_EQ(int(uint8_t(png[24])), 16);  // IHDR bit depth
    EXPECT_EQ(int(uint8_t(png[25])), 2);   // RGB
    EXPECT_EQ(sizeOf(d / "out16.png"), Size(16, 12));
    // Other formats keep 8 bits, and say so.
    const ProcessResult r = RUN_OK(d, "+Iball.pov", "+W16", "+H12", "+FJ16", "+Oout.jpg");
    EXPECT_TRUE(contains(r.err, "16 bits per colour are written for PNG images only")) << r.err;
}

TEST(CliPovForm, AnIncludeHeaderDeclaresWhatTheSceneUses) {
    SceneDir d;
    writeFile(d / "uses.pov", "#version 3.7;\ncamera { location -5*z look_at 0 }\nsphere { 0, 1 pigment { Paint } finish { ambient 1 } }\n");
    writeFile(d / "paint.inc", "#declare Paint = rgb <1, 0, 0>;\n");
    RUN_OK(d, "+Iuses.pov", "+W8", "+H6", "+HIpaint.inc", "+Oa.png");
    const auto img = loadPngRgb((d / "a.png").string());
    ASSERT_TRUE(img.ok());
    const size_t centre = (size_t(3) * 8 + 4) * 3;
    EXPECT_EQ(img.pixels[centre], 255);
    EXPECT_EQ(img.pixels[centre + 1], 0);
    const ProcessResult r = d.run({"+Iuses.pov", "+W8", "+H6", "+Ob.png"});  // without it: undeclared
    EXPECT_EQ(r.exitCode, 2) << r.summary();
    EXPECT_TRUE(contains(r.err, "undeclared identifier 'Paint'")) << r.err;
}

TEST(CliPovForm, TheDefaultOutputIsTheSceneNameInTheCurrentFolder) {
    SceneDir d;
    writeFile(d / "sub/globe.pov", kBall);
    RUN_OK(d, "+Isub/globe.pov", "+W32", "+H24");
    EXPECT_EQ(sizeOf(d / "globe.png"), Size(32, 24));
    EXPECT_FALSE(fs::exists(d / "sub/globe.png"));
    RUN_OK(d, "ball.pov", "+W16", "+H12", "+FJ");  // a .pov argument is the scene; +FJ: JPEG
    EXPECT_EQ(readFile(d / "ball.jpg").substr(0, 2), "\xFF\xD8");
}

TEST(CliPovForm, ASceneAloneRendersAtTheDefaultSize) {
    SceneDir d;
    RUN_OK(d, "ball.pov");
    EXPECT_EQ(sizeOf(d / "ball.png"), Size(640, 480));
}

TEST(CliPovForm, AnIniFileNamesSceneSizeAndOutput) {
    SceneDir d;
    writeFile(d / "ball.ini",
              "; render settings\n"
              "Input_File_Name=ball.pov\n"
              "Width=40 ; pixels\n"
              "Height=30\n"
              "Antialias=on\n"
              "Output_File_Name=fromini.png\n");
    RUN_OK(d, "ball.ini");
    EXPECT_EQ(sizeOf(d / "fromini.png"), Size(40, 30));
    RUN_OK(d, "ball", "+W20", "+H10");  // ".ini is assumed"; the switches after it win
    EXPECT_EQ(sizeOf(d / "fromini.png"), Size(20, 10));
}

TEST(CliPovForm, AnIniFileInAFolderFindsTheSceneNextToIt) {
    SceneDir d;
    writeFile(d / "job/globe.pov", kBall);
    writeFile(d / "job/globe.ini", "Input_File_Name=globe.pov\n+W24 +H18\n");
    RUN_OK(d, "job/globe.ini");
    EXPECT_EQ(sizeOf(d / "globe.png"), Size(24, 18));
}

TEST(CliPovForm, ASectionOfAnIniFile) {
    SceneDir d;
    writeFile(d / "res.ini", "+W100 +H100\n[Small]\n+W20 +H15\n[Tiny]\n+W8 +H6\n");
    RUN_OK(d, "+Iball.pov", "res.ini[small]", "+Oa.png");
    EXPECT_EQ(sizeOf(d / "a.png"), Size(20, 15));
}

TEST(CliPovForm, AnIniErrorNamesTheFileAndLineAndWritesNothing) {
    SceneDir d;
    writeFile(d / "bad.ini", "Input_File_Name=ball.pov\nWidth=abc\n");
    const ProcessResult r = d.run({"bad.ini"});
    EXPECT_EQ(r.exitCode, 2) << r.summary();
    EXPECT_EQ(r.err, "rays: error: bad.ini:2: Width must be a positive integer, got 'abc'\n");
    EXPECT_EQ(d.files(), (std::vector<std::string>{"bad.ini", "ball.pov"}));
}

TEST(CliPovForm, UnknownOptionsWarnOnceWithTheirPlaceAndTheImageIsWritten) {
    SceneDir d;
    writeFile(d / "w.ini", "Input_File_Name=ball.pov\nFancy_Option=3\n+W16 +H12 +Zz\nfancy_option=4\n");
    const ProcessResult r = RUN_OK(d, "w.ini", "Other=1", "-q");
    EXPECT_TRUE(contains(r.err, "w.ini:2: warning: unknown option 'Fancy_Option'\n")) << r.err;
    EXPECT_TRUE(contains(r.err, "w.ini:3: warning: unknown option '+Zz'\n")) << r.err;
    EXPECT_TRUE(contains(r.err, "rays: warning: Other=1: unknown option 'Other'\n")) << r.err;
    EXPECT_FALSE(contains(r.err, "fancy_option")) << r.err;
    EXPECT_EQ(sizeOf(d / "ball.png"), Size(16, 12));
}

TEST(CliPovForm, PartOfTheImageIsRenderedAndTheRestIsBlack) {
    SceneDir d;
    RUN_OK(d, "+Iball.pov", "+W16", "+H12", "+Owhole.png");
    RUN_OK(d, "+Iball.pov", "+W16", "+H12", "+SR0.5", "+SC3", "+EC10", "+Opart.png");
    const auto whole = loadPngRgb((d / "whole.png").string()), part = loadPngRgb((d / "part.png").string());
    ASSERT_EQ(part.width, 16);
    ASSERT_EQ(part.height, 12);
    int lit = 0;
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 16; ++x)
            for (int k = 0; k < 3; ++k) {
                const size_t i = (size_t(y) * 16 + size_t(x)) * 3 + size_t(k);
                const bool inside = y >= 6 && x >= 2 && x <= 9;  // rows 7-12, columns 3-10
                EXPECT_EQ(part.pixels[i], inside ? whole.pixels[i] : 0) << x << " " << y;
                lit += inside && part.pixels[i] > 0;
            }
    EXPECT_GT(lit, 0);
    RUN_OK(d, "+Iball.pov", "+W16", "+H12", "+SR1", "+ER12", "+SC0", "+EC16", "+Oall.png");  // the whole image
    EXPECT_EQ(loadPngRgb((d / "all.png").string()).pixels, whole.pixels);
}

TEST(CliPovForm, NoSceneIsAnError) {
    SceneDir d;
    const ProcessResult r = d.run({"+W16", "+H12"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "rays: error: no scene: give +Iscene.pov, a .pov file or Input_File_Name in an INI file\n");
}

// ---- switches in `rays render` ------------------------------------------------------------------

TEST(CliPovRender, SwitchesMixWithRendersOptions) {
    SceneDir d;
    RUN_OK(d, "render", "ball.pov", "64", "48", "-o", "out.png", "+L/tmp", "+A0.3", "-q", "-D", "Work_Threads=2");
    EXPECT_EQ(sizeOf(d / "out.png"), Size(64, 48));
    RUN_OK(d, "render", "ball.pov", "+W16", "+H12");  // render keeps output.png
    EXPECT_EQ(sizeOf(d / "output.png"), Size(16, 12));
}

TEST(CliPovRender, TheLaterOfTwoSettingsWins) {
    SceneDir d;
    RUN_OK(d, "render", "ball.pov", "64", "48", "+W32", "-o", "a.png");
    EXPECT_EQ(sizeOf(d / "a.png"), Size(32, 48));
    RUN_OK(d, "render", "ball.pov", "+W32", "-W", "16", "+H8", "-o", "b.png");
    EXPECT_EQ(sizeOf(d / "b.png"), Size(16, 8));
    RUN_OK(d, "render", "ball.pov", "16", "12", "-o", "c.png", "+Od.png");
    EXPECT_TRUE(fs::exists(d / "d.png"));
    EXPECT_FALSE(fs::exists(d / "c.png"));
    RUN_OK(d, "render", "ball.pov", "16", "12", "+Oe.png", "-o", "f.png");
    EXPECT_TRUE(fs::exists(d / "f.png"));
    EXPECT_FALSE(fs::exists(d / "e.png"));
}

TEST(CliPovRender, AnIniFileAfterTheScene) {
    SceneDir d;
    writeFile(d / "small.ini", "Width=24\nHeight=12\n");
    RUN_OK(d, "render", "ball.pov", "small.ini", "-o", "s.png");
    EXPECT_EQ(sizeOf(d / "s.png"), Size(24, 12));
    RUN_OK(d, "render", "+Iball.pov", "20", "10", "-o", "n.png");  // W H when the scene came from +I
    EXPECT_EQ(sizeOf(d / "n.png"), Size(20, 10));
}

TEST(CliPovRender, LanguageOptionsAreAccepted) {
    SceneDir d;
    RUN_OK(d, "render", "ball.pov", "16", "12", "--dialect", "povray", "--strict", "--library", "/tmp", "--library=inc",
           "Declare=Rad=1", "-q");
    const ProcessResult r = d.run({"render", "ball.pov", "--dialect", "klingon"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(contains(r.err, "--dialect")) << r.err;
}

TEST(CliPovRender, HelpListsThePovRaySwitches) {
    SceneDir d;
    const ProcessResult r = RUN_OK(d, "render", "--help");
    for (const char* s : {"+Iscene.pov", "+KFF30", "+A[0.3]", "file.ini[Section]", "--resume", "--library", "--dialect"})
        EXPECT_TRUE(contains(r.out, s)) << s << "\n" << r.out;
}

// ---- animation ----------------------------------------------------------------------------------

TEST(CliPovAnimation, ThreeFramesWriteThreeNumberedFiles) {
    SceneDir d;
    const ProcessResult r = RUN_OK(d, "+Iball.pov", "+W16", "+H12", "+KFF3", "+Oout.png");
    EXPECT_EQ(d.files(), (std::vector<std::string>{"ball.pov", "out1.png", "out2.png", "out3.png"}));
    EXPECT_TRUE(contains(r.err, "rays: frame 1 of 3 (frame_number 1, clock 0): wrote out1.png in ")) << r.err;
    EXPECT_TRUE(contains(r.err, "rays: frame 3 of 3 (frame_number 3, clock 1): wrote out3.png in ")) << r.err;
    EXPECT_EQ(sizeOf(d / "out2.png"), Size(16, 12));
}

TEST(CliPovAnimation, FrameNumbersArePaddedToTheFinalFramesDigits) {
    SceneDir d;
    RUN_OK(d, "+Iball.pov", "+W8", "+H6", "+KFF10", "+SF2", "+EF3", "-GA");
    EXPECT_EQ(d.files(), (std::vector<std::string>{"ball.pov", "ball02.png", "ball03.png"}));
}

TEST(CliPovAnimation, AnIniFileDrivesTheAnimation) {
    SceneDir d;
    writeFile(d / "anim.ini",
              "Input_File_Name=ball.pov\nOutput_File_Name=f.png\nWidth=8\nHeight=6\n"
              "Initial_Frame=1\nFinal_Frame=4\nCyclic_Animation=on\nSubset_Start_Frame=0.5\n");
    RUN_OK(d, "anim.ini", "-q");
    EXPECT_EQ(d.files(), (std::vector<std::string>{"anim.ini", "ball.pov", "f2.png", "f3.png", "f4.png"}));
}

TEST(CliPovAnimation, WrittenFramesAreSkippedOnlyWhenResuming) {
    SceneDir d;
    writeFile(d / "out2.png", "not an image");
    RUN_OK(d, "+Iball.pov", "+W8", "+H6", "+KFF3", "+Oout.png", "--resume");
    EXPECT_EQ(readFile(d / "out2.png"), "not an image");
    EXPECT_TRUE(loadPngRgb((d / "out1.png").string()).ok());
    EXPECT_TRUE(loadPngRgb((d / "out3.png").string()).ok());

    fs::remove(d / "out3.png");
    const ProcessResult r = RUN_OK(d, "+Iball.pov", "+W8", "+H6", "+KFF3", "+Oout.png", "+C");  // POV-Ray's continue
    EXPECT_EQ(readFile(d / "out2.png"), "not an image");
    EXPECT_TRUE(contains(r.err, "out2.png exists; skipped (resume)")) << r.err;
    EXPECT_TRUE(loadPngRgb((d / "out3.png").string()).ok());

    RUN_OK(d, "+Iball.pov", "+W8", "+H6", "+KFF3", "+Oout.png");  // not resuming: rendered again
    EXPECT_TRUE(loadPngRgb((d / "out2.png").string()).ok());
}

TEST(CliPovAnimation, RenderFormAnimatesWithItsOutputName) {
    SceneDir d;
    RUN_OK(d, "render", "ball.pov", "8", "6", "-o", "anim.png", "+KFF2", "-q");
    EXPECT_EQ(d.files(), (std::vector<std::string>{"anim1.png", "anim2.png", "ball.pov"}));
}

TEST(CliPovAnimation, ASubsetSelectingNoFrameIsAnError) {
    SceneDir d;
    const ProcessResult r = d.run({"+Iball.pov", "+W8", "+H6", "+KFF3", "+SF5"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "rays: error: Subset_Start_Frame selects frame 5, after the final frame 3\n");
}

}}  // namespace RAYS_TEST_UNIT, namespace
