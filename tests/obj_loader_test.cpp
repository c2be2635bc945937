#include "rays/io/obj_loader.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>

#include "rays/error.h"

namespace fs = std::filesystem;
using rays::ObjMesh;

namespace { namespace RAYS_TEST_UNIT {

/// A fresh directory for OBJ/MTL files, removed when the test ends.
class ObjDir {
public:
    ObjDir() {
        static int counter = 0;
        path_ = fs::temp_directory_path() /
                ("rays_obj_loader_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~ObjDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    /// Writes text to name inside the directory and returns its path.
    std::string write(const std::string& name, const std::string& text) const {
        const std::string p = (path_ / name).string();
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    fs::path path_;
};

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const rays::Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected rays::Error";
    return "";
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

const char* const kTriangle =
    "# a triangle\n"
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 0 2 0\n"
    "vt 0 0\n"
    "vt 1 0\n"
    "vt 0 1\n"
    "vn 0 0 1\n"
    "f 1/1/1 2/2/1 3/3/1\n";

TEST(ObjLoader, TriangleWithUvsAndNormals) {
    ObjDir dir;
    const ObjMesh m = rays::loadObj(dir.write("tri.obj", kTriangle));
    ASSERT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.positions[2], rays::Vec3(0, 2, 0));
    ASSERT_EQ(m.normals.size(), 1u);
    EXPECT_EQ(m.normals[0], rays::Vec3(0, 0, 1));
    ASSERT_EQ(m.uvs.size(), 3u);
    EXPECT_EQ(m.uvs[1][0], 1.0);
    EXPECT_EQ(m.uvs[1][1], 0.0);
    ASSERT_EQ(m.faces.size(), 1u);
    EXPECT_EQ(m.faces[0].v, (std::array<int, 3>{0, 1, 2}));
    EXPECT_EQ(m.faces[0].t, (std::array<int, 3>{0, 1, 2}));
    EXPECT_EQ(m.faces[0].n, (std::array<int, 3>{0, 0, 0}));
    ASSERT_EQ(m.faceMaterial.size(), 1u);
    EXPECT_EQ(m.faceMaterial[0], -1);
    EXPECT_TRUE(m.materials.empty());
}

TEST(ObjLoader, MissingNormals) {
    ObjDir dir;
    const ObjMesh m = rays::loadObj(dir.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                                       "f 1/1 2/2 3/3\n"));
    ASSERT_EQ(m.faces.size(), 1u);
    EXPECT_TRUE(m.normals.empty());
    EXPECT_EQ(m.faces[0].n, (std::array<int, 3>{-1, -1, -1}));
    EXPECT_EQ(m.faces[0].t, (std::array<int, 3>{0, 1, 2}));
}

TEST(ObjLoader, MissingUvs) {
    ObjDir dir;
    const ObjMesh m = rays::loadObj(dir.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n"
                                                       "f 3 2 1\n"));
    ASSERT_EQ(m.faces.size(), 2u);
    EXPECT_TRUE(m.uvs.empty());
    EXPECT_EQ(m.faces[0].t, (std::array<int, 3>{-1, -1, -1}));
    EXPECT_EQ(m.faces[0].n, (std::array<int, 3>{0, 0, 0}));
    EXPECT_EQ(m.faces[1].v, (std::array<int, 3>{2, 1, 0}));
    EXPECT_EQ(m.faces[1].n, (std::array<int, 3>{-1, -1, -1}));
    EXPECT_EQ(m.faces[1].t, (std::array<int, 3>{-1, -1, -1}));
}

TEST(ObjLoader, NegativeIndicesAreRelative) {
    ObjDir dir;
    const ObjMesh m = rays::loadObj(dir.write("a.obj",
                                              "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                              "vn 0 0 1\n"
                                              "f -3//-1 -2//-1 -1//-1\n"
                                              "v 5 0 0\nv 6 0 0\nv 5 1 0\n"
                                              "f -3 -2 -1\n"
                                              "f -6 2 -1\n"));
    ASSERT_EQ(m.faces.size(), 3u);
    EXPECT_EQ(m.faces[0].v, (std::array<int, 3>{0, 1, 2}));
    EXPECT_EQ(m.faces[0].n, (std::array<int, 3>{0, 0, 0}));
    EXPECT_EQ(m.faces[1].v, (std::array<int, 3>{3, 4, 5}));
    EXPECT_EQ(m.faces[2].v, (std::array<int, 3>{0, 1, 5}));
}

TEST(ObjLoader, QuadBecomesTwoTriangles) {
    ObjDir dir;
    const ObjMesh m =
        rays::loadObj(dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                            "f 1/1 2/2 3/3 4/4\n"));
    ASSERT_EQ(m.faces.size(), 2u);
    ASSERT_EQ(m.faceMaterial.size(), 2u);
    std::set<int> used;
    double area = 0;
    for (const ObjMesh::Face& f : m.faces) {
        for (int c = 0; c < 3; ++c) {
            used.insert(f.v[size_t(c)]);
            EXPECT_EQ(f.t[size_t(c)], f.v[size_t(c)]);  // uv i belongs to vertex i here
        }
        const rays::Vec3 n = rays::cross(m.positions[size_t(f.v[1])] - m.positions[size_t(f.v[0])],
                                         m.positions[size_t(f.v[2])] - m.positions[size_t(f.v[0])]);
        EXPECT_GT(n.z, 0.0);  // winding kept
        area += 0.5 * rays::length(n);
    }
    EXPECT_EQ(used, (std::set<int>{0, 1, 2, 3}));
    EXPECT_DOUBLE_EQ(area, 1.0);
}

TEST(ObjLoader, PolygonIsTriangulated) {
    ObjDir dir;
    const ObjMesh m = rays::loadObj(dir.write("hex.obj", "v 2 0 0\nv 1 1.7 0\nv -1 1.7 0\nv -2 0 0\nv -1 -1.7 0\n"
                                                         "v 1 -1.7 0\nf 1 2 3 4 5 6\n"));
    EXPECT_EQ(m.faces.size(), 4u);
}

TEST(ObjLoader, MalformedNumberNamesFileAndLine) {
    ObjDir dir;
    const std::string path = dir.write("bad.obj", "# comment\nv 0 0 0\n\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n");
    const std::string msg = messageOf([&] { rays::loadObj(path); });
    EXPECT_TRUE(startsWith(msg, path + ":4:1: error: ")) << msg;
    EXPECT_NE(msg.find("zero"), std::string::npos) << msg;
}

TEST(ObjLoader, MalformedLinesOfEachKind) {
    ObjDir dir;
    const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";  // lines 1-5
    const struct {
        const char* line;
        const char* expect;  // part of the message
    } cases[] = {
        {"v 1 2", "numbers"},
        {"v 1 2 3x", "3x"},
        {"vn 0 0", "numbers"},
        {"vn 0 0 1 0", "numbers"},
        {"vt u v", "'u'"},
        {"vt", "numbers"},
        {"v nan 0 0", "nan"},
        {"f 1 2", "at least 3"},
        {"f 1 2 a", "'a'"},
        {"f 1 2 4", "out of range"},
        {"f 1 2 -4", "out of range"},
        {"f 0 1 2", "start at 1"},
        {"f 1/1/1 2/1/1 3/9/1", "texture coordinate index 9"},
        {"f 1//1 2//1 3//2", "normal index 2"},
        {"f 1/ 2/ 3/", "missing index"},
        {"f 1/1/1/1 2 3", "too many"},
        {"f 1 2 3 # tail", "comment"},
    };
    for (const auto& c : cases) {
        const std::string path = dir.write("bad.obj", head + "\n" + c.line + "\nf 1 2 3\n");
        const std::string msg = messageOf([&] { rays::loadObj(path); });
        EXPECT_TRUE(startsWith(msg, path + ":7:1: error: ")) << c.line << " -> " << msg;
        EXPECT_NE(msg.find(c.expect), std::string::npos) << c.line << " -> " << msg;
    }
}

TEST(ObjLoader, LineNumbersWithCrLfAndCr) {
    ObjDir dir;
    const std::string crlf = dir.write("crlf.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 7\r\n");
    EXPECT_TRUE(startsWith(messageOf([&] { rays::loadObj(crlf); }), crlf + ":4:1: error: "));
    const std::string cr = dir.write("cr.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 7\r");
    EXPECT_TRUE(startsWith(messageOf([&] { rays::loadObj(cr); }), cr + ":4:1: error: "));
    // CRLF files load normally.
    const std::string ok = dir.write("ok.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n");
    EXPECT_EQ(rays::loadObj(ok).faces.size(), 1u);
}

TEST(ObjLoader, ForwardReferenceOutOfRangeIsReportedAtItsLine) {
    ObjDir dir;
    // Positive indices may refer to vertices defined later; too large ones are still caught.
    const std::string ok = dir.write("fwd.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
    EXPECT_EQ(rays::loadObj(ok).faces.size(), 1u);
    const std::string bad = dir.write("fwd_bad.obj", "v 0 0 0\nf 1 2 4\nv 1 0 0\nv 0 1 0\n");
    const std::string msg = messageOf([&] { rays::loadObj(bad); });
    EXPECT_TRUE(startsWith(msg, bad + ":2:1: error: ")) << msg;
}

TEST(ObjLoader, TolerableExtras) {
    ObjDir dir;
    // Vertex colours, w, trailing comments on vertex lines, groups, smoothing, unknown keywords, blank lines.
    const ObjMesh m = rays::loadObj(dir.write("x.obj",
                                              "o thing\n"
                                              "g part\n"
                                              "s 1\n"
                                              "v 0 0 0 1 0 0  # red\n"
                                              "v 1 0 0 1.0\n"
                                              "v +0 1 0\n"
                                              "\t  \n"
                                              "vt 0.5\n"
                                              "vp 0.1 0.2\n"
                                              "f 1/1 2/1 +3/+1\n"));
    EXPECT_EQ(m.faces.size(), 1u);
    EXPECT_EQ(m.positions[0], rays::Vec3(0, 0, 0));
}

TEST(ObjLoader, MissingFileNamesPath) {
    ObjDir dir;
    const std::string path = dir.file("nope.obj");
    const std::string msg = messageOf([&] { rays::loadObj(path); });
    EXPECT_TRUE(startsWith(msg, path + ": error: ")) << msg;
}

TEST(ObjLoader, MtlDiffuseAndTexture) {
    ObjDir dir;
    dir.write("mats.mtl",
              "newmtl red\n"
              "Kd 0.9 0.1 0.2\n"
              "map_Kd tex/red.png\n"
              "\n"
              "newmtl blue\n"
              "Kd 0.1 0.2 0.7\n");
    const std::string path = dir.write("m.obj",
                                       "mtllib mats.mtl\n"
                                       "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                       "f 1 2 3\n"
                                       "usemtl blue\n"
                                       "f 2 4 3\n"
                                       "usemtl red\n"
                                       "f 1 2 4\n");
    const ObjMesh m = rays::loadObj(path);
    ASSERT_EQ(m.materials.size(), 2u);
    ASSERT_EQ(m.faces.size(), 3u);
    ASSERT_EQ(m.faceMaterial.size(), 3u);
    auto byName = [&](const std::string& name) -> const ObjMesh::Material& {
        for (const auto& mat : m.materials)
            if (mat.name == name) return mat;
        throw std::runtime_error("no material " + name);
    };
    const ObjMesh::Material& red = byName("red");
    EXPECT_NEAR(red.diffuse.x, 0.9, 1e-6);
    EXPECT_NEAR(red.diffuse.y, 0.1, 1e-6);
    EXPECT_NEAR(red.diffuse.z, 0.2, 1e-6);
    EXPECT_EQ(red.diffuseTexture, dir.file("tex/red.png"));
    EXPECT_NEAR(byName("blue").diffuse.z, 0.7, 1e-6);
    EXPECT_TRUE(byName("blue").diffuseTexture.empty());

    // Faces come in file order with their materials.
    std::vector<std::string> names;
    for (int idx : m.faceMaterial) names.push_back(idx < 0 ? "-" : m.materials[size_t(idx)].name);
    EXPECT_EQ(names, (std::vector<std::string>{"-", "blue", "red"}));
    EXPECT_EQ(m.faces[1].v, (std::array<int, 3>{1, 3, 2}));
}

TEST(ObjLoader, MissingMtlIsOnlyAWarning) {
    ObjDir dir;
    const ObjMesh m = rays::loadObj(dir.write("m.obj", "mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                       "usemtl red\nf 1 2 3\n"));
    EXPECT_EQ(m.faces.size(), 1u);
    EXPECT_EQ(m.faceMaterial[0], -1);
}

// The shipped model (scenes/models/, gzip-compressed): read through zlib, every face kept.
TEST(ObjLoader, StanfordBunny) {
    const std::string path = RAYS_SOURCE_DIR "/scenes/models/stanford-bunny.obj.gz";
    const ObjMesh m = rays::loadObj(path);
    EXPECT_EQ(m.faces.size(), 69451u);
    EXPECT_EQ(m.positions.size(), 35947u);
    EXPECT_EQ(m.faceMaterial.size(), m.faces.size());
    for (const ObjMesh::Face& f : m.faces)
        for (int v : f.v) ASSERT_TRUE(v >= 0 && v < int(m.positions.size()));
}

// Writes `text` gzip-compressed to `path`.
void writeGzip(const std::string& path, const std::string& text) {
    gzFile f = gzopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    ASSERT_EQ(gzwrite(f, text.data(), unsigned(text.size())), int(text.size()));
    ASSERT_EQ(gzclose(f), Z_OK);
}

TEST(ObjLoader, GzipFileIsDecompressed) {
    ObjDir dir;
    const std::string path = dir.file("quad.obj.gz");
    writeGzip(path, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n");
    const ObjMesh m = rays::loadObj(path);
    EXPECT_EQ(m.faces.size(), 2u);
    EXPECT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(m.uvs.size(), 4u);
}

TEST(ObjLoader, GzipFileErrorsNameTheLine) {
    ObjDir dir;
    const std::string path = dir.file("bad.obj.gz");
    writeGzip(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    const std::string msg = messageOf([&] { rays::loadObj(path); });
    EXPECT_TRUE(startsWith(msg, path + ":4:1: error: ")) << msg;
}

TEST(ObjLoader, MissingGzipFileIsAnError) {
    const std::string msg = messageOf([] { rays::loadObj("/nonexistent/rays-no-such.obj.gz"); });
    EXPECT_NE(msg.find("cannot open OBJ file"), std::string::npos) << msg;
}

TEST(ObjLoader, ReaderErrorKeepsItsLineNumber) {
    ObjDir dir;
    // Not pre-scanned by us: tinyobjloader rejects the zero index of an `l` line and names the line.
    const std::string path = dir.write("l.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 0 1\n");
    const std::string msg = messageOf([&] { rays::loadObj(path); });
    EXPECT_TRUE(startsWith(msg, path + ":5:1: error: ")) << msg;
}

}}  // namespace RAYS_TEST_UNIT, namespace
