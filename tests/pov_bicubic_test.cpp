// POV-Ray's bicubic_patch (reference 3.4.5.2.1): the triangles and normals against POV-Ray 3.7's
// trace() for several u_steps, v_steps and flatness values; every corner on the Bézier surface.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rays/scene/shapes/bicubic_patch.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

// objects/bezier.pov's patch.
const char* const kPoints =
    "< 0.0, 0.0, 2.0>, < 1.0, 0.0, 0.0>, < 2.0, 0.0, 0.0>, < 3.0, 0.0, -2.0>,"
    "< 0.0, 1.0, 0.0>, < 1.0, 1.0, 0.0>, < 2.0, 1.0, 0.0>, < 3.0, 1.0,  0.0>,"
    "< 0.0, 2.0, 0.0>, < 1.0, 2.0, 0.0>, < 2.0, 2.0, 0.0>, < 3.0, 2.0,  0.0>,"
    "< 0.0, 3.0, 2.0>, < 1.0, 3.0, 0.0>, < 2.0, 3.0, 0.0>, < 3.0, 3.0, -2.0>";

struct Traced {
    const char* items;
    double z[5];  // trace() from <0.37 + 0.55 i, 0.61 + 0.41 i, 10> along −z: the hit's z (povray 3.7.0.10)
};

const Traced kTraced[] = {
    {"type 1", {1.506666667, 0.773333333, 0.04, -0.693333333, -1.426666667}},
    {"type 1 flatness 0 u_steps 1 v_steps 1", {1.266666667, 0.673333333, 0.04, -0.513333333, -1.106666667}},
    {"type 1 flatness 0 u_steps 2 v_steps 2", {0.828697917, 0.254583333, 0.01421875, -0.209895833, -0.577135417}},
    {"type 0 flatness 0 u_steps 2 v_steps 2", {0.828697917, 0.254583333, 0.01421875, -0.209895833, -0.577135417}},
    {"type 1 flatness 0 u_steps 5 v_steps 5", {0.692067439, 0.199638642, 0.007597771, -0.157002061, -0.547971598}},
    {"type 1 flatness 0 u_steps 8 v_steps 8", {0.6907534, 0.198995259, 0.007550242, -0.156050486, -0.547532019}},
    {"type 1 flatness 0.1 u_steps 8 v_steps 8", {0.707316081, 0.215374349, 0.009091797, -0.161297201, -0.550885417}},
    {"type 0 flatness 0.1 u_steps 3 v_steps 3", {0.707316081, 0.215374349, 0.009091797, -0.161297201, -0.550885417}},
    {"type 1 flatness 0.01 u_steps 4 v_steps 4", {0.694188334, 0.201561635, 0.007892456, -0.158441976, -0.549005534}},
    {"type 1 flatness 0 u_steps 3 v_steps 1", {0.834166667, 0.308333333, 0.011875, -0.205833333, -0.624166667}},
};

TEST(PovBicubicPatch, TrianglesMatchPovRayTrace) {
    for (const Traced& c : kTraced) {
        std::vector<std::string> warnings;
        const Scene s = test::buildPov(std::string("bicubic_patch { ") + c.items + " " + kPoints + " }", &warnings);
        ASSERT_EQ(s.objects.size(), 1u) << c.items;
        EXPECT_TRUE(warnings.empty()) << warnings[0];
        for (int i = 0; i < 5; ++i) {
            const Vec3 from{0.37 + i * 0.55, 0.61 + i * 0.41, 10};
            const Hit h = test::shootPov(s, from, {0, 0, -1});
            ASSERT_TRUE(h.valid()) << c.items << " ray " << i;
            EXPECT_NEAR(10 - h.t, c.z[i], 2e-6) << c.items << " ray " << i;  // the mesh keeps floats
        }
    }
}

TEST(PovBicubicPatch, NormalsAreTheSurfacesInterpolated) {
    // u_steps 2 v_steps 2 flatness 0: POV-Ray's normals (its sign is the other side's).
    const Vec3 want[5] = {{-0.532682, -0.498309, -0.68406}, {-0.391683, -0.219174, -0.893615},
                          {-0.260404, -0.013484, -0.965406}, {-0.358368, -0.155464, -0.920545},
                          {-0.49129, -0.45618, -0.741979}};
    const Scene s = test::buildPov(std::string("bicubic_patch { type 1 flatness 0 u_steps 2 v_steps 2 ") + kPoints + " }");
    ASSERT_EQ(s.objects.size(), 1u);
    for (int i = 0; i < 5; ++i) {
        const Hit h = test::shootPov(s, {0.37 + i * 0.55, 0.61 + i * 0.41, 10}, {0, 0, -1});
        ASSERT_TRUE(h.valid());
        EXPECT_GT(std::fabs(dot(h.normal, normalize(want[i]))), 1 - 1e-5) << i;
    }
}

TEST(PovBicubicPatch, UvVectorsWithoutCommas) {
    // portfolio/allobjects.pov writes `uv_vectors <0,0> <1,0> <1,1> <0,1>` before the points.
    const Scene s = test::buildPov(std::string("bicubic_patch { type 1 u_steps 2 v_steps 2 uv_vectors <0,0> <2,0> <2,2> <0,2> ") +
                                   kPoints + " }");
    ASSERT_EQ(s.objects.size(), 1u);
    const Hit h = test::shootPov(s, {0.37, 0.61, 10}, {0, 0, -1});
    ASSERT_TRUE(h.valid());
    EXPECT_NEAR(10 - h.t, 0.828697917, 2e-6);
    ASSERT_TRUE(s.objects[0].mesh->hasUVs());
    EXPECT_FLOAT_EQ(s.objects[0].mesh->uvs[2], 2 * 0.25f);  // the second grid corner: s = 1/4
}

TEST(PovBicubicPatch, CornersLieOnTheBezierSurface) {
    BicubicPatch p;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) p.points[j * 4 + i] = Vec3{double(i), double(j), (i == 1 || j == 2) ? 1.0 : 0.3 * i * j};
    p.uSteps = 3;
    p.vSteps = 2;
    Mesh m;
    tessellateBicubicPatch(p, m);
    EXPECT_EQ(m.indices.size(), size_t(8 * 4 * 2 * 3));
    // The Bézier surface by de Casteljau along rows, then across them.
    auto casteljau = [](std::vector<Vec3> c, double x) {
        while (c.size() > 1) {
            for (size_t k = 0; k + 1 < c.size(); ++k) c[k] = (1 - x) * c[k] + x * c[k + 1];
            c.pop_back();
        }
        return c[0];
    };
    for (size_t v = 0; v < m.positions.size() / 3; ++v) {
        const Vec3 q{m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
        const double s = m.uvs[2 * v], t = m.uvs[2 * v + 1];  // default uv_vectors: uv = (s, t)
        std::vector<Vec3> col;
        for (int j = 0; j < 4; ++j) col.push_back(casteljau({p.points[j * 4], p.points[j * 4 + 1], p.points[j * 4 + 2], p.points[j * 4 + 3]}, s));
        EXPECT_LT(length(q - casteljau(col, t)), 1e-6);
    }
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
