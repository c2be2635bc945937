// Determinism: the same command gives the same bytes whatever the thread count and however often it
// runs. A scene with every feature (jittered area light, reflection, refraction with Fresnel and
// Beer's law, an image-mapped and normal-mapped sphere, a smooth mesh, box, cone) is rendered by the
// real `rays` binary in each sampling and effect mode (-ss grid, stratified, random, tent and
// Gaussian filters, edge-guided AA, depth of field, GI, feature lines by both methods with a mask,
// lines only, Cook-Torrance with a post filter) at 1, 2 and 8 threads and a second time at 8; the
// PNG files (and masks) must be identical byte for byte.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "rays/image/image.h"
#include "rays/io/image_io.h"
#include "support/files.h"
#include "support/process.h"

namespace fs = std::filesystem;
using rays::test::ProcessResult;
using rays::test::readFile;
using rays::test::runProcess;
using rays::test::TempDir;

namespace { namespace RAYS_TEST_UNIT {

const std::string kScene = R"(
camera { location <0, 3, 12> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0.5, 0> }
light_source { <-5, 9, 7> color rgb 1.2 area_light <2, 0, 0>, <0, 0, 2>, 4, 4 jitter }
light_source { <6, 4, 5> color rgb <0.3, 0.3, 0.35> }
plane { <0, 1, 0>, -1 pigment { color rgb <0.8, 0.8, 0.75> } finish { ambient 0.15 diffuse 0.7 reflection 0.25 } }
sphere { <-2.4, 0.3, 0>, 1.3 pigment { color rgbf <0.9, 1, 0.9, 0.8> } finish { ambient 0.05 diffuse 0.1 specular 0.6 roughness 0.05 ior 1.5 } }
sphere { <0.4, 0.3, -1>, 1.3
  pigment { image_map { png "tex.png" map_type 1 interpolate 2 } }
  normal { normal_map { png "tex.png" map_type 1 } }
  finish { ambient 0.2 diffuse 0.7 specular 0.3 roughness 0.2 } }
box { <-0.7, -1, -0.7>, <0.7, 0.4, 0.7> rotate <0, 30, 0> translate <3, 0, 1>
  pigment { color rgb <0.3, 0.8, 0.35> } finish { ambient 0.15 diffuse 0.7 reflection 0.4 } }
cone { <0, -1, 0>, 0.6, <0, 1.2, 0>, 0 translate <1.5, 0, 2.5> pigment { color rgb <0.95, 0.8, 0.2> } finish { ambient 0.2 diffuse 0.7 } }
mesh2 {
  vertex_vectors { 4, <-1, 0, 0>, <1, 0, 0>, <1, 1.5, 0>, <-1, 1.5, 0> }
  normal_vectors { 4, <-0.3, 0, 1>, <0.3, 0, 1>, <0.3, 0.2, 1>, <-0.3, 0.2, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  pigment { color rgb <0.6, 0.3, 0.8> } finish { ambient 0.2 diffuse 0.6 specular 0.4 roughness 0.1 }
  translate <-0.5, -1, -4> }
)";

struct Mode {
    std::string name;
    std::vector<std::string> args;
    bool mask = false;  ///< the mode writes an edge mask too
};

void PrintTo(const Mode& m, std::ostream* os) { *os << m.name; }

std::vector<Mode> modes() {
    return {
        {"SsGridFresnelBeers", {"-ss=2", "-fresnel", "-beers"}},
        {"StratifiedTent", {"--spp", "9", "--filter", "tent"}},
        {"RandomGaussian", {"--spp", "6", "--aa", "random", "--filter", "gaussian"}},
        {"EdgeGuidedAa", {"--aa-edges", "--spp", "9"}},
        {"DepthOfField", {"--aperture", "0.3", "--focal-distance", "11", "--dof-samples", "9"}},
        {"GlobalIllumination", {"-gi", "-gi_samples=6,2", "-gi_bounces=1"}},
        {"StencilLines", {"--edges", "all", "--edge-method", "stencil", "--spp", "4", "--edge-mask", "mask.png"}, true},
        {"ImageLines", {"--edges", "all", "--edge-method", "image", "--edge-mask", "mask.png"}, true},
        {"LinesOnly", {"--lines-only", "--edges", "all"}},
        {"CookTorrancePost", {"--shading", "cook-torrance", "--seed", "7", "--spp", "4", "--post", "gaussian_blur_3"}},
    };
}

class Determinism : public ::testing::TestWithParam<Mode> {};

TEST_P(Determinism, SameBytesForAnyThreadCountAndEveryRun) {
    const Mode& mode = GetParam();
    TempDir dir;
    ASSERT_FALSE(dir.path().empty());
    std::ofstream(dir.path() / "scene.pov") << kScene;
    rays::Image8 tex(32, 16, 3);
    for (int y = 0; y < tex.height; ++y)
        for (int x = 0; x < tex.width; ++x)
            for (int c = 0; c < 3; ++c) tex.row(y)[x * 3 + c] = uint8_t(((x / 4 + y / 4) % 2) ? 220 - 60 * c : 40 + 50 * c);
    rays::writeImage((dir.path() / "tex.png").string(), tex);

    std::string firstImage, firstMask;
    int run = 0;
    for (const char* threads : {"1", "2", "8", "8"}) {
        std::vector<std::string> args = {"render", "scene.pov", "64", "48", "-q", "--threads", threads, "-o", "out.png"};
        args.insert(args.end(), mode.args.begin(), mode.args.end());
        const ProcessResult r = runProcess(RAYS_BINARY, args, dir.path().string(), std::chrono::seconds(120));
        ASSERT_TRUE(r.ok()) << r.summary() << "\n" << r.err;
        const std::string image = readFile(dir.path() / "out.png");
        const std::string mask = mode.mask ? readFile(dir.path() / "mask.png") : "";
        ASSERT_FALSE(image.empty());
        if (run++ == 0) {
            firstImage = image;
            firstMask = mask;
            continue;
        }
        EXPECT_TRUE(image == firstImage) << mode.name << ": image at --threads " << threads << " (run " << run
                                         << ") differs from --threads 1";
        EXPECT_TRUE(mask == firstMask) << mode.name << ": edge mask at --threads " << threads << " (run " << run
                                       << ") differs from --threads 1";
    }
    // The render is not trivially uniform (a broken feature could make every run black).
    const rays::Image8 img = rays::readImage((dir.path() / "out.png").string());
    size_t distinct = 0;
    for (size_t i = 3; i < img.pixels.size(); i += 3) distinct += img.pixels[i] != img.pixels[i - 3];
    EXPECT_GT(distinct, img.pixels.size() / 3 / 20) << mode.name << ": the image is nearly uniform";
}

INSTANTIATE_TEST_SUITE_P(Modes, Determinism, ::testing::ValuesIn(modes()),
                         [](const ::testing::TestParamInfo<Mode>& info) { return info.param.name; });

}}  // namespace RAYS_TEST_UNIT, namespace
