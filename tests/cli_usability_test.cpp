// The command line's rough edges a new user met (issue "The first hour"), each run through the real
// `rays` binary (RAYS_BINARY) in a fresh TempDir: `rays --help` names every command, a width without
// a height is an error, -gi_samples alone says it turns GI on, -ss with --spp is an error, `assets`
// tells a missing folder from a file, and sceneinfo shows object transforms and numbers objects as
// printrays does.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/files.h"
#include "support/process.h"

namespace fs = std::filesystem;
using rays::test::ProcessResult;
using rays::test::runProcess;
using rays::test::TempDir;
using rays::test::writeFile;

namespace { namespace RAYS_TEST_UNIT {

const std::string kScene =
    "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n"
    "light_source { <10,10,10> color rgb <1,1,1> }\n"
    "sphere { <0,0,0>, 2 pigment { color rgb <1,0,0> } finish { ambient 0.2 diffuse 0.6 } }\n";

// Runs rays in dir with a scene.pov written there.
ProcessResult rays(const TempDir& dir, const std::vector<std::string>& args, const std::string& scene = kScene) {
    writeFile(dir.path() / "scene.pov", scene);
    return runProcess(RAYS_BINARY, args, dir.path().string());
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(CliUsability, HelpListsEveryCommand) {
    TempDir dir;
    const ProcessResult r = rays(dir, {"--help"});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    for (const char* c : {"render", "raycast", "sceneinfo", "scenes", "assets", "filter", "compare", "printrays"})
        EXPECT_TRUE(contains(r.out, std::string("\n  ") + c + " ")) << c << " missing from:\n" << r.out;
}

TEST(CliUsability, WidthWithoutHeightIsAnError) {
    TempDir dir;
    const ProcessResult r = rays(dir, {"render", "scene.pov", "32", "-q"});
    EXPECT_EQ(r.exitCode, 2) << r.summary();
    EXPECT_EQ(r.err, "rays: error: width 32 without a height: give both (rays render SCENE WIDTH HEIGHT)\n");
    EXPECT_FALSE(fs::exists(dir.path() / "output.png"));
}

TEST(CliUsability, WidthWithHeightFromAnotherOptionRenders) {
    TempDir dir;
    for (const std::string h : {"-H", "+H"}) {
        const std::vector<std::string> args = h == "-H" ? std::vector<std::string>{"render", "scene.pov", "32", "-H", "24", "-q"}
                                                        : std::vector<std::string>{"render", "scene.pov", "32", "+H24", "-q"};
        const ProcessResult r = rays(dir, args);
        EXPECT_TRUE(r.ok()) << h << ": " << r.summary() << r.err;
    }
}

TEST(CliUsability, GiSamplesAloneSaysItTurnsGiOn) {
    TempDir dir;
    const ProcessResult alone = rays(dir, {"render", "scene.pov", "16", "12", "-q", "-gi_samples=2,1"});
    ASSERT_TRUE(alone.ok()) << alone.summary() << alone.err;
    EXPECT_EQ(alone.err, "rays: warning: -gi_samples turns global illumination on (as -gi)\n");
    const ProcessResult bounces = rays(dir, {"render", "scene.pov", "16", "12", "-q", "-gi_bounces=1"});
    ASSERT_TRUE(bounces.ok()) << bounces.summary() << bounces.err;
    EXPECT_EQ(bounces.err, "rays: warning: -gi_bounces turns global illumination on (as -gi)\n");
    const ProcessResult withGi = rays(dir, {"render", "scene.pov", "16", "12", "-q", "-gi", "-gi_samples=2,1"});
    ASSERT_TRUE(withGi.ok()) << withGi.summary() << withGi.err;
    EXPECT_EQ(withGi.err, "");
}

TEST(CliUsability, SsWithSppIsAnError) {
    TempDir dir;
    const ProcessResult r = rays(dir, {"render", "scene.pov", "16", "12", "-q", "-ss=2", "--spp", "9"});
    EXPECT_EQ(r.exitCode, 2) << r.summary();
    EXPECT_EQ(r.err, "rays: error: -ss=2 and --spp 9 both set the samples per pixel: give one of them\n");
    EXPECT_FALSE(fs::exists(dir.path() / "output.png"));
}

TEST(CliUsability, AssetsTellsAMissingFolderFromAFile) {
    TempDir dir;
    const ProcessResult missing = rays(dir, {"assets", "missing/dir"});
    EXPECT_EQ(missing.exitCode, 2) << missing.summary();
    EXPECT_EQ(missing.err, "missing/dir: error: does not exist (create the folder first)\n");
    const ProcessResult file = rays(dir, {"assets", "scene.pov"});
    EXPECT_EQ(file.exitCode, 2) << file.summary();
    EXPECT_EQ(file.err, "scene.pov: error: is not a folder\n");
}

TEST(CliUsability, SceneinfoShowsObjectTransforms) {
    TempDir dir;
    const std::string scene =
        "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n"
        "light_source { <10,10,10> color rgb <1,1,1> }\n"
        "sphere { <0,0,0>, 1 scale <2,1,1> translate <0,1,0> pigment { color rgb <1,0,0> } }\n"
        "cone { <0,0,0>, 1, <0,2,0>, 0.5 translate <3,0,0> pigment { color rgb <0,1,0> } }\n"
        "sphere { <0,0,0>, 1 translate <0,0,0> pigment { color rgb <0,0,1> } }\n";
    const ProcessResult r = rays(dir, {"sceneinfo", "scene.pov"}, scene);
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    const std::string ellipsoid =
        "- Radius: 1.0000\n"
        "- Transform (object to world):\n"
        "  - X axis: {2.0000 0.0000 0.0000}\n"
        "  - Y axis: {0.0000 1.0000 0.0000}\n"
        "  - Z axis: {0.0000 0.0000 1.0000}\n"
        "  - Translation: {0.0000 1.0000 0.0000}\n";
    EXPECT_TRUE(contains(r.out, ellipsoid)) << r.out;
    const std::string cone =
        "- Cap Radius: 0.5000\n"
        "- Transform (object to world):\n"
        "  - X axis: {1.0000 0.0000 0.0000}\n"
        "  - Y axis: {0.0000 1.0000 0.0000}\n"
        "  - Z axis: {0.0000 0.0000 1.0000}\n"
        "  - Translation: {3.0000 0.0000 0.0000}\n";
    EXPECT_TRUE(contains(r.out, cone)) << r.out;
    // An identity transform (translate <0,0,0>) prints none, as the course's sceneinfo.
    const size_t third = r.out.find("Object[3]:");
    ASSERT_NE(third, std::string::npos) << r.out;
    EXPECT_FALSE(contains(r.out.substr(third), "Transform")) << r.out;
}

TEST(CliUsability, SceneinfoNumbersObjectsAsPrintraysDoes) {
    TempDir dir;
    const std::string scene =
        "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n"
        "light_source { <10,10,10> color rgb <1,1,1> }\n"
        "plane { <0,0,1>, -20 pigment { color rgb <1,1,1> } }\n"
        "sphere { <0,0,0>, 2 pigment { color rgb <1,0,0> } }\n";
    const ProcessResult info = rays(dir, {"sceneinfo", "scene.pov"}, scene);
    ASSERT_TRUE(info.ok()) << info.summary() << info.err;
    EXPECT_FALSE(contains(info.out, "Object[0]")) << info.out;
    EXPECT_TRUE(contains(info.out, "Object[2]:\n- Type: Sphere")) << info.out;
    const ProcessResult rays2 = rays(dir, {"printrays", "scene.pov", "64", "48", "32", "24"}, scene);
    ASSERT_TRUE(rays2.ok()) << rays2.summary() << rays2.err;
    EXPECT_TRUE(contains(rays2.out, "(ID #2 - Sphere)")) << rays2.out;
}

}}  // namespace RAYS_TEST_UNIT, namespace
