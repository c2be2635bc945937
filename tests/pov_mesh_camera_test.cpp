// POV-Ray's mesh_camera read from POV text: which face each pixel's rays start from, where and
// which way, as measured from POV-Ray 3.7.0.10 renders (probe scenes: a plane z = 10 coloured by
// x and y seen through small camera meshes, 16-bit PPM, File_Gamma 1).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/error.h"
#include "rays/pov/load_pov.h"
#include "rays/render/renderer.h"
#include "rays/scene/camera.h"
#include "rays/scene/uv_face_grid.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

Scene loadScene(const std::string& text) {
    ParseOptions o;
    o.warn = [](const std::string&) {};
    o.language.installedIncludeDir.clear();
    return pov::parsePovText("#version 3.7;\n" + text, "scene.pov", ".", o);
}

Camera loadCamera(const std::string& body) { return loadScene("camera { " + body + " }\n").cameras.at(0); }

std::string errorOf(const std::string& body) {
    try {
        loadCamera(body);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// A row of n faces along x, face i centred at x = 10·i (+ dx), looking to +z (POV-Ray's winding).
std::string faces(int n, double dx = 0) {
    std::string s = "mesh { ";
    for (int i = 0; i < n; ++i) {
        const std::string x = std::to_string(10 * i + dx);
        s += "triangle { <" + x + ",1,0>, <" + x + "+1,-1,0>, <" + x + "-1,-1,0> } ";
    }
    return s + "}";
}

// Ray k of pixel (x, y) of a W×H image, y counted from the top row as in an image file.
Ray pixelRay(const Camera& c, int x, int y, int w, int h, int k = 0) {
    return CameraRays(c).meshRay(k, x + 0.5, h - 1 - y + 0.5, w, h);
}

// The x of the face a pixel's ray starts from (its centroid's x is 10·index + dx; the centroid's
// y is −1/3), or −1 when the ray has no face.
double faceX(const Camera& c, int x, int y, int w, int h, int k = 0) {
    const Ray r = pixelRay(c, x, y, w, h, k);
    return CameraRays::missed(r) ? -1 : r.origin.x;
}

TEST(PovMeshCamera, EachPixelTakesTheFaceOfItsNumberTheTopRowRepeated) {
    // POV-Ray 3.7.0.10 (measured, 3×3 and 2×8 images): rows 0 and 1 show faces 0..W−1, row r > 0
    // faces W·(r − 1) onwards; the last row of faces is never shown.
    const Camera c = loadCamera("mesh_camera { 1 0 " + faces(9) + " }");
    ASSERT_EQ(c.projection, Projection::Mesh);
    for (int x = 0; x < 3; ++x) {
        EXPECT_EQ(faceX(c, x, 0, 3, 3), 10 * x);
        EXPECT_EQ(faceX(c, x, 1, 3, 3), 10 * x);
        EXPECT_EQ(faceX(c, x, 2, 3, 3), 10 * (3 + x));
    }
    // The ray starts at the centroid and follows the face's normal: (c − a) × (b − a) for corners
    // a, b, c of triangle { a, b, c } (measured: this winding looks to +z).
    const Ray r = pixelRay(c, 1, 0, 3, 3);
    EXPECT_NEAR(r.origin.y, -1.0 / 3, 1e-6);
    EXPECT_EQ(r.origin.z, 0);
    EXPECT_EQ(r.dir, Vec3(0, 0, 1));
    // A pixel past the last face shoots no ray.
    EXPECT_EQ(faceX(loadCamera("mesh_camera { 1 0 " + faces(4) + " }"), 1, 2, 3, 3), -1);
}

TEST(PovMeshCamera, LocationAndDirectionZMoveAndTurnTheRays) {
    // location's z moves the origin along the (unit) normal, a direction with z < 0 reverses the
    // ray; x and y do nothing; the camera's transformations apply to both first (measured).
    const std::string mc = "mesh_camera { 1 0 mesh { triangle { <0,10,0>, <10,-10,0>, <-10,-10,0> } } } ";
    auto ray = [&](const std::string& rest) { return pixelRay(loadCamera(mc + rest), 0, 0, 1, 1); };
    Ray r = ray("location <5, 3, 0.6>");
    EXPECT_NEAR(r.origin.z, 0.6, 1e-12);
    EXPECT_NEAR(r.origin.x, 0, 1e-6);
    EXPECT_EQ(r.dir, Vec3(0, 0, 1));
    r = ray("location <0, 0, 0.6> direction <1, 0, -1>");
    EXPECT_NEAR(r.origin.z, 0.6, 1e-12);
    EXPECT_EQ(r.dir, Vec3(0, 0, -1));
    EXPECT_EQ(ray("scale -1").dir, Vec3(0, 0, -1));
    EXPECT_EQ(ray("rotate 30*y").dir, Vec3(0, 0, 1));
    EXPECT_EQ(ray("look_at <0, 0, -10>").dir, Vec3(0, 0, -1));
    EXPECT_NEAR(ray("translate <5, 0, 20>").origin.z, 20, 1e-12);
    EXPECT_EQ(ray("direction 0").dir, Vec3(0, 0, 1));  // a zero direction is accepted
}

TEST(PovMeshCamera, MeshTransformsMoveTheFacesAndTurnTheirNormals) {
    // The normal turns as a normal (measured: scale <1,1,-1> looks to −z, scale <-1,1,1> to +z).
    auto ray = [&](const std::string& t) {
        const std::string mesh = faces(1);  // "mesh { ... }": the transformation goes before its '}'
        return pixelRay(loadCamera("mesh_camera { 1 0 " + mesh.substr(0, mesh.size() - 1) + t + " } }"), 0, 0, 1, 1);
    };
    EXPECT_EQ(ray("scale <1,1,-1>").dir, Vec3(0, 0, -1));
    EXPECT_EQ(ray("scale <-1,1,1>").dir, Vec3(0, 0, 1));
    const Ray r = ray("rotate 90*y translate <0, 0, 5>");
    EXPECT_NEAR(r.dir.x, 1, 1e-12);
    EXPECT_NEAR(r.origin.z, 5, 1e-6);
}

TEST(PovMeshCamera, Distribution0TakesRayKFromMeshK) {
    const Camera c = loadCamera("mesh_camera { 2 0 " + faces(6) + " " + faces(4, 1000) + " }");
    EXPECT_EQ(faceX(c, 0, 0, 3, 3, 0), 0);
    EXPECT_EQ(faceX(c, 0, 0, 3, 3, 1), 1000);
    EXPECT_EQ(faceX(c, 0, 2, 3, 3, 1), 1030);
    EXPECT_EQ(faceX(c, 1, 2, 3, 3, 0), 40);
    EXPECT_EQ(faceX(c, 1, 2, 3, 3, 1), -1);  // the second mesh has 4 faces: that ray is not shot
}

TEST(PovMeshCamera, CopiesOfADeclaredMeshShareItsFacesAndKeepTheirOwnPlaces) {
    // POV-Ray's ess-ortho-camera.pov takes 100 translated copies of one declared mesh: its faces
    // are kept once, each copy only its transformation.
    const std::string decl = "#declare M = " + faces(400) + "\n";
    auto copies = [&](int n) {
        std::string s = decl + "camera { mesh_camera { " + std::to_string(n) + " 0 ";
        for (int i = 0; i < n; ++i) s += "mesh { M translate <0, " + std::to_string(i) + ", 0> } ";
        return loadScene(s + "} }\n").cameras.at(0);
    };
    const Camera one = copies(1), many = copies(40);
    EXPECT_LT(many.mesh->memoryBytes(), one.mesh->memoryBytes() + 40 * 512);  // a copy of the faces: 19,200 bytes
    for (int k : {0, 7, 39}) {
        const Ray r = pixelRay(many, 3, 0, 10, 10, k);
        EXPECT_NEAR(r.origin.x, 30, 1e-9) << k;
        EXPECT_NEAR(r.origin.y, k - 1.0 / 3, 1e-9) << k;
        EXPECT_EQ(r.dir, Vec3(0, 0, 1)) << k;
    }
    // Copies under distribution 1 are counted as one list all the same.
    const Camera summed = loadScene("#declare N = " + faces(50) +
                                    "\ncamera { mesh_camera { 1 1 mesh { N } mesh { N translate 1000*x } } }\n")
                              .cameras.at(0);
    EXPECT_NEAR(faceX(summed, 9, 6, 10, 10), 1090, 1e-9);  // face 50 + 9: the copy's face 9
}

TEST(PovMeshCamera, Distribution1CountsTheMeshesAsOneList) {
    const Camera c = loadCamera("mesh_camera { 1 1 " + faces(2) + " " + faces(3, 1000) + " }");
    EXPECT_EQ(faceX(c, 1, 0, 2, 3), 10);
    EXPECT_EQ(faceX(c, 0, 2, 2, 3), 1000);
    EXPECT_EQ(faceX(c, 1, 2, 2, 3), 1010);
    // POV-Ray 3.7.0.10 shoots only the pixel's own face whatever rays_per_pixel says (measured).
    EXPECT_EQ(loadCamera("mesh_camera { 2 1 " + faces(8) + " " + faces(8, 1000) + " }").mesh->raysShot(), 1);
}

TEST(PovMeshCamera, Distribution2SplitsTheImageIntoStrips) {
    // Measured (4×3, 6×4 and 5×2 images, two meshes): mesh m = x / (W / 2) (the last one past the
    // end), its face (W / 2)·row + x with x counted from the image's left edge.
    const Camera c = loadCamera("mesh_camera { 1 2 " + faces(16) + " " + faces(16, 1000) + " }");
    EXPECT_EQ(faceX(c, 1, 0, 4, 3), 10);
    EXPECT_EQ(faceX(c, 2, 0, 4, 3), 1020);
    EXPECT_EQ(faceX(c, 3, 2, 4, 3), 1050);
    EXPECT_EQ(faceX(c, 0, 2, 4, 3), 20);
    EXPECT_EQ(faceX(c, 3, 3, 6, 4), 1090);
    EXPECT_EQ(faceX(c, 4, 0, 5, 2), 1040);
}

TEST(PovMeshCamera, Distribution3StartsAtThePointWithThePixelsUv) {
    // A 20×20 square with uv 0..1 over it: the pixel's uv is (x − ½)/W, 1 − (y + ½)/H in
    // POV-Ray's pixel coordinates (measured on 4×4 and 10×6 images: u = i/W but (W − 1.5)/W in
    // the last column, v = 1 − r/H but 1 − 0.5/H in the top row).
    const std::string square =
        "mesh { triangle { <-10,-10,0>, <-10,10,0>, <10,10,0> uv_vectors <0,0>, <0,1>, <1,1> } "
        "triangle { <-10,-10,0>, <10,10,0>, <10,-10,0> uv_vectors <0,0>, <1,1>, <1,0> } }";
    const Camera c = loadCamera("mesh_camera { 1 3 " + square + " }");
    auto expectAt = [&](int x, int y, int w, int h, double u, double v) {
        SCOPED_TRACE(std::to_string(x) + "," + std::to_string(y));
        const Ray r = pixelRay(c, x, y, w, h);
        EXPECT_NEAR(r.origin.x, -10 + 20 * u, 1e-5);
        EXPECT_NEAR(r.origin.y, -10 + 20 * v, 1e-5);
        EXPECT_EQ(r.dir, Vec3(0, 0, 1));
    };
    expectAt(0, 0, 10, 6, 0.0, 1 - 0.5 / 6);
    expectAt(3, 2, 10, 6, 0.3, 1 - 2.0 / 6);
    expectAt(9, 5, 10, 6, 0.85, 1 - 5.0 / 6);
    expectAt(2, 3, 4, 4, 0.5, 0.25);
    // Outside every face's uvs: no ray (a 1×1 image's only pixel has u = −½).
    EXPECT_TRUE(CameraRays::missed(pixelRay(c, 0, 0, 1, 1)));
    // Edges count in, with no slack for rounding (measured on a 3×3 image: (0, 2/3) is inside the
    // face (0,0), (0,1), (1,0), (1/3, 2/3) outside).
    const Camera half = loadCamera("mesh_camera { 1 3 mesh { triangle { <0,1,0>, <1,-1,0>, <-1,-1,0> "
                                   "uv_vectors <0,0>, <0,1>, <1,0> } } }");
    EXPECT_FALSE(CameraRays::missed(pixelRay(half, 0, 1, 3, 3)));
    EXPECT_TRUE(CameraRays::missed(pixelRay(half, 1, 1, 3, 3)));
    EXPECT_FALSE(CameraRays::missed(pixelRay(half, 1, 2, 3, 3)));
}

TEST(UvFaceGrid, AGridOfFacesHasNoHolesAlongItsEdges) {
    // meshcam_macros.inc's uv cameras: n×n cells of four faces round the cell's centre, uvs as
    // floats; the pixels' uvs i/W, 1 − j/H fall on its edges and corners. Each must find a face
    // (with plain barycentric weights, rounding left holes where POV-Ray has none).
    constexpr int n = 30;
    std::vector<double> uvs;
    auto corner = [&](double u, double v) {
        uvs.push_back(double(float(u)));
        uvs.push_back(double(float(v)));
    };
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            const double u0 = double(c) / n, u1 = double(c + 1) / n, v0 = 1 - double(r) / n, v1 = 1 - double(r + 1) / n;
            const double um = (c + 0.5) / n, vm = 1 - (r + 0.5) / n;
            const double ring[5][2] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}, {u0, v0}};
            for (int k = 0; k < 4; ++k) {
                corner(um, vm);
                corner(ring[k][0], ring[k][1]);
                corner(ring[k + 1][0], ring[k + 1][1]);
            }
        }
    const UvFaceGrid grid(uvs);
    for (const int w : {120, 160, 240, 300})
        for (int i = 0; i < w; ++i)
            for (int j = 1; j <= 90; ++j) {
                double b[3];
                const double u = double(i) / w, v = 1 - double(j) / 90;
                ASSERT_GE(grid.find(u, v, b), 0) << u << " " << v;
                EXPECT_NEAR(b[0] + b[1] + b[2], 1, 1e-12);
            }
}

TEST(PovMeshCamera, SmoothInterpolatesTheCornerNormalsForDistribution3) {
    const std::string tri = "mesh { smooth_triangle { <-10,-10,0>, <-1,0,1>, <-10,10,0>, <-1,0,1>, <10,10,0>, <1,0,1> "
                            "uv_vectors <0,0>, <0,1>, <1,1> } }";
    const Ray flat = pixelRay(loadCamera("mesh_camera { 1 3 " + tri + " }"), 1, 0, 4, 4);
    EXPECT_EQ(flat.dir, Vec3(0, 0, 1));
    const Ray smooth = pixelRay(loadCamera("mesh_camera { 1 3 " + tri + " smooth }"), 1, 0, 4, 4);
    // uv (0.25, 0.875): corner weights 0.125, 0.625, 0.25 → normal ∝ (−0.5, 0, 1).
    EXPECT_NEAR(smooth.dir.x, -0.5 / std::sqrt(1.25), 1e-6);
    EXPECT_NEAR(smooth.dir.z, 1 / std::sqrt(1.25), 1e-6);
    EXPECT_NEAR(smooth.origin.x, -5, 1e-5);
}

TEST(PovMeshCamera, ErrorsAreThoseOfPovRay) {
    EXPECT_NE(errorOf("mesh_camera { 3 0 " + faces(1) + faces(1) + " }").find("must be <= number of meshes"),
              std::string::npos);
    EXPECT_NE(errorOf("mesh_camera { 2 3 " + faces(1) + " }").find("must be 1 for distribution method #2 or #3"),
              std::string::npos);
    EXPECT_NE(errorOf("mesh_camera { 1 0 " + faces(1) + " smooth }").find("smooth can only be used"), std::string::npos);
    EXPECT_NE(errorOf("mesh_camera { 1 4 " + faces(1) + " }").find("unrecognized distribution"), std::string::npos);
    EXPECT_NE(errorOf("mesh_camera { 0 0 " + faces(1) + " }").find("may not be 0"), std::string::npos);
    EXPECT_EQ(errorOf("mesh_camera { 1 0 }").rfind("scene.pov:2:10: error: mesh_camera needs a mesh", 0), 0u);
}

// Rendered: a red plane at z = 10 before a blue background.
Vec3 renderedPixel(const std::string& camera, int x, int w) {
    const Scene scene = loadScene("global_settings { assumed_gamma 1 } background { rgb <0,0,1> }\n"
                                  "plane { z, 10 pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } }\n" +
                                  camera + "\n");
    const Bvh bvh(scene.objects);
    RenderSettings s;
    s.width = w;
    s.height = 1;
    s.threads = 1;
    TraceStats stats;
    return render(scene, bvh, s, stats).at(x, 0);
}

void expectColor(Vec3 got, Vec3 want) {
    EXPECT_NEAR(got.x, want.x, 1e-6);
    EXPECT_NEAR(got.y, want.y, 1e-6);
    EXPECT_NEAR(got.z, want.z, 1e-6);
}

TEST(PovMeshCamera, MaxDistanceStopsCameraRaysAndFacelessPixelsAreBlack) {
    const std::string mesh = faces(1);
    expectColor(renderedPixel("camera { mesh_camera { 1 0 " + mesh + " } }", 0, 2), Vec3(1, 0, 0));
    expectColor(renderedPixel("camera { mesh_camera { 1 0 " + mesh + " } }", 1, 2), Vec3(0, 0, 0));
    // Past max_distance the ray meets nothing: the background (measured).
    expectColor(renderedPixel("camera { mesh_camera { 1 0 5 " + mesh + " } }", 0, 2), Vec3(0, 0, 1));
    expectColor(renderedPixel("camera { mesh_camera { 1 0 11 " + mesh + " } }", 0, 2), Vec3(1, 0, 0));
    // Distribution 0's rays average over the rays shot only: red from the first mesh, nothing
    // from the second (one face) at pixel 1.
    expectColor(renderedPixel("camera { mesh_camera { 2 0 " + faces(2) + " " + mesh + " } }", 1, 2), Vec3(1, 0, 0));
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
