// POV-Ray's image_map pigment (pattern/image_map.*, pov/pigment_compile, pov/image_files) and
// height_field (scene/shapes/height_field.*, pov/build_height_field): texels of tiny generated
// PNGs at known points for each map type, once, interpolate 2 and 4 (values measured with
// POV-Ray 3.7 on the same 4×2 image), filter/transmit, file gamma; height field hits and normals
// on tiny images (checked against POV-Ray's trace()) and functions, water_level and CSG inside.
#include <gtest/gtest.h>

#include <zlib.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "rays/error.h"
#include "rays/io/image_io.h"
#include "support/pov_scene.h"
#include "support/process.h"
#include "support/tiny_images.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

// The 4×2 grey image: top row 0 80 160 240, bottom row 40 120 200 255.
std::string greyImage(const test::TempDir& dir) {
    Image8 img(4, 2, 1);
    const uint8_t v[8] = {0, 80, 160, 240, 40, 120, 200, 255};
    std::copy(v, v + 8, img.pixels.begin());
    const std::string path = (dir.path() / "g42.png").string();
    writeImage(path, img);
    return path;
}

// The colour of the only object's pigment at p.
pattern::Rgbft pigmentAt(const Scene& s, Vec3 p) {
    const PovSurface& surface = s.povSurfaces.at(size_t(s.objects.at(0).material.pov));
    return s.pigments.atRoot(surface.pigment, p);
}

Scene withMap(const std::string& path, const std::string& modifiers, const std::string& head = "#version 3.7;\n") {
    return test::loadPov("plane { z, 0 pigment { image_map { png \"" + path + "\" " + modifiers + " } } }", head).scene;
}

// A 4×2 image: top row red, green, blue, (200, 100, 50); bottom row black, white, grey 128,
// (30, 60, 90); with alpha 255, 128, 0, 64 / 255, 200, 30, 100 when asked.
std::string colourImage(const test::TempDir& dir, bool alpha) {
    const int ch = alpha ? 4 : 3;
    Image8 img(4, 2, ch);
    const uint8_t rgb[8][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {200, 100, 50},
                               {0, 0, 0},   {255, 255, 255}, {128, 128, 128}, {30, 60, 90}};
    const uint8_t a[8] = {255, 128, 0, 64, 255, 200, 30, 100};
    for (int i = 0; i < 8; ++i) {
        for (int c = 0; c < 3; ++c) img.pixels[size_t(i * ch + c)] = rgb[i][c];
        if (alpha) img.pixels[size_t(i * ch + 3)] = a[i];
    }
    const std::string path = (dir.path() / (alpha ? "a42.png" : "c42.png")).string();
    writeImage(path, img);
    return path;
}

// The value of `image_pattern { ... }` (black to white) at p.
double imagePatternAt(const std::string& pattern, Vec3 p) {
    return pigmentAt(test::loadPov("plane { z, 0 pigment { " + pattern + " color_map { [0 rgb 0] [1 rgb 1] } } }").scene, p)
        .rgb.x;
}

TEST(PovImageMap, ImagePatternIsTheImagesGreyAsPovRayReadsIt) {
    test::TempDir dir;
    const std::string c = colourImage(dir, false), a = colourImage(dir, true);
    // Values printed by POV-Ray 3.7's pattern functions on the same images.
    struct Sample {
        Vec3 p;
        double v;
    };
    const std::string plain = "image_pattern { png \"" + c + "\" }";
    for (const Sample& s : {Sample{{0.125, 0.75, 0}, 0.297}, Sample{{0.375, 0.75, 0}, 0.589}, Sample{{0.625, 0.75, 0}, 0.114},
                            Sample{{0.875, 0.75, 0}, 0.486274511}, Sample{{0.625, 0.25, 0}, 0.501960814},
                            Sample{{0.875, 0.25, 0}, 0.213764712}, Sample{{1.3, -0.4, 0}, 0.589}})
        EXPECT_NEAR(imagePatternAt(plain, s.p), s.v, 1e-7) << s.p.x << " " << s.p.y;
    // An explicit gamma decodes each channel; interpolation and once as image_map's.
    const std::string gamma = "image_pattern { png \"" + c + "\" gamma 2.2 }";
    EXPECT_NEAR(imagePatternAt(gamma, {0.875, 0.75, 0}), 0.252313137, 1e-7);
    EXPECT_NEAR(imagePatternAt(gamma, {0.625, 0.25, 0}), 0.219519734, 1e-7);
    EXPECT_NEAR(imagePatternAt("image_pattern { png \"" + c + "\" interpolate 2 }", {0.3, 0.6, 0}), 0.560979962, 1e-7);
    const std::string once = "image_pattern { png \"" + c + "\" once } scale 0.5";
    EXPECT_NEAR(imagePatternAt(once, {0.3, 0.45, 0}), 0.114, 1e-7);
    EXPECT_NEAR(imagePatternAt(once, {0.6, 0.3, 0}), 0, 1e-7);
    // use_alpha: the transparency 1 − alpha.
    const std::string alpha = "image_pattern { png \"" + a + "\" gamma 1.0 use_alpha }";
    EXPECT_NEAR(imagePatternAt(alpha, {0.375, 0.75, 0}), 0.498039186, 1e-7);
    EXPECT_NEAR(imagePatternAt(alpha, {0.875, 0.75, 0}), 0.749019623, 1e-7);
    EXPECT_NEAR(imagePatternAt(alpha, {0.625, 0.25, 0}), 0.882352948, 1e-7);
}

TEST(PovImageMap, PlanarTexelsRepeatUnlessOnce) {
    test::TempDir dir;
    const std::string path = greyImage(dir);
    const Scene s = withMap(path, "gamma 1.0");
    EXPECT_NEAR(pigmentAt(s, {0.6, 0.75, 0}).rgb.x, 160 / 255.0, 1e-6);  // column 2, top row
    EXPECT_NEAR(pigmentAt(s, {0.1, 0.25, 0}).rgb.y, 40 / 255.0, 1e-6);   // column 0, bottom row
    EXPECT_NEAR(pigmentAt(s, {1.6, 0.75, 0}).rgb.z, 160 / 255.0, 1e-6);  // repeated
    EXPECT_NEAR(pigmentAt(s, {-0.1, -0.75, 0}).rgb.x, 255 / 255.0, 1e-6);
    const Scene once = withMap(path, "gamma 1.0 once");
    EXPECT_NEAR(pigmentAt(once, {0.6, 0.75, 0}).rgb.x, 160 / 255.0, 1e-6);
    EXPECT_EQ(pigmentAt(once, {1.6, 0.75, 0}).transmit, 1.0);  // outside: fully transparent
    EXPECT_EQ(pigmentAt(once, {0.6, 0.75, 0}).transmit, 0.0);
}

TEST(PovImageMap, InterpolationMatchesPovRay) {
    test::TempDir dir;
    const std::string path = greyImage(dir);
    // POV-Ray 3.7 wrote 88 (sRGB) there with interpolate 2 and 72 with interpolate 4.
    const Vec3 p{0.1875, 0.8125, 0};
    EXPECT_NEAR(pigmentAt(withMap(path, "gamma 1.0 interpolate 2"), p).rgb.x, 25 / 255.0, 1e-6);
    EXPECT_NEAR(pigmentAt(withMap(path, "gamma 1.0 interpolate 4"), p).rgb.x, 16.7997 / 255.0, 1e-4);
    EXPECT_NEAR(pigmentAt(withMap(path, "gamma 1.0"), p).rgb.x, 0.0, 1e-6);
}

TEST(PovImageMap, SphericalAndCylindricalMaps) {
    test::TempDir dir;
    const std::string path = greyImage(dir);
    const Scene sph = withMap(path, "gamma 1.0 map_type 1");
    EXPECT_NEAR(pigmentAt(sph, {1, 0.01, 0}).rgb.x, 0 / 255.0, 1e-6);     // +x, just north: top row, column 0
    EXPECT_NEAR(pigmentAt(sph, {1, -0.01, 0}).rgb.x, 40 / 255.0, 1e-6);   // just south: bottom row
    EXPECT_NEAR(pigmentAt(sph, {0, 0.5, 1}).rgb.x, 80 / 255.0, 1e-6);     // +z: a quarter turn, column 1
    EXPECT_NEAR(pigmentAt(sph, {0, 0.5, 7}).rgb.x, 80 / 255.0, 1e-6);     // any radius
    const Scene cyl = withMap(path, "gamma 1.0 map_type 2");
    EXPECT_NEAR(pigmentAt(cyl, {0, 0.25, -1}).rgb.x, 255 / 255.0, 1e-6);  // −z: column 3, bottom row
    EXPECT_NEAR(pigmentAt(cyl, {0, 1.75, -1}).rgb.x, 240 / 255.0, 1e-6);  // repeated in y
    const Scene cylOnce = withMap(path, "gamma 1.0 map_type 2 once");
    EXPECT_EQ(pigmentAt(cylOnce, {0, 1.75, -1}).transmit, 1.0);
}

TEST(PovImageMap, FilterAndTransmitAll) {
    test::TempDir dir;
    const std::string path = greyImage(dir);
    const pattern::Rgbft c = pigmentAt(withMap(path, "filter all 0.25 transmit all 0.5"), {0.1, 0.1, 0});
    EXPECT_DOUBLE_EQ(c.filter, 0.25);
    EXPECT_DOUBLE_EQ(c.transmit, 0.5);
    const Scene plain = withMap(path, "");
    EXPECT_EQ(pigmentAt(plain, {0.1, 0.1, 0}).filter, 0.0);
}

TEST(PovImageMap, PngIsDecodedAsSrgbInVersion37AndRawInLegacyScenes) {
    test::TempDir dir;
    const std::string path = greyImage(dir);
    const double v = 160 / 255.0, linear = std::pow((v + 0.055) / 1.055, 2.4);
    EXPECT_NEAR(pigmentAt(withMap(path, ""), {0.6, 0.75, 0}).rgb.x, linear, 1e-6);
    EXPECT_NEAR(pigmentAt(withMap(path, "", "#version 3.6;\n"), {0.6, 0.75, 0}).rgb.x, v, 1e-6);
    // A legacy scene keeps the bytes as they are even with assumed_gamma 1.0 (measured with POV-Ray
    // 3.7: a texel of 85 shows as 156 under #version 3.6 and assumed_gamma 1.0, as 85 under 3.7).
    const Scene legacyLinear = withMap(path, "", "#version 3.6;\nglobal_settings { assumed_gamma 1.0 }\n");
    EXPECT_NEAR(pigmentAt(legacyLinear, {0.6, 0.75, 0}).rgb.x, v, 1e-6);
    // assumed_gamma 2.2: linear light in the working space, c = linear^(1/2.2).
    const Scene g22 = withMap(path, "", "#version 3.7;\nglobal_settings { assumed_gamma 2.2 }\n");
    EXPECT_NEAR(pigmentAt(g22, {0.6, 0.75, 0}).rgb.x, std::pow(linear, 1 / 2.2), 1e-6);
    // An explicit gamma: v^gamma.
    EXPECT_NEAR(pigmentAt(withMap(path, "gamma 2.0"), {0.6, 0.75, 0}).rgb.x, v * v, 1e-6);
}

// A PNG that states its gamma is decoded by it in a legacy scene with an assumed_gamma, one
// without those chunks is not (measured with POV-Ray 3.7, #version 3.6, assumed_gamma 1.0: a grey
// texel of 85 shows as 84 with gAMA 0.45455, as 85 with an sRGB chunk, as 156 without either).
TEST(PovImageMap, LegacyScenesDecodeOnlyPngsThatStateTheirGamma) {
    test::TempDir dir;
    const std::vector<uint8_t> raw = {0, 85, 85, 85, 160, 160, 160};  // one row: two RGB texels
    const std::string plain = (dir.path() / "plain.png").string(), gama = (dir.path() / "gama.png").string(),
                      srgb = (dir.path() / "srgb.png").string();
    test::writeBytes(plain, test::pngBytes(2, 1, 8, 2, raw));
    test::writeBytes(gama, test::pngBytes(2, 1, 8, 2, raw, {}, {{"gAMA", {0, 0, 0xB1, 0x8F}}}));  // 45455
    test::writeBytes(srgb, test::pngBytes(2, 1, 8, 2, raw, {}, {{"sRGB", {0}}}));
    const std::string legacy = "#version 3.6;\nglobal_settings { assumed_gamma 1.0 }\n";
    const double v = 85 / 255.0;
    const Vec3 p{0.25, 0.5, 0};
    EXPECT_NEAR(pigmentAt(withMap(plain, "", legacy), p).rgb.x, v, 1e-6);
    EXPECT_NEAR(pigmentAt(withMap(gama, "", legacy), p).rgb.x, std::pow(v, 1 / 0.45455), 1e-6);
    EXPECT_NEAR(pigmentAt(withMap(srgb, "", legacy), p).rgb.x, std::pow((v + 0.055) / 1.055, 2.4), 1e-6);
    // Without assumed_gamma a legacy scene does no gamma handling at all.
    EXPECT_NEAR(pigmentAt(withMap(gama, "", "#version 3.6;\n"), p).rgb.x, v, 1e-6);
}

TEST(PovImageMap, MissingFileIsAnErrorAtItsPlace) {
    try {
        test::loadPov("plane { z, 0 pigment { image_map { png \"no-such-image-file.png\" } } }");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("scene.pov:2:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no-such-image-file.png"), std::string::npos) << e.what();
    }
}

// A 16-bit grey PNG of w × h samples (row-major, top row first), written by hand.
void write16(const std::string& path, int w, int h, const std::vector<uint16_t>& v) {
    std::vector<uint8_t> raw;
    for (int y = 0; y < h; ++y) {
        raw.push_back(0);
        for (int x = 0; x < w; ++x) {
            raw.push_back(uint8_t(v[size_t(y * w + x)] >> 8));
            raw.push_back(uint8_t(v[size_t(y * w + x)] & 255));
        }
    }
    test::writeBytes(path, test::pngBytes(w, h, 16, 0, raw));
}

TEST(PovHeightField, TrianglesSplitAsPovRayAndNormalsFaceUp) {
    test::TempDir dir;
    Image8 img(2, 2, 1);
    img.pixels = {255, 0, 0, 0};  // the top-left sample high: the corner x = 0, z = 1
    const std::string path = (dir.path() / "hf22.png").string();
    writeImage(path, img);
    const Scene s = test::buildPov("height_field { png \"" + path + "\" }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(shapeName(s.objects[0].type), "HeightField");
    // POV-Ray's trace(): (0.25, 0.75) → y 0.75, normal <0.707, 0.707, 0> (the far triangle, y = 1 − x);
    // (0.25, 0.25) → y 0.25, normal <0, 0.707, −0.707> (the near one, y = z); (0.75, 0.25) → 0.25:
    // the diagonal runs from x = 1, z = 0 to x = 0, z = 1.
    Hit h = test::shootPov(s, {0.3, 5, 0.75}, {0, -1, 0});
    ASSERT_TRUE(h.valid());
    EXPECT_NEAR(5 - h.t, 0.7, 1e-9);
    EXPECT_NEAR(length(h.normal - normalize(Vec3{1, 1, 0})), 0, 1e-9);
    h = test::shootPov(s, {0.25, 5, 0.25}, {0, -1, 0});
    EXPECT_NEAR(5 - h.t, 0.25, 1e-9);
    EXPECT_NEAR(length(h.normal - normalize(Vec3{0, 1, -1})), 0, 1e-9);
    EXPECT_NEAR(5 - test::shootPov(s, {0.75, 5, 0.25}, {0, -1, 0}).t, 0.25, 1e-9);
    EXPECT_NEAR(5 - test::shootPov(s, {0.75, 5, 0.75}, {0, -1, 0}).t, 0.25, 1e-9);
    EXPECT_FALSE(test::shootPov(s, {2, 5, 2}, {0, -1, 0}).valid());  // outside the unit square
}

TEST(PovHeightField, SixteenBitSamplesKeepTheirPrecision) {
    test::TempDir dir;
    const std::string path = (dir.path() / "hf16.png").string();
    write16(path, 2, 2, {32768, 32768, 32768, 32768});
    const Scene s = test::buildPov("height_field { png \"" + path + "\" }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_NEAR(5 - test::shootPov(s, {0.3, 5, 0.6}, {0, -1, 0}).t, 32768 / 65535.0, 1e-9);
}

TEST(PovHeightField, FunctionSmoothWaterLevelAndCsgInside) {
    // y = x / 2 sampled on 3 × 3: a plane, hit at x / 2 with the normal <−0.5, 1, 0> normalised.
    const Scene f = test::buildPov("height_field { function 3, 3 { x * 0.5 } }");
    Hit h = test::shootPov(f, {0.5, 5, 0.3}, {0, -1, 0});
    ASSERT_TRUE(h.valid());
    EXPECT_NEAR(5 - h.t, 0.25, 1e-9);
    EXPECT_NEAR(length(h.normal - normalize(Vec3{-0.5, 1, 0})), 0, 1e-9);
    // smooth: the vertex normals of a plane are the plane's.
    h = test::shootPov(test::buildPov("height_field { function 3, 3 { x * 0.5 } smooth }"), {0.4, 5, 0.3}, {0, -1, 0});
    EXPECT_NEAR(length(h.normal - normalize(Vec3{-0.5, 1, 0})), 0, 1e-9);
    // water_level 0.5 leaves out what lies below it.
    const Scene w = test::buildPov("height_field { function 5, 5 { x } water_level 0.5 }");
    EXPECT_FALSE(test::shootPov(w, {0.25, 5, 0.5}, {0, -1, 0}).valid());
    EXPECT_NEAR(5 - test::shootPov(w, {0.75, 5, 0.5}, {0, -1, 0}).t, 0.75, 1e-9);
    // Inside is below the surface: the sphere's top (above the field) is cut away by the
    // intersection, leaving the field's surface at 0.5 inside the sphere.
    const Scene c = test::buildPov(
        "intersection { height_field { function 3, 3 { 0.5 } } sphere { <0.5, 0.5, 0.5>, 0.3 } }");
    EXPECT_NEAR(5 - test::shootPov(c, {0.5, 5, 0.5}, {0, -1, 0}).t, 0.5, 1e-9);
}

TEST(PovImageMap, MaterialMapPicksATextureByPaletteIndex) {
    test::TempDir dir;
    // A 9 × 1 palette image of indices 0 1 2 6 7 8 9 10 11 under three textures: index modulo 3
    // (measured with POV-Ray 3.7 on a 16 × 1 image of indices 0..15: red green blue from index 6
    // on; indices 3, 4, 5 gave blue, green, blue, index 3 unexplained and not reproduced).
    const std::string path = (dir.path() / "mm.png").string();
    test::Palette pal(16, {0, 0, 0});
    for (int i = 0; i < 16; ++i) pal[size_t(i)] = {uint8_t(16 * i), uint8_t(16 * i), uint8_t(16 * i)};
    test::writePalettePng(path, 9, 1, {0, 1, 2, 6, 7, 8, 9, 10, 11}, pal, 4);
    const Scene s = test::loadPov("plane { -z, 0 texture { material_map { png \"" + path +
                                  "\" texture { pigment { rgb <1,0,0> } } texture { pigment { rgb <0,1,0> } }"
                                  " texture { pigment { rgb <0,0,1> } } } } }")
                        .scene;
    const Vec3 want[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 9; ++i) {
        const Vec3 c = pigmentAt(s, {(i + 0.5) / 9, 0.5, 0}).rgb;
        EXPECT_NEAR(length(c - want[i % 3]), 0, 1e-9) << i;
    }
    // The map repeats over the plane as an image_map does.
    EXPECT_NEAR(length(pigmentAt(s, {1 + 1.5 / 9, 0.5, 0}).rgb - want[1]), 0, 1e-9);
}

TEST(PovImageMap, GifTexelsAreTheirPaletteColours) {
    test::TempDir dir;
    const std::string path = (dir.path() / "t.gif").string();
    test::writeGif(path, 2, 2, {0, 1, 2, 1}, {{0, 0, 0}, {255, 255, 255}, {255, 0, 0}});
    const Scene s = withMap(path, "", "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n");
    EXPECT_NEAR(length(pigmentAt(s, {0.25, 0.75, 0}).rgb - Vec3{0, 0, 0}), 0, 1e-6);
    EXPECT_NEAR(length(pigmentAt(s, {0.75, 0.75, 0}).rgb - Vec3{1, 1, 1}), 0, 1e-6);
    EXPECT_NEAR(length(pigmentAt(s, {0.25, 0.25, 0}).rgb - Vec3{1, 0, 0}), 0, 1e-6);
}

TEST(PovHeightField, PotFilesHoldSixteenBitHeightsInTwoHalves) {
    test::TempDir dir;
    // A 2 × 2 field: the left half holds the high bytes, the right half the low bytes.
    const std::string path = (dir.path() / "f.pot").string();
    test::Palette pal(256);
    for (int i = 0; i < 256; ++i) pal[size_t(i)] = {uint8_t(i), uint8_t(i), uint8_t(i)};
    test::writeGif(path, 4, 2, {128, 128, 0, 0, 128, 128, 0, 0}, pal);
    const Scene s = test::buildPov("height_field { pot \"" + path + "\" }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_NEAR(5 - test::shootPov(s, {0.3, 5, 0.6}, {0, -1, 0}).t, 32768 / 65536.0, 1e-9);
    const std::string path2 = (dir.path() / "g.pot").string();
    test::writeGif(path2, 4, 2, {1, 1, 2, 2, 1, 1, 2, 2}, pal);  // high byte 1, low byte 2
    const Scene s2 = test::buildPov("height_field { pot \"" + path2 + "\" }");
    EXPECT_NEAR(5 - test::shootPov(s2, {0.3, 5, 0.6}, {0, -1, 0}).t, 258 / 65536.0, 1e-9);
}

TEST(PovHeightField, MtmandPotHeightsMatchPovRaysTrace) {
    const std::string pot = "/usr/share/povray-3.7/include/mtmand.pot";
    if (!std::filesystem::exists(pot)) GTEST_SKIP() << pot << " is not installed";
    const Scene s = test::buildPov("height_field { pot \"" + pot + "\" }");
    ASSERT_EQ(s.objects.size(), 1u);
    // POV-Ray 3.7's trace() straight down onto grid points (column i / 159, row j / 119) of the
    // 160 × 120 field, its heights × 65535 printed with #debug.
    struct Point {
        int i, j;
        double y;
    };
    for (const Point& p : {Point{1, 1, 22983.649}, Point{158, 118, 255.996}, Point{100, 30, 64675.013},
                           Point{2, 117, 28481.565}, Point{157, 3, 46871.285}, Point{120, 90, 31674.517},
                           Point{70, 20, 53806.179}, Point{10, 5, 27745.577}})
        EXPECT_NEAR((5 - test::shootPov(s, {p.i / 159.0, 5, p.j / 119.0}, {0, -1, 0}).t) * 65535, p.y, 2e-3)
            << p.i << " " << p.j;
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
