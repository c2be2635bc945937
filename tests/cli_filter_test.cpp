// `rays filter` and `rays render --post` through the real binary.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "rays/image/image.h"
#include "rays/io/image_io.h"
#include "support/process.h"

namespace fs = std::filesystem;
using rays::test::runProcess;
using rays::test::TempDir;

namespace { namespace RAYS_TEST_UNIT {

const std::string kScene =
    "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n"
    "light_source { <10,10,10> color rgb <1,1,1> }\n"
    "sphere { <0,0,0>, 3 pigment { color rgb <1,0,0> } finish { ambient 0.2 diffuse 0.6 } }\n";

rays::test::ProcessResult run(const TempDir& dir, const std::vector<std::string>& args) {
    return runProcess(RAYS_BINARY, args, dir.path().string(), std::chrono::seconds(60));
}

TEST(CliFilter, FilterCommandWritesAndBadKernelsLeaveOutputAlone) {
    TempDir dir;
    std::ofstream(dir.path() / "s.pov") << kScene;
    ASSERT_TRUE(run(dir, {"render", "s.pov", "64", "48", "-o", "in.png", "-q"}).ok());
    auto r = run(dir, {"filter", "in.png", "out.png", "box_blur_5", "edge_detect_2"});
    ASSERT_TRUE(r.ok()) << r.err;
    EXPECT_EQ(rays::readImage((dir.path() / "out.png").string()).width, 64);
    std::ofstream(dir.path() / "keep.png") << "original bytes";
    for (const std::vector<std::string>& bad : {std::vector<std::string>{"box_blur_4"}, {"gaussian_blur_0"}, {"nope"}, {"median_x"}}) {
        std::vector<std::string> args = {"filter", "in.png", "keep.png"};
        args.insert(args.end(), bad.begin(), bad.end());
        r = run(dir, args);
        EXPECT_EQ(r.exitCode, 2) << bad[0] << r.err;
        std::ifstream in(dir.path() / "keep.png");
        std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_EQ(content, "original bytes") << bad[0];
    }
}

TEST(CliFilter, PostProcessingChangesTheRender) {
    TempDir dir;
    std::ofstream(dir.path() / "s.pov") << kScene;
    ASSERT_TRUE(run(dir, {"render", "s.pov", "64", "48", "-o", "a.png", "-q"}).ok());
    auto r = run(dir, {"render", "s.pov", "64", "48", "-o", "b.png", "-q", "--post", "box_blur_9"});
    ASSERT_TRUE(r.ok()) << r.err;
    const rays::Image8 a = rays::readImage((dir.path() / "a.png").string());
    const rays::Image8 b = rays::readImage((dir.path() / "b.png").string());
    EXPECT_NE(a.pixels, b.pixels);
    r = run(dir, {"render", "s.pov", "64", "48", "-o", "c.png", "--post", "box_blur_8"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_FALSE(fs::exists(dir.path() / "c.png"));
}

}}  // namespace RAYS_TEST_UNIT, namespace
