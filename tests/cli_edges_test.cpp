// End-to-end tests of the feature-line and sampling options of `rays render`.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "rays/image/image.h"
#include "rays/io/image_io.h"
#include "support/process.h"

namespace fs = std::filesystem;
using rays::test::runProcess;
using rays::test::TempDir;

namespace { namespace RAYS_TEST_UNIT {

constexpr auto kTimeout = std::chrono::seconds(60);

const std::string kScene =
    "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n"
    "light_source { <10,10,10> color rgb <1,1,1> }\n"
    "sphere { <0,0,0>, 3 pigment { color rgb <1,0,0> } finish { ambient 0.2 diffuse 0.6 } }\n";

fs::path writeScene(const TempDir& dir, const std::string& text, const char* name = "s.pov") {
    const fs::path p = dir.path() / name;
    std::ofstream(p) << text;
    return p;
}

rays::test::ProcessResult runRays(const TempDir& dir, std::vector<std::string> args) {
    return runProcess(RAYS_BINARY, args, dir.path().string(), kTimeout);
}

TEST(CliEdges, MaskIsGreyscaleWithTheOutline) {
    TempDir dir;
    writeScene(dir, kScene);
    const auto r = runRays(dir, {"render", "s.pov", "64", "48", "-o", "out.png", "--edges", "silhouette", "--edge-mask", "mask.png", "-q"});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    const rays::Image8 mask = rays::readImage((dir.path() / "mask.png").string());
    ASSERT_EQ(mask.channels, 1);
    ASSERT_EQ(mask.width, 64);
    // The sphere's outline passes the middle row; the centre and the corner are empty.
    int lit = 0;
    for (int x = 0; x < 64; ++x) lit += mask.row(24)[x] > 128;
    EXPECT_GE(lit, 2);
    EXPECT_EQ(mask.row(24)[32], 0);
    EXPECT_EQ(mask.row(0)[0], 0);
}

TEST(CliEdges, LinesOnlyIsBlackOnWhite) {
    TempDir dir;
    writeScene(dir, kScene);
    const auto r = runRays(dir, {"render", "s.pov", "64", "48", "-o", "out.png", "--lines-only", "-q"});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    const rays::Image8 img = rays::readImage((dir.path() / "out.png").string());
    EXPECT_EQ(img.row(0)[0], 255);        // background: white
    EXPECT_EQ(img.row(24)[32 * 3], 255);  // inside the sphere: white, not shaded red
    int dark = 0;
    for (int x = 0; x < 64; ++x) dark += img.row(24)[x * 3] < 100;
    EXPECT_GE(dark, 2);  // the outline
}

TEST(CliEdges, EdgeColourIsUsed) {
    TempDir dir;
    writeScene(dir, kScene);
    const auto r = runRays(dir, {"render", "s.pov", "64", "48", "-o", "out.png", "--lines-only", "--edge-color", "0,0,1", "-q"});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    const rays::Image8 img = rays::readImage((dir.path() / "out.png").string());
    bool blue = false;
    for (int x = 0; x < 64; ++x) {
        const uint8_t* p = img.row(24) + x * 3;
        blue |= p[2] == 255 && p[0] < 100 && p[1] < 100;
    }
    EXPECT_TRUE(blue);
}

TEST(CliEdges, BadValuesFailWithoutWritingAnything) {
    TempDir dir;
    writeScene(dir, kScene);
    const std::vector<std::vector<std::string>> cases = {
        {"--edges", "silhouete"},
        {"--edges", "all", "--edge-width", "9"},
        {"--edges", "all", "--edge-width", "0.1"},
        {"--edges", "all", "--edge-method", "pencil"},
        {"--edges", "all", "--edge-color", "1,2"},
        {"--edges", "all", "--crease-angle", "200"},
        {"--edge-mask", "mask.png"},
        {"--edges", "all", "--edge-mask", "mask.xyz"},
        {"--aa", "fancy"},
        {"--filter", "lanczos"},
        {"--aperture", "-1"},
        {"--spp", "0"},
        {"--area-samples", "0"},
        {"--aa-edges"},
    };
    for (const auto& extra : cases) {
        std::vector<std::string> args = {"render", "s.pov", "32", "24", "-o", "out.png"};
        args.insert(args.end(), extra.begin(), extra.end());
        const auto r = runRays(dir, args);
        std::string what;
        for (const auto& a : extra) what += a + " ";
        EXPECT_EQ(r.exitCode, 2) << what << r.err;
        EXPECT_FALSE(fs::exists(dir.path() / "out.png")) << what;
        EXPECT_FALSE(fs::exists(dir.path() / "mask.png")) << what;
        EXPECT_FALSE(fs::exists(dir.path() / "mask.xyz")) << what;
    }
}

TEST(CliEdges, SceneBlockErrorsNameTheLine) {
    TempDir dir;
    writeScene(dir, kScene + "edges { silhouette\n  edge_width 20 }\n");
    const auto r = runRays(dir, {"render", "s.pov", "32", "24"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err.rfind("s.pov:5:3: error: edge_width must be between 0.5 and 8", 0), 0u) << r.err;
}

TEST(CliEdges, SceneBlockDrawsLinesAndCliOverrides) {
    TempDir dir;
    writeScene(dir, kScene + "edges { silhouette lines_only }\n");
    auto r = runRays(dir, {"render", "s.pov", "64", "48", "-o", "a.png", "-q"});
    ASSERT_TRUE(r.ok()) << r.err;
    const rays::Image8 a = rays::readImage((dir.path() / "a.png").string());
    EXPECT_EQ(a.row(24)[32 * 3], 255);  // lines only from the scene block
    r = runRays(dir, {"render", "s.pov", "64", "48", "-o", "b.png", "--edges", "none", "-q"});
    ASSERT_TRUE(r.ok()) << r.err;
    const rays::Image8 b = rays::readImage((dir.path() / "b.png").string());
    EXPECT_EQ(b.row(0)[0], 255);  // still lines-only (white), but no outline drawn
    for (int x = 0; x < 64; ++x) EXPECT_EQ(b.row(24)[x * 3], 255);
}

TEST(CliScenes, ListsTheShippedScenesAndRendersOneByName) {
    TempDir dir;
    auto r = runRays(dir, {"scenes"});
    ASSERT_TRUE(r.ok()) << r.err;
    EXPECT_NE(r.out.find("soft-shadows"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("depth-of-field"), std::string::npos) << r.out;
    r = runRays(dir, {"render", "--scene", "depth-of-field", "--camera", "2", "32", "24", "-o", "d.png", "-q"});
    ASSERT_TRUE(r.ok()) << r.err;
    EXPECT_TRUE(fs::exists(dir.path() / "d.png"));
    r = runRays(dir, {"render", "--scene", "no-such-scene", "32", "24"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("soft-shadows"), std::string::npos) << r.err;  // the message lists the scenes
}

}}  // namespace RAYS_TEST_UNIT, namespace
