// Indexed meshes: POV-Ray mesh and mesh2, obj_mesh, uv mapping and smooth normals.
#include <gtest/gtest.h>

#include <fstream>

#include "rays/accel/bvh.h"
#include "rays/error.h"
#include "rays/io/image_io.h"
#include "rays/io/scene_parser.h"
#include "rays/pov/load_pov.h"
#include "rays/render/renderer.h"
#include "support/error_text.h"
#include "support/process.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

const std::string kCam = "camera { location <0.5, 0.5, 10> up <0, 0.1, 0> right <0.1, 0, 0> look_at <0.5, 0.5, 0> }\n";

Scene parse(const std::string& text, const std::string& file = "t.pov") {
    ParseOptions opt;
    opt.warn = [](const std::string&) {};
    return parseScene(text, file, opt);
}

std::string errorOf(const std::string& text) {
    return rays::test::errorText([&] { parse(text); });
}

ImageF flatRender(const Scene& scene, int w, int h) {
    const Bvh bvh(scene.objects);
    RenderSettings s;
    s.width = w;
    s.height = h;
    s.shading = ShadingModel::Flat;
    TraceStats st;
    return render(scene, bvh, s, st);
}

TEST(Mesh, PovrayMeshAndMesh2AreOneIndexedObject) {
    const Scene a = parse(kCam +
                          "mesh { triangle { <0,0,0>, <1,0,0>, <1,1,0> } triangle { <0,0,0>, <1,1,0>, <0,1,0> } "
                          "pigment { color rgb <1,0,0> } }\n");
    ASSERT_EQ(a.objects.size(), 1u);
    EXPECT_EQ(a.objects[0].type, ShapeType::Mesh);
    EXPECT_EQ(a.objects[0].mesh->triangleCount(), 2u);
    const Scene b = parse(kCam +
                          "mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> } "
                          "face_indices { 2, <0,1,2>, <0,2,3> } pigment { color rgb <0,1,0> } }\n");
    ASSERT_EQ(b.objects.size(), 1u);
    EXPECT_EQ(b.objects[0].mesh->triangleCount(), 2u);
    EXPECT_EQ(b.objects[0].mesh->positions.size(), 12u);  // shared vertices stored once
    // Both cover the unit square the camera looks at.
    const ImageF ia = flatRender(a, 4, 4), ib = flatRender(b, 4, 4);
    for (const Vec3& c : ia.pixels) EXPECT_EQ(c, Vec3(1, 0, 0));
    for (const Vec3& c : ib.pixels) EXPECT_EQ(c, Vec3(0, 1, 0));
}

TEST(Mesh, CopyOfADeclaredMeshDrawsItWithItsModifiers) {
    // `mesh { M ... }` draws the declared mesh M (as POV-Ray 3.7 does, measured); it drew nothing.
    ParseOptions opt;
    opt.language.installedIncludeDir.clear();
    const Scene s = pov::parsePovText("#version 3.7;\n" + kCam +
                          "#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <1,1,0> } }\n"
                          "#declare M2 = mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <1,1,0> } face_indices { 1, <0,1,2> } }\n"
                          "mesh { M translate <0, 0, 2> }\nmesh2 { M2 scale 2 }\n",
                                      "t.pov", ".", opt);
    ASSERT_EQ(s.objects.size(), 2u);
    for (const Object& o : s.objects) {
        EXPECT_EQ(o.type, ShapeType::Mesh);
        EXPECT_EQ(o.mesh->triangleCount(), 1u);
    }
    EXPECT_EQ(s.objects[0].toObject.point(Vec3(0, 0, 2)), Vec3(0, 0, 0));
    EXPECT_EQ(s.objects[1].toObject.point(Vec3(2, 2, 2)), Vec3(1, 1, 1));
}

TEST(Mesh, Mesh2UvMappingLandsOnKnownTexels) {
    rays::test::TempDir dir;
    Image8 tex(2, 2, 3);  // top-left red, top-right green, bottom-left blue, bottom-right white
    const uint8_t px[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c) tex.pixels[size_t(i * 3 + c)] = px[i][c];
    writeImage((dir.path() / "t.png").string(), tex);
    // uv = position: the square shows the texture once, v up.
    const Scene s = parse(kCam +
                              "mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> } "
                              "uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> } "
                              "face_indices { 2, <0,1,2>, <0,2,3> } "
                              "pigment { uv_mapping image_map { png \"t.png\" } } }\n",
                          (dir.path() / "s.pov").string());
    const ImageF img = flatRender(s, 4, 4);
    EXPECT_EQ(img.at(0, 0), Vec3(1, 0, 0));  // top-left of the image: top-left texel
    EXPECT_EQ(img.at(3, 0), Vec3(0, 1, 0));
    EXPECT_EQ(img.at(0, 3), Vec3(0, 0, 1));
    EXPECT_EQ(img.at(3, 3), Vec3(1, 1, 1));
}

TEST(Mesh, SmoothTriangleNormalsInterpolate) {
    const Scene s = parse(kCam +
                          "mesh { smooth_triangle { <0,0,0>, <-1,0,1>, <1,0,0>, <1,0,1>, <0,1,0>, <0,0,1> } }\n");
    const Bvh bvh(s.objects);
    const Hit h = bvh.closest(s.objects, Ray{{0.5, 0.0001, 5}, {0, 0, -1}}, 1e-6, kInfinity);
    ASSERT_TRUE(h.valid());
    // Halfway along the bottom edge: the average of (−1,0,1) and (1,0,1) normalised.
    EXPECT_NEAR(h.normal.x, 0, 1e-3);
    EXPECT_NEAR(h.normal.z, 1, 1e-3);
    EXPECT_NEAR(h.geomNormal.z, 1, 1e-9);
}

TEST(Mesh, Mesh2Errors) {
    EXPECT_NE(errorOf(kCam + "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0> } face_indices { 1, <0,1,2> } }")
                  .find("vertex_vectors has fewer items than its count 3"), std::string::npos);
    EXPECT_NE(errorOf(kCam + "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,5> } }")
                  .find("t.pov:2:1: error: mesh vertex index 5 is out of range"), std::string::npos);
    EXPECT_NE(errorOf(kCam + "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,-2> } }")
                  .find("mesh2 indices must be whole numbers"), std::string::npos);
    EXPECT_NE(errorOf(kCam + "mesh { }").find("mesh has no triangles"), std::string::npos);
}

TEST(Mesh, ObjMeshLoadsAndMissingFileNamesTheSceneLine) {
    rays::test::TempDir dir;
    std::ofstream(dir.path() / "sq.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    const Scene s = parse(kCam + "obj_mesh { \"sq.obj\" pigment { color rgb <0, 0, 1> } }\n", (dir.path() / "s.pov").string());
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].mesh->triangleCount(), 2u);  // the quad split in two
    for (const Vec3& c : flatRender(s, 4, 4).pixels) EXPECT_EQ(c, Vec3(0, 0, 1));
    try {
        parse(kCam + "obj_mesh {\n  \"missing.obj\" }\n", (dir.path() / "s.pov").string());
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind((dir.path() / "s.pov").string() + ":3:3: error: cannot open OBJ file", 0), 0u)
            << e.what();
    }
}

TEST(Mesh, TransformedMeshIntersectsLikeTransformedTriangles) {
    // The same two triangles as a mesh and as separate triangle objects, under one transform.
    const std::string xf = " rotate <30, 40, 10> scale <2, 1, 0.5> translate <0.3, 0.2, 0> ";
    const Scene a = parse(kCam + "mesh { triangle { <0,0,0>, <1,0,0>, <1,1,0> } triangle { <0,0,0>, <1,1,0>, <0,1,0.5> }" + xf + "}\n");
    const Scene b = parse(kCam + "triangle { <0,0,0>, <1,0,0>, <1,1,0>" + xf + "}\ntriangle { <0,0,0>, <1,1,0>, <0,1,0.5>" + xf + "}\n");
    const Bvh ba(a.objects), bb(b.objects);
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
        const Ray r{{-1 + i % 20 * 0.15, -1 + i / 20 * 0.15, 5}, normalize(Vec3{0.05, -0.02, -1})};
        const Hit ha = ba.closest(a.objects, r, 1e-6, kInfinity), hb = bb.closest(b.objects, r, 1e-6, kInfinity);
        ASSERT_EQ(ha.valid(), hb.valid()) << i;
        if (!ha.valid()) continue;
        ++hits;
        EXPECT_NEAR(ha.t, hb.t, 1e-4);
        EXPECT_NEAR(std::fabs(dot(ha.geomNormal, hb.geomNormal)), 1.0, 1e-6);
    }
    EXPECT_GT(hits, 30);
}

}}  // namespace RAYS_TEST_UNIT, namespace
