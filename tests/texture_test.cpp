// Texture mapping, normal and bump maps, and the extra shading models.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>

#include "rays/accel/bvh.h"
#include "rays/error.h"
#include "rays/image/procedural.h"
#include "rays/io/image_io.h"
#include "rays/io/scene_parser.h"
#include "rays/render/renderer.h"
#include "rays/render/shading.h"
#include "rays/render/texturing.h"
#include "support/process.h"

using namespace rays;
namespace fs = std::filesystem;

namespace { namespace RAYS_TEST_UNIT {

ImageF renderText(const std::string& text, const std::string& file, int w, int h, ShadingModel shading) {
    ParseOptions opt;
    opt.warn = [](const std::string&) {};
    const Scene scene = parseScene(text, file, opt);
    const Bvh bvh(scene.objects);
    RenderSettings s;
    s.width = w;
    s.height = h;
    s.shading = shading;
    TraceStats stats;
    return render(scene, bvh, s, stats);
}

// A 4×4 texture whose texel (x, y) (y = row from the top) has colour (x·60, y·60, 200).
Image8 codedTexture() {
    Image8 img(4, 4, 3);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            img.row(y)[x * 3 + 0] = uint8_t(x * 60);
            img.row(y)[x * 3 + 1] = uint8_t(y * 60);
            img.row(y)[x * 3 + 2] = 200;
        }
    return img;
}

TEST(Texturing, TangentFramesAreOrthonormal) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 N = normalize(Vec3{u(rng), u(rng), u(rng)});
        Vec3 T, B;
        tangentFrame(N, Vec3{u(rng), u(rng), u(rng)}, Vec3{u(rng), u(rng), u(rng)}, T, B);
        EXPECT_NEAR(length(T), 1, 1e-12);
        EXPECT_NEAR(length(B), 1, 1e-12);
        EXPECT_NEAR(dot(T, N), 0, 1e-12);
        EXPECT_NEAR(dot(B, N), 0, 1e-12);
        EXPECT_NEAR(dot(T, B), 0, 1e-12);
    }
    // Degenerate dP/du (along N) still gives a frame.
    Vec3 T, B;
    tangentFrame(Vec3{0, 0, 1}, Vec3{0, 0, 1}, Vec3{0, 1, 0}, T, B);
    EXPECT_NEAR(dot(T, Vec3{0, 0, 1}), 0, 1e-12);
    EXPECT_GT(B.y, 0);  // turned toward dP/dv
}

TEST(Texturing, KnownPointsLandOnKnownTexels) {
    Texture t;
    t.width = t.height = 4;
    const Image8 img = codedTexture();
    t.rgb = img.pixels;
    for (int b = 0; b < 256; ++b) t.decode[size_t(b)] = float(b / 255.0);
    auto texelAt = [&](int mapType, Vec3 p) {
        double u, v;
        mapCoordinates(mapType, p, u, v);
        const Vec3 c = t.sample(u, v, false);
        return std::pair<int, int>{int(std::lround(c.x * 255 / 60)), int(std::lround(c.y * 255 / 60))};
    };
    // Planar: u = x, v = y, v = 0 at the bottom row (row 3).
    EXPECT_EQ(texelAt(0, {0.1, 0.1, 5}), std::make_pair(0, 3));
    EXPECT_EQ(texelAt(0, {0.6, 0.9, 0}), std::make_pair(2, 0));
    EXPECT_EQ(texelAt(0, {1.3, 0.3, 0}), std::make_pair(1, 2));  // repeats
    // Spherical: u from +x toward +z, v = ½ + asin(y)/π.
    EXPECT_EQ(texelAt(1, {1, 0.01, 0.01}), std::make_pair(0, 1));
    EXPECT_EQ(texelAt(1, {-0.01, 0.01, 1}), std::make_pair(1, 1));
    EXPECT_EQ(texelAt(1, {-1, -0.01, -0.01}), std::make_pair(2, 2));
    EXPECT_EQ(texelAt(1, {0.1, 0.99, 0}), std::make_pair(0, 0));  // near the top: top row
    // Cylindrical: u around y, v = y.
    EXPECT_EQ(texelAt(2, {0.01, 0.3, -1}), std::make_pair(3, 2));
    EXPECT_EQ(texelAt(2, {-1, 0.8, -0.01}), std::make_pair(2, 0));
}

TEST(Texturing, ImageMapEndToEnd) {
    rays::test::TempDir dir;
    writeImage((dir.path() / "coded.png").string(), codedTexture());
    // A plane facing the camera covering [0,1]² exactly (camera 10 away, image plane 0.1 wide).
    const std::string scene =
        "camera { location <0.5, 0.5, 10> up <0, 0.1, 0> right <0.1, 0, 0> look_at <0.5, 0.5, 0> }\n"
        "plane { <0, 0, 1>, 0 pigment { image_map { png \"coded.png\" } } }\n";
    const ImageF img = renderText(scene, (dir.path() / "s.pov").string(), 8, 8, ShadingModel::Flat);
    // Pixel (x, y) of the 8×8 image shows texel (x/2, y/2).
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            EXPECT_NEAR(img.at(x, y).x * 255, (x / 2) * 60, 1e-3) << x << "," << y;
            EXPECT_NEAR(img.at(x, y).y * 255, (y / 2) * 60, 1e-3) << x << "," << y;
        }
}

TEST(Texturing, FlatNormalMapChangesNothing) {
    rays::test::TempDir dir;
    Image8 flat(8, 8, 3);
    for (size_t i = 0; i < flat.pixels.size(); i += 3) {
        flat.pixels[i] = 128;
        flat.pixels[i + 1] = 128;
        flat.pixels[i + 2] = 255;
    }
    writeImage((dir.path() / "flat.png").string(), flat);
    const std::string base =
        "camera { location <0, 1, 6> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }\n"
        "light_source { <-5, 5, 5> color rgb 1 }\n"
        "plane { <0, 1, 0>, -1 pigment { color rgb 0.8 } finish { ambient 0.2 diffuse 0.7 } }\n";
    const std::string sphere = "sphere { <0, 0, 0>, 1 pigment { color rgb <1, 0.5, 0.2> } finish { ambient 0.2 diffuse 0.6 specular 0.5 roughness 0.1 } ";
    const std::string file = (dir.path() / "s.pov").string();
    const ImageF plain = renderText(base + sphere + "}\n", file, 64, 48, ShadingModel::BlinnPhong);
    const ImageF mapped = renderText(base + sphere + "normal { normal_map { png \"flat.png\" map_type 1 } } }\n", file, 64, 48,
                                     ShadingModel::BlinnPhong);
    EXPECT_EQ(toImage8(plain).pixels, toImage8(mapped).pixels);
}

TEST(Texturing, NormalMapTiltsShading) {
    rays::test::TempDir dir;
    writeImage((dir.path() / "n.png").string(), normalMapFromHeight(brickHeightImage(64, 64, 4), 6.0));
    const std::string text =
        "camera { location <0, 0, 6> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }\n"
        "light_source { <-5, 5, 5> color rgb 1 }\n"
        "sphere { <0, 0, 0>, 1.5 pigment { color rgb 1 } finish { diffuse 1 } ";
    const std::string file = (dir.path() / "s.pov").string();
    const ImageF plain = renderText(text + "}\n", file, 64, 48, ShadingModel::Lambert);
    const ImageF mapped = renderText(text + "normal { normal_map { png \"n.png\" map_type 1 } } }\n", file, 64, 48,
                                     ShadingModel::Lambert);
    double diff = 0;
    for (size_t i = 0; i < plain.pixels.size(); ++i) diff += std::fabs(plain.pixels[i].x - mapped.pixels[i].x);
    EXPECT_GT(diff / double(plain.pixels.size()), 0.01);
}

TEST(Texturing, FlatHeightGivesFlatNormals) {
    Image8 h(16, 16, 1);
    std::fill(h.pixels.begin(), h.pixels.end(), 100);
    const Image8 n = normalMapFromHeight(h, 5.0);
    for (size_t i = 0; i < n.pixels.size(); i += 3) {
        EXPECT_EQ(n.pixels[i], 128);
        EXPECT_EQ(n.pixels[i + 1], 128);
        EXPECT_EQ(n.pixels[i + 2], 255);
    }
    EXPECT_EQ(decodeNormal(Vec3{128 / 255.0, 128 / 255.0, 1.0}), Vec3(0, 0, 1));
}

TEST(Texturing, MissingTextureIsAnErrorAtTheFileName) {
    rays::test::TempDir dir;
    const std::string file = (dir.path() / "s.pov").string();
    try {
        ParseOptions opt;
        parseScene("camera { location <0,0,5> up <0,1,0> right <1,0,0> look_at <0,0,0> }\n"
                   "sphere { <0,0,0>, 1 pigment { image_map { png \"nope.png\" } } }\n",
                   file, opt);
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind(file + ":2:47: error: cannot open image file", 0), 0u) << msg;
    }
}

TEST(ShadingModels, OrenNayarWithZeroSigmaIsLambert) {
    Material m;
    m.color = {0.8, 0.5, 0.3};
    m.diffuse = 0.9;
    m.sigma = 0;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 200; ++i) {
        const Vec3 N{0, 0, 1};
        const Vec3 L = normalize(Vec3{u(rng), u(rng), std::fabs(u(rng)) + 0.05});
        const Vec3 V = normalize(Vec3{u(rng), u(rng), std::fabs(u(rng)) + 0.05});
        const LightTerms a = orenNayar(m, N, L, V, Vec3(1.0)), b = lambert(m, N, L, Vec3(1.0));
        EXPECT_NEAR(a.diffuse.x, b.diffuse.x, 1e-12);
        EXPECT_NEAR(a.diffuse.z, b.diffuse.z, 1e-12);
    }
}

TEST(ShadingModels, OrenNayarFlattensBackscatter) {
    // Rough surfaces look flatter: lit and viewed from the same grazing direction, Oren-Nayar
    // returns more light than Lambert.
    Material m;
    m.color = Vec3(1.0);
    m.diffuse = 1;
    m.sigma = 30;
    const Vec3 N{0, 0, 1}, L = normalize(Vec3{1, 0, 0.3});
    const LightTerms on = orenNayar(m, N, L, L, Vec3(1.0)), lam = lambert(m, N, L, Vec3(1.0));
    EXPECT_GT(on.diffuse.x, lam.diffuse.x);
}

TEST(ShadingModels, PerObjectKeywordAndNames) {
    ShadingModel sm;
    EXPECT_TRUE(parseShadingName("oren_nayar", sm));
    EXPECT_EQ(sm, ShadingModel::OrenNayar);
    EXPECT_TRUE(parseShadingName("lambert", sm));
    EXPECT_FALSE(parseShadingName("phong", sm));
    ParseOptions opt;
    const Scene s = parseScene("camera { location <0,0,5> up <0,1,0> right <1,0,0> look_at <0,0,0> }\n"
                               "sphere { <0,0,0>, 1 shading lambert finish { sigma 25 } }\n",
                               "t.pov", opt);
    EXPECT_EQ(s.objects[0].material.shading, int(ShadingModel::Lambert));
    EXPECT_DOUBLE_EQ(s.objects[0].material.sigma, 25);
}

}}  // namespace RAYS_TEST_UNIT, namespace
