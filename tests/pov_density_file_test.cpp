// POV-Ray's density_file pattern (pattern/density_file.*, pov/density_files.*): DF3 reading (sizes,
// 8/16/32-bit values, broken files) and the values of a 3×2×2 grid at scattered points against
// POV-Ray 3.7's, printed by `function { pigment { density_file df3 "t.df3" interpolate N
// color_map { [0 rgb 0] [1 rgb 1] } } }` for the file written below (voxel (x, y, z) holds
// min(255, 10 + 20x + 70y + 140z)).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "rays/error.h"
#include "rays/pattern/density_file.h"
#include "support/pov_scene.h"
#include "support/process.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

std::string df3(int nx, int ny, int nz, const std::string& values) {
    std::string b;
    for (int n : {nx, ny, nz}) b += char(n >> 8), b += char(n & 255);
    return b + values;
}

std::string sample() {
    std::string v;
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) v += char(std::min(255, 10 + 20 * x + 70 * y + 140 * z));
    return df3(3, 2, 2, v);
}

TEST(PovDensityFile, ReadsSizesAndScalesEachValueSize) {
    pattern::DensityGrid g;
    std::string why;
    ASSERT_TRUE(pattern::readDf3(sample(), g, why)) << why;
    EXPECT_EQ(g.nx, 3);
    EXPECT_EQ(g.ny, 2);
    EXPECT_EQ(g.nz, 2);
    EXPECT_FLOAT_EQ(g.values[1], 30 / 255.0f);
    // Two bytes a value: big-endian, over 65535.
    ASSERT_TRUE(pattern::readDf3(df3(1, 1, 2, std::string("\x80\x00\xff\xff", 4)), g, why)) << why;
    EXPECT_FLOAT_EQ(g.values[0], 32768 / 65535.0f);
    EXPECT_FLOAT_EQ(g.values[1], 1.0f);
    ASSERT_TRUE(pattern::readDf3(df3(1, 1, 1, std::string("\x40\x00\x00\x00", 4)), g, why)) << why;
    EXPECT_NEAR(g.values[0], 0.25, 1e-6);
    EXPECT_FALSE(pattern::readDf3("\x00\x01", g, why));
    EXPECT_NE(why.find("three 16-bit sizes"), std::string::npos);
    EXPECT_FALSE(pattern::readDf3(df3(0, 2, 2, ""), g, why));
    EXPECT_NE(why.find("size is 0"), std::string::npos);
    EXPECT_FALSE(pattern::readDf3(df3(2, 2, 2, "abc"), g, why));
    EXPECT_NE(why.find("3 bytes of values for a 2x2x2 grid"), std::string::npos);
}

struct Point {
    Vec3 p;
    double nearest, trilinear;
};

// POV-Ray 3.7's values (interpolate 0 and 1).
const Point kMeasured[] = {
    {{0.1, 0.1, 0.1}, 0.039216, 0.227451}, {{0.4, 0.1, 0.1}, 0.117647, 0.297882},
    {{0.7, 0.1, 0.1}, 0.196078, 0.344392}, {{0.1, 0.6, 0.1}, 0.313726, 0.392157},
    {{0.1, 0.1, 0.6}, 0.588235, 0.556863}, {{0.5, 0.5, 0.5}, 0.941176, 0.970588},
    {{0.2, 0.3, 0.4}, 0.039216, 0.690196}, {{0.9, 0.9, 0.9}, 1.000000, 0.250745},
    {{1.1, 0.5, 0.5}, 0, 0},               {{-0.1, 0.5, 0.5}, 0, 0},
    {{0.333, 0.25, 0.25}, 0.039216, 0.529333}, {{0.99, 0.01, 0.5}, 0.745098, 0.598420},
};

TEST(PovDensityFile, ValuesMatchPovRay) {
    test::TempDir dir;
    const std::string path = (dir.path() / "t.df3").string();
    std::ofstream(path, std::ios::binary) << sample();
    for (int mode : {0, 1, 2}) {
        const Scene s = test::buildPov("plane { z, 0 pigment { density_file df3 \"" + path + "\" interpolate " +
                                       std::to_string(mode) + " color_map { [0 rgb 0] [1 rgb 1] } } }");
        const PovSurface& surface = s.povSurfaces.at(size_t(s.objects.at(0).material.pov));
        for (const Point& m : kMeasured) {
            const double v = s.pigments.atRoot(surface.pigment, m.p).rgb.x;
            if (mode == 2) continue;
            EXPECT_NEAR(v, mode == 0 ? m.nearest : m.trilinear, 2e-6) << mode << " at " << m.p.x << " " << m.p.y << " " << m.p.z;
        }
        if (mode == 2) {  // Catmull-Rom: POV-Ray's values where the cell is not the first along x
            EXPECT_NEAR(s.pigments.atRoot(surface.pigment, {0.4, 0.1, 0.1}).rgb.x, 0.222709, 2e-6);
            EXPECT_NEAR(s.pigments.atRoot(surface.pigment, {0.5, 0.5, 0.5}).rgb.x, 0.984069, 2e-6);
            EXPECT_NEAR(s.pigments.atRoot(surface.pigment, {0.9, 0.9, 0.9}).rgb.x, 0.161978, 2e-6);
        }
    }
}

TEST(PovDensityFile, AMissingOrBrokenFileIsAnErrorAtTheKeyword) {
    try {
        test::buildPov("plane { z, 0\n  pigment { density_file df3 \"no-such.df3\" } }");  // line 3 (after #version)
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("scene.pov:3:13: error: cannot find the density file \"no-such.df3\""), std::string::npos)
            << e.what();
    }
    test::TempDir dir;
    const std::string path = (dir.path() / "bad.df3").string();
    std::ofstream(path, std::ios::binary) << df3(4, 4, 4, "x");
    try {
        test::buildPov("sphere { 0, 1 pigment { density_file df3 \"" + path + "\" } }");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("1 bytes of values for a 4x4x4 grid"), std::string::npos) << e.what();
    }
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
