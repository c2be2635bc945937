// The shipped scenes (scenes/NN-name.pov) are self-contained: each renders with the assets the
// project ships (scenes/models, scenes/textures), without warnings, even with --strict; none reads
// a file outside scenes/; a scene whose model is missing is an error, not a different picture; and
// `cmake --install` gives a rays that renders a shipped scene from any folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "support/files.h"
#include "support/process.h"

namespace fs = std::filesystem;
using rays::test::ProcessResult;
using rays::test::readFile;
using rays::test::runProcess;
using rays::test::TempDir;

namespace { namespace RAYS_TEST_UNIT {

const fs::path kScenes = fs::path(RAYS_SOURCE_DIR) / "scenes";

std::vector<fs::path> shippedScenes() {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(kScenes))
        if (e.path().extension() == ".pov") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(ShippedScenes, EveryOneRendersWithoutWarnings) {
    const std::vector<fs::path> scenes = shippedScenes();
    ASSERT_GE(scenes.size(), 12u);
    TempDir dir;
    for (const fs::path& scene : scenes) {
        const fs::path out = dir.path() / (scene.stem().string() + ".png");
        const ProcessResult r = runProcess(RAYS_BINARY, {"render", scene.string(), "40", "30", "--strict", "-q", "-o", out.string()},
                                           dir.path().string());
        EXPECT_TRUE(r.ok()) << scene << ": " << r.summary() << "\n" << r.err;
        EXPECT_EQ(r.err, "") << scene;
        EXPECT_TRUE(fs::exists(out)) << scene;
    }
}

TEST(ShippedScenes, NoneReadsAFileOutsideTheProject) {
    for (const fs::path& scene : shippedScenes()) {
        const std::string text = readFile(scene);
        EXPECT_FALSE(contains(text, "../")) << scene << " names a file outside scenes/";
        EXPECT_FALSE(contains(text, "shared/")) << scene << " names ../shared";
    }
}

TEST(ShippedScenes, BunnySceneHasTheBunny) {
    const ProcessResult r = runProcess(RAYS_BINARY, {"sceneinfo", (kScenes / "08-bunny-lines.pov").string()});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    EXPECT_TRUE(contains(r.out, "- Type: Mesh\n- Triangles: 69451\n")) << r.out;
}

TEST(ShippedScenes, TexturedMeshSceneHasSpot) {
    const ProcessResult r = runProcess(RAYS_BINARY, {"sceneinfo", (kScenes / "12-textured-mesh.pov").string()});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    EXPECT_TRUE(contains(r.out, "- Type: Mesh\n- Triangles: 5856\n")) << r.out;
}

TEST(ShippedScenes, MissingModelIsAnError) {
    TempDir dir;  // the bunny scene without its models/ folder
    fs::copy_file(kScenes / "08-bunny-lines.pov", dir.path() / "08-bunny-lines.pov");
    const ProcessResult r = runProcess(RAYS_BINARY, {"render", "08-bunny-lines.pov", "40", "30", "-q", "-o", "out.png"},
                                       dir.path().string());
    EXPECT_EQ(r.exitCode, 2) << r.summary();
    EXPECT_TRUE(contains(r.err, "error: cannot open OBJ file")) << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out.png"));
}

TEST(ShippedScenes, InstalledRaysRendersAShippedSceneFromAnyFolder) {
    TempDir prefix, elsewhere;
    const ProcessResult install = runProcess(RAYS_CMAKE, {"--install", RAYS_BUILD_DIR, "--prefix", prefix.path().string()});
    ASSERT_TRUE(install.ok()) << install.summary() << "\n" << install.out << install.err;
    const fs::path rays = prefix.path() / "bin" / "rays";
    ASSERT_TRUE(fs::exists(rays)) << install.out;
    EXPECT_TRUE(fs::exists(prefix.path() / "share" / "rays" / "scenes" / "models" / "stanford-bunny.obj.gz"));
    EXPECT_TRUE(fs::exists(prefix.path() / "share" / "doc" / "rays" / "README.md"));
    const std::string man = readFile(prefix.path() / "share" / "man" / "man1" / "rays.1");
    EXPECT_TRUE(contains(man, ".TH RAYS 1")) << man.substr(0, 200);
    EXPECT_TRUE(contains(man, "--edges")) << "the man page carries render --help";

    const ProcessResult list = runProcess(rays.string(), {"scenes"}, elsewhere.path().string());
    ASSERT_TRUE(list.ok()) << list.summary() << list.err;
    EXPECT_TRUE(contains(list.out, (prefix.path() / "share" / "rays" / "scenes").string())) << list.out;
    // Scene 12 reads a texture, a gzip-compressed OBJ and its uv map, all from the installed folder.
    for (const char* scene : {"8", "textured-mesh"}) {
        const ProcessResult r = runProcess(rays.string(), {"render", "--scene", scene, "40", "30", "-q", "--strict", "-o", "out.png"},
                                           elsewhere.path().string());
        EXPECT_TRUE(r.ok()) << scene << ": " << r.summary() << "\n" << r.err;
        EXPECT_EQ(r.err, "") << scene;
        EXPECT_TRUE(fs::exists(elsewhere.path() / "out.png")) << scene;
        fs::remove(elsewhere.path() / "out.png");
    }
}

}}  // namespace RAYS_TEST_UNIT, namespace
