// Golden images: the project's own scenes (tests/scenes) rendered and compared with committed
// images (tests/golden) using the course tolerance. Set RAYS_UPDATE_GOLDEN=1 to rewrite them
// after an intended change, and look at the new images before committing them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "rays/accel/bvh.h"
#include "rays/io/image_io.h"
#include "rays/io/scene_parser.h"
#include "rays/render/renderer.h"
#include "support/image_compare.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

struct GoldenCase {
    const char* name;   ///< golden image name
    const char* scene;  ///< tests/scenes/<scene>.pov
    ShadingModel shading;
    bool fresnel, beers;
    int grid;
};

// gtest prints the case by name instead of its bytes.
void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name; }

std::string path(const std::string& rel) { return std::string(RAYS_SOURCE_DIR) + "/tests/" + rel; }

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesCommittedImage) {
    const GoldenCase& c = GetParam();
    const Scene scene = loadScene(path(std::string("scenes/") + c.scene + ".pov"));
    const Bvh bvh(scene.objects);
    RenderSettings s;
    s.width = 160;
    s.height = 120;
    s.shading = c.shading;
    s.fresnel = c.fresnel;
    s.beers = c.beers;
    s.aa = AaMode::Grid;
    s.spp = c.grid * c.grid;
    TraceStats stats;
    const Image8 img = toImage8(render(scene, bvh, s, stats));
    const std::string golden = path(std::string("golden/") + c.name + ".png");
    const char* update = std::getenv("RAYS_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
        writeImage(golden, img);
        GTEST_SKIP() << "rewrote " << golden;
    }
    const rays::test::RgbImage expected = rays::test::loadPngRgb(golden);
    ASSERT_EQ(expected.width, img.width);
    ASSERT_EQ(expected.height, img.height);
    const rays::test::ImageDiff d = rays::test::compareRgb(expected.pixels.data(), img.pixels.data(),
                                                         size_t(img.width) * size_t(img.height));
    EXPECT_TRUE(d.matches()) << c.name << ": " << d.describe();
}

INSTANTIATE_TEST_SUITE_P(Scenes, Golden,
                         ::testing::Values(GoldenCase{"shapes", "shapes", ShadingModel::BlinnPhong, false, false, 1},
                                           GoldenCase{"glass", "glass", ShadingModel::BlinnPhong, true, true, 2},
                                           GoldenCase{"pbr", "pbr", ShadingModel::CookTorrance, false, false, 1},
                                           GoldenCase{"shapes_normals", "shapes", ShadingModel::Normals, false, false, 1},
                                           GoldenCase{"shapes_flat", "shapes", ShadingModel::Flat, false, false, 1}),
                         [](const auto& info) { return std::string(info.param.name); });

}}  // namespace RAYS_TEST_UNIT, namespace
