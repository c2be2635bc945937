// HDR output and AOVs (docs/aov.md): the half conversion, PFM bytes, EXR files read back with
// OpenEXR's own C++ API, and `rays render -o X.exr --aov ...` on scenes of known geometry.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "rays/error.h"
#include "rays/image/image.h"
#include "rays/io/hdr_io.h"
#include "rays/io/image_io.h"
#include "rays/render/aov.h"
#include "rays/render/pov_output.h"
#include "support/files.h"
#include "support/process.h"

// RAYS_TEST_EXR: set by tests/CMakeLists.txt when the build found OpenEXR.
#if RAYS_TEST_EXR
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#endif

namespace fs = std::filesystem;
using rays::test::runProcess;
using rays::test::TempDir;

namespace { namespace RAYS_TEST_UNIT {

rays::test::ProcessResult runRays(const TempDir& dir, std::vector<std::string> args) {
    return runProcess(RAYS_BINARY, args, dir.path().string(), std::chrono::seconds(60));
}

#if RAYS_TEST_EXR
// An EXR read back with OpenEXR's C++ API: every channel as floats, top row first, and its type.
struct ExrRead {
    int width = 0, height = 0;
    std::map<std::string, std::vector<float>> channels;
    std::map<std::string, Imf::PixelType> types;
    float at(const std::string& name, int x, int y) const { return channels.at(name)[size_t(y) * width + x]; }
};

ExrRead readExr(const std::string& path) {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    ExrRead r;
    r.width = dw.max.x - dw.min.x + 1;
    r.height = dw.max.y - dw.min.y + 1;
    Imf::FrameBuffer fb;
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
        std::vector<float>& v = r.channels[it.name()];
        v.assign(size_t(r.width) * r.height, -12345.0f);
        r.types[it.name()] = it.channel().type;
        fb.insert(it.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(v.data()), sizeof(float),
                                        sizeof(float) * size_t(r.width)));
    }
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    return r;
}
#endif

// A PFM's floats (rows as stored, bottom first) and header.
struct PfmRead {
    std::string kind;
    int width = 0, height = 0;
    std::vector<float> values;
};

PfmRead readPfm(const fs::path& path) {
    const std::string bytes = rays::test::readFile(path);
    PfmRead r;
    char kind[3] = {};
    double scale = 0;
    int used = 0;
    EXPECT_EQ(std::sscanf(bytes.c_str(), "%2s %d %d %lf%n", kind, &r.width, &r.height, &scale, &used), 4);
    EXPECT_EQ(scale, -1.0);  // little-endian
    r.kind = kind;
    const size_t start = size_t(used) + 1;  // one whitespace byte after the scale
    r.values.resize((bytes.size() - start) / 4);
    std::memcpy(r.values.data(), bytes.data() + start, r.values.size() * 4);
    return r;
}

// Camera 10 units from the z = 0 plane, looking straight at it; odd sizes put a pixel centre on
// the axis: pixel (32, 24) of 65×49.
const char* kCamera = "camera { location <0,0,10> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n"
                      "light_source { <10,10,10> color rgb <1,1,1> }\n";

TEST(HdrIo, FloatToHalfRoundsToNearestEven) {
    EXPECT_EQ(rays::floatToHalf(1.0f), 0x3c00);
    EXPECT_EQ(rays::floatToHalf(-2.0f), 0xc000);
    EXPECT_EQ(rays::floatToHalf(0.0f), 0x0000);
    EXPECT_EQ(rays::floatToHalf(65504.0f), 0x7bff);                      // largest half
    EXPECT_EQ(rays::floatToHalf(65520.0f), 0x7c00);                      // rounds up to infinity
    EXPECT_EQ(rays::floatToHalf(std::ldexp(1.0f, -24)), 0x0001);         // smallest subnormal
    EXPECT_EQ(rays::floatToHalf(std::ldexp(1.0f, -25)), 0x0000);         // tie: to even (0)
    EXPECT_EQ(rays::floatToHalf(std::ldexp(3.0f, -25)), 0x0002);         // tie: to even (2)
    EXPECT_EQ(rays::floatToHalf(std::ldexp(1.0f, -14)), 0x0400);         // smallest normal
    EXPECT_EQ(rays::floatToHalf(1.0f + std::ldexp(1.0f, -11)), 0x3c00);  // tie below: even
    EXPECT_EQ(rays::floatToHalf(1.0f + std::ldexp(3.0f, -11)), 0x3c02);  // tie above: even
    EXPECT_EQ(rays::floatToHalf(INFINITY), 0x7c00);
    EXPECT_EQ(rays::floatToHalf(NAN) & 0x7c00, 0x7c00);
}

TEST(HdrIo, PfmIsBottomRowFirstLittleEndian) {
    rays::HdrImage img(2, 2);
    rays::HdrChannel& z = img.add("Z");
    z.values = {1, 2, 3, 4};  // top row 1 2, bottom row 3 4
    const std::vector<uint8_t> bytes = rays::encodePfm(img);
    const std::string header = "Pf\n2 2\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + 16);
    EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + long(header.size())), header);
    float v[4];
    std::memcpy(v, bytes.data() + header.size(), 16);
    EXPECT_EQ(v[0], 3.0f);
    EXPECT_EQ(v[1], 4.0f);
    EXPECT_EQ(v[2], 1.0f);
    EXPECT_EQ(v[3], 2.0f);
    img.add("Y");
    EXPECT_THROW(rays::encodePfm(img), rays::Error);  // 2 channels: not a PFM
}

TEST(HdrIo, FailedWriteLeavesNoFile) {
    TempDir dir;
    rays::HdrImage img(2, 1);
    img.add("R");
    img.add("G");
    const std::string path = (dir.path() / "x.pfm").string();
    rays::test::writeFile(path, "old");
    EXPECT_THROW(rays::writeHdrImage(path, img), rays::Error);  // 2 channels
    EXPECT_EQ(rays::test::readFile(path), "old");
    size_t files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++files;
    EXPECT_EQ(files, 1u);  // no temporary left behind
    EXPECT_THROW(rays::writeHdrImage((dir.path() / "no" / "x.exr").string(), img), rays::Error);
}

TEST(HdrIo, AovListNames) {
    EXPECT_EQ(rays::parseAovList("depth,normal"), unsigned(rays::kAovDepth | rays::kAovNormal));
    EXPECT_EQ(rays::parseAovList("all"), rays::kAovAll);
    EXPECT_EQ(rays::parseAovList("none"), 0u);
    EXPECT_EQ(rays::parseAovList("ObjectId,coverage"), unsigned(rays::kAovObjectId | rays::kAovCoverage));
    EXPECT_THROW(rays::parseAovList("depth,speed"), rays::Error);
}

TEST(HdrIo, PovLinearColorInvertsTheOutputEncoding) {
    for (double gamma : {0.0, 1.0, 2.2})
        for (double c : {0.0, 0.1, 0.5, 0.9}) {
            const double lin = rays::povLinearColor({c, c, c}, gamma).x;
            EXPECT_NEAR(rays::srgbEncode(lin), rays::povOutputColor({c, c, c}, gamma).x, 1e-12) << gamma << " " << c;
        }
    EXPECT_GT(rays::povLinearColor({2, 2, 2}, 1.0).x, 1.9);  // unclamped
}

#if RAYS_TEST_EXR
TEST(HdrIo, ExrChannelsReadBackWithOpenExr) {
    TempDir dir;
    rays::HdrImage img(3, 2);
    img.add("R", true).values = {0.5f, 1.0f, 2.0f, 100.0f, -1.0f, 0.0f};
    img.add("objectId").values = {0, 1, 2, 3, 4, 100000};
    const std::string path = (dir.path() / "x.exr").string();
    rays::writeHdrImage(path, img);
    const ExrRead r = readExr(path);
    ASSERT_EQ(r.width, 3);
    ASSERT_EQ(r.height, 2);
    EXPECT_EQ(r.types.at("R"), Imf::HALF);
    EXPECT_EQ(r.types.at("objectId"), Imf::FLOAT);
    EXPECT_EQ(r.at("R", 2, 0), 2.0f);
    EXPECT_EQ(r.at("R", 0, 1), 100.0f);
    EXPECT_EQ(r.at("R", 1, 1), -1.0f);
    EXPECT_EQ(r.at("objectId", 2, 1), 100000.0f);  // exact: float, not half
}

TEST(HdrIo, RenderExrAovsOfAPlaneAtKnownDistance) {
    TempDir dir;
    rays::test::writeFile(dir.path() / "s.pov",
                          std::string(kCamera) +
                              "plane { <0,0,1>, 0 pigment { color rgb <0.2,0.4,0.6> } finish { ambient 0.2 diffuse 0.6 } }\n");
    const auto r = runRays(dir, {"render", "s.pov", "65", "49", "-o", "out.exr", "--aov", "all", "-q"});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    const ExrRead e = readExr((dir.path() / "out.exr").string());
    ASSERT_EQ(e.width, 65);
    for (const char* ch : {"R", "G", "B", "Z", "N.X", "N.Y", "N.Z", "albedo.R", "albedo.G", "albedo.B", "objectId",
                           "materialId", "coverage"})
        EXPECT_TRUE(e.channels.count(ch)) << ch;
    EXPECT_NEAR(e.at("Z", 32, 24), 10.0f, 1e-4);
    EXPECT_GT(e.at("Z", 0, 0), 10.5f);  // off axis: farther along the ray (ray t, not camera z)
    EXPECT_NEAR(e.at("N.Z", 32, 24), 1.0f, 1e-6);
    EXPECT_NEAR(e.at("albedo.G", 5, 5), 0.4f, 1e-6);
    EXPECT_EQ(e.at("objectId", 32, 24), 0.0f);
    EXPECT_EQ(e.at("coverage", 32, 24), 0.0f);  // no lines asked for
    EXPECT_GT(e.at("R", 32, 24), 0.0f);
    EXPECT_EQ(e.types.at("R"), Imf::FLOAT);
    EXPECT_EQ(e.types.at("Z"), Imf::FLOAT);

    const auto h = runRays(dir, {"render", "s.pov", "65", "49", "-o", "half.exr", "--aov", "depth", "--exr-half", "-q"});
    ASSERT_TRUE(h.ok()) << h.summary() << h.err;
    const ExrRead eh = readExr((dir.path() / "half.exr").string());
    EXPECT_EQ(eh.types.at("R"), Imf::HALF);
    EXPECT_EQ(eh.types.at("Z"), Imf::FLOAT);  // AOVs stay float
    EXPECT_NEAR(eh.at("R", 32, 24), e.at("R", 32, 24), 1e-3);
}

TEST(HdrIo, RenderExrAovsOfASphereWithLines) {
    TempDir dir;
    rays::test::writeFile(dir.path() / "s.pov",
                          std::string(kCamera) + "sphere { <9,9,-40>, 1 pigment { color rgb <0,1,0> } }\n"
                                                 "sphere { <0,0,0>, 3 pigment { color rgb <1,0,0> } }\n");
    const auto r = runRays(dir, {"render", "s.pov", "65", "49", "-o", "out.exr", "--aov",
                                 "depth,normal,objectid,materialid,coverage,edgetype", "--edges", "silhouette", "-q"});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    const ExrRead e = readExr((dir.path() / "out.exr").string());
    EXPECT_FALSE(e.channels.count("albedo.R"));  // not asked for
    EXPECT_NEAR(e.at("Z", 32, 24), 7.0f, 1e-4);   // the sphere's front, 3 in front of the centre
    EXPECT_NEAR(e.at("N.X", 32, 24), 0.0f, 1e-6);
    EXPECT_NEAR(e.at("N.Z", 32, 24), 1.0f, 1e-6);
    EXPECT_EQ(e.at("objectId", 32, 24), 1.0f);  // sceneinfo's Object[1]
    EXPECT_EQ(e.at("materialId", 32, 24), 1.0f);
    EXPECT_EQ(e.at("objectId", 0, 0), -1.0f);   // background
    EXPECT_TRUE(std::isinf(e.at("Z", 0, 0)));
    EXPECT_EQ(e.at("coverage", 32, 24), 0.0f);  // inside the outline
    EXPECT_EQ(e.at("coverage", 0, 0), 0.0f);
    float most = 0;
    int mostX = 0;
    for (int x = 0; x < 65; ++x)
        if (e.at("coverage", x, 24) > most) most = e.at("coverage", x, 24), mostX = x;
    EXPECT_GT(most, 0.5f);  // the outline crosses the middle row
    EXPECT_EQ(e.at("edgeType", mostX, 24), 1.0f);  // kEdgeSilhouette
    EXPECT_EQ(e.at("edgeType", 32, 24), 0.0f);      // no line there
    for (int x = 0; x < 65; ++x) {
        if (e.at("coverage", x, 24) == 0.0f) {
            EXPECT_EQ(e.at("edgeType", x, 24), 0.0f) << x;
        }
    }
}

TEST(HdrIo, EdgeTypeTellsIntersectionsFromOutlines) {
    TempDir dir;
    // Two spheres cutting each other in front of nothing: outline (1) and intersection (4) lines.
    rays::test::writeFile(dir.path() / "s.pov", std::string(kCamera) + "sphere { <-1.2,0,0>, 2 pigment { color rgb 1 } }\n"
                                                                         "sphere { <1.2,0,0>, 2 pigment { color rgb 1 } }\n");
    const auto r = runRays(dir, {"render", "s.pov", "65", "49", "-o", "out.pfm", "--aov", "edgetype", "--edges",
                                 "silhouette,intersection", "--edge-method", "image", "-q"});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    const PfmRead t = readPfm(dir.path() / "out.edgetype.pfm");
    unsigned seen = 0;
    for (float v : t.values) seen |= unsigned(v);
    EXPECT_EQ(seen, 1u | 4u);
}

TEST(HdrIo, PovSceneExrIsLinearAndMatchesThePng) {
    TempDir dir;
    rays::test::writeFile(dir.path() / "s.pov",
                          "#version 3.7;\nglobal_settings { assumed_gamma 2.2 }\n" + std::string(kCamera) +
                              "sphere { <0,0,0>, 3 pigment { color rgb <0.5,0.25,1> } finish { ambient 0.3 } }\n");
    auto r = runRays(dir, {"render", "s.pov", "65", "49", "-o", "out.exr", "--aov", "albedo,materialid", "-q"});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    r = runRays(dir, {"render", "s.pov", "65", "49", "-o", "out.png", "-q"});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    const ExrRead e = readExr((dir.path() / "out.exr").string());
    const rays::Image8 png = rays::readImage((dir.path() / "out.png").string());
    EXPECT_NEAR(e.at("albedo.R", 32, 24), std::pow(0.5, 2.2), 1e-6);  // linear light of the pigment
    EXPECT_NEAR(e.at("albedo.B", 32, 24), 1.0, 1e-6);
    EXPECT_EQ(e.at("materialId", 32, 24), 0.0f);  // the first texture
    int worst = 0;
    for (int y = 0; y < 49; ++y)
        for (int x = 0; x < 65; ++x) {
            const int b = rays::toByte(rays::srgbEncode(std::clamp(double(e.at("G", x, y)), 0.0, 1.0)));
            worst = std::max(worst, std::abs(b - int(png.row(y)[x * 3 + 1])));
        }
    EXPECT_LE(worst, 1);
}
#endif

TEST(HdrIo, RenderPfmAndAovFilesNextToAPng) {
    TempDir dir;
    rays::test::writeFile(dir.path() / "s.pov",
                          std::string(kCamera) + "plane { <0,0,1>, 0 pigment { color rgb <0.2,0.4,0.6> } }\n");
    auto r = runRays(dir, {"render", "s.pov", "65", "49", "-o", "out.png", "--aov", "depth,normal", "-q"});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    EXPECT_TRUE(fs::exists(dir.path() / "out.png"));
    const PfmRead depth = readPfm(dir.path() / "out.depth.pfm");
    EXPECT_EQ(depth.kind, "Pf");
    ASSERT_EQ(depth.values.size(), size_t(65 * 49));
    EXPECT_NEAR(depth.values[size_t(24) * 65 + 32], 10.0f, 1e-4);  // row 24 of 49 is the middle both ways
    const PfmRead normal = readPfm(dir.path() / "out.normal.pfm");
    EXPECT_EQ(normal.kind, "PF");
    EXPECT_NEAR(normal.values[(size_t(24) * 65 + 32) * 3 + 2], 1.0f, 1e-6);
    EXPECT_FALSE(fs::exists(dir.path() / "out.albedo.pfm"));

    r = runRays(dir, {"render", "s.pov", "65", "49", "-o", "c.pfm", "-q"});
    ASSERT_TRUE(r.ok()) << r.summary() << r.err;
    const PfmRead c = readPfm(dir.path() / "c.pfm");
    EXPECT_EQ(c.kind, "PF");
    ASSERT_EQ(c.values.size(), size_t(65 * 49 * 3));
    const rays::Image8 png = rays::readImage((dir.path() / "out.png").string());
    // Course scenes: the PNG holds the traced values as they are (toByte), the PFM the floats.
    EXPECT_EQ(rays::toByte(c.values[(size_t(48 - 3) * 65 + 7) * 3]), png.row(3)[7 * 3]);
}

TEST(HdrIo, ExrWithoutOpenExrSaysSo) {
    if (rays::exrAvailable()) GTEST_SKIP() << "this build has OpenEXR";
    rays::HdrImage img(1, 1);
    img.add("R");
    try {
        rays::encodeExr(img);
        FAIL() << "no error";
    } catch (const rays::Error& e) {
        EXPECT_NE(std::string(e.what()).find("built without OpenEXR"), std::string::npos) << e.what();
    }
}

TEST(HdrIo, BadAovListFailsBeforeWriting) {
    TempDir dir;
    rays::test::writeFile(dir.path() / "s.pov", std::string(kCamera) + "plane { <0,0,1>, 0 }\n");
    const auto r = runRays(dir, {"render", "s.pov", "65", "49", "-o", "out.pfm", "--aov", "depth,speed", "-q"});
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.err.find("unknown AOV 'speed'"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out.pfm"));
    EXPECT_FALSE(fs::exists(dir.path() / "out.depth.pfm"));
}

}}  // namespace RAYS_TEST_UNIT, namespace
