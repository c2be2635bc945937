// Layered and patterned textures lit as POV-Ray 3.7 lights them: each layer with its own pigment,
// normal and finish, lower layers' light filtered by the layers above, reflections per layer, the
// transmitted ray through all layers; a texture map's textures shaded in full and blended. The
// expected values were measured with povray 3.7.0.10 on these scenes (4×4, 16-bit PPM, sRGB
// decoded, assumed_gamma 1, centre pixel: tests/data/povray/shading/measure_layers.py); they hold
// to 1e-4 (povray clips at 1, Rays' working colour does not: the cases stay below 1 or say so).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/error.h"
#include "rays/render/tracer.h"
#include "rays/scene/shapes/shape_data.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

constexpr double kMeasured = 1e-4;

Scene load(const std::string& body) {
    return test::loadPov(body, "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n").scene;
}

// The centre pixel's ray of povray's 4×4 render through `camera { orthographic location -3*z
// look_at 0 right x up y }`.
Vec3 centre(const Scene& s) {
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    return Tracer(s, bvh, rs).tracePrimary(Ray{{0.125, -0.125, -3}, {0, 0, 1}}, ctx);
}

void expectColor(Vec3 got, Vec3 want, double tol = kMeasured) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

// A plane facing the camera, lit straight on by a parallel light (N·L = 1), before a background.
Vec3 plane(const std::string& textures, const std::string& background = "rgb 0") {
    return centre(load("background { " + background + " }\n"
                       "light_source { <0,0,-10>, rgb 1 parallel point_at 0 }\n"
                       "plane { -z, 0 " + textures + " }\n"));
}

const std::string kFilterLayer = "texture { pigment { rgbf <1,.5,.25,.5> } finish { ambient 0 diffuse 0 } }";

TEST(PovLayeredTexture, LowerLayersLightIsFilteredByTheLayersAbove) {
    // A white diffuse .8 layer under a filtering layer: 0.8·filter·C.
    expectColor(plane("texture { pigment { rgb 1 } finish { ambient 0 diffuse .8 } } " + kFilterLayer), {0.4, 0.2, 0.1});
    // Transmit lets the light through untinted.
    expectColor(plane("texture { pigment { rgb 1 } finish { ambient 0 diffuse .8 } } "
                      "texture { pigment { rgbt <1,.5,.25,.5> } finish { ambient 0 diffuse 0 } }"),
                {0.4, 0.4, 0.4});
    // The upper layer's own diffuse, weighted by its opacity, adds to it.
    expectColor(plane("texture { pigment { rgb 1 } finish { ambient 0 diffuse .8 } } "
                      "texture { pigment { rgbf <1,.5,.25,.5> } finish { ambient 0 diffuse .5 } }"),
                {0.65, 0.325, 0.1625});
}

TEST(PovLayeredTexture, EachLayerHasItsOwnFinish) {
    // A phong layer over a dull one: the highlight is the top layer's, not weighted by its opacity.
    expectColor(plane("texture { pigment { rgb 1 } finish { ambient 0 diffuse 0 } } "
                      "texture { pigment { rgbf <1,.5,.25,.5> } finish { ambient 0 diffuse 0 phong .6 } }"),
                {0.6, 0.6, 0.6});
    // A phong bottom layer: its highlight is filtered by the layer above.
    expectColor(plane("texture { pigment { rgb 1 } finish { ambient 0 diffuse 0 phong 1 } } " + kFilterLayer),
                {0.5, 0.25, 0.125});
    // Ambient per layer, three layers: filters multiply on the way down.
    expectColor(plane("texture { pigment { rgb <.2,.4,.8> } finish { ambient 1 diffuse 0 } } "
                      "texture { pigment { rgbf <1,.5,.25,.5> } finish { ambient 1 diffuse 0 } } "
                      "texture { pigment { rgbt <.5,1,.5,.6> } finish { ambient 1 diffuse 0 } }"),
                {0.56, 0.61, 0.335});
    // Filter and transmit together: opacity 1 − f − t, through f·C + t.
    expectColor(plane("texture { pigment { rgb <.2,.4,.8> } finish { ambient 1 diffuse 0 } } "
                      "texture { pigment { rgbft <1,.5,.25,.3,.2> } finish { ambient .5 diffuse 0 } }"),
                {0.35, 0.265, 0.2825});
}

TEST(PovLayeredTexture, EachLayerHasItsOwnNormal) {
    // normal { gradient x 1 } tilts by atan(2/15). On the bottom layer: its diffuse tilts, the top's
    // phong does not; on the top layer: the reverse. Measured .54780 and .46022.
    const double tilt = std::atan(2.0 / 15.0);
    expectColor(plane("texture { pigment { rgb 1 } normal { gradient x 1 } finish { ambient 0 diffuse .5 } } "
                      "texture { pigment { rgbt <1,1,1,.5> } finish { ambient 0 diffuse 0 phong .3 phong_size 10 } }"),
                Vec3(0.25 * std::cos(tilt) + 0.3));
    expectColor(plane("texture { pigment { rgb 1 } finish { ambient 0 diffuse .5 } } "
                      "texture { pigment { rgbt <1,1,1,.5> } normal { gradient x 1 } "
                      "finish { ambient 0 diffuse 0 phong .3 phong_size 10 } }"),
                Vec3(0.25 + 0.3 * std::pow(std::cos(2 * tilt), 10)));
}

TEST(PovLayeredTexture, ReflectionsPerLayerAndTheTransmittedRayThroughAll) {
    // What all layers let through goes on to the background: .5·(f·C) of white.
    expectColor(plane("texture { pigment { rgbt <.2,.4,.8,.5> } finish { ambient 1 diffuse 0 } } "
                      "texture { pigment { rgbf <1,.5,.25,.5> } finish { ambient 1 diffuse 0 } }",
                      "rgb 1"),
                {0.8, 0.425, 0.2375});
    // Each layer reflects with its own amount, the lower one unfiltered by the upper (measured).
    expectColor(plane("texture { pigment { rgb .5 } finish { ambient 1 diffuse 0 reflection .3 } } "
                      "texture { pigment { rgbf <1,.5,.25,.5> } finish { ambient 0 diffuse 0 reflection .2 } }",
                      "rgb <1,.8,.6>"),
                {0.75, 0.525, 0.3625});
    // But a lower layer's reflected ray is traced only when max(R)·grey(what lies above) reaches
    // adc_bailout: transmit .02 lets the bottom's reflection through, .01 does not.
    const std::string bottom = "texture { pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection .3 } } ";
    expectColor(plane(bottom + "texture { pigment { rgbt <1,.5,.25,.02> } finish { ambient 0 diffuse 0 } }",
                      "rgb <1,.8,.6>"),
                {0.3, 0.24, 0.18}, 2e-3);  // plus the top's own .98·C·0 and .02·background·0
    expectColor(plane(bottom + "texture { pigment { rgbt <1,.5,.25,.01> } finish { ambient 0 diffuse 0 } }",
                      "rgb <1,.8,.6>"),
                {0, 0, 0});
}

TEST(PovLayeredTexture, ConserveEnergyTakesALayersReflectionFromWhatItLetsThrough) {
    // Top: reflection .4 with conserve_energy lets through (1 − .4)·f·C: the bottom's ambient
    // .1 becomes .06 (measured .14000 .22000 .29999).
    expectColor(plane("texture { pigment { rgb <.2,.4,.8> } finish { ambient 1 diffuse 0 } } "
                      "texture { pigment { rgbf <1,.5,.25,.5> } finish { ambient 0 diffuse 0 reflection .4 conserve_energy } }",
                      "rgb <.2,.4,.6>"),
                {0.14, 0.22, 0.30});
    // Bottom: its transmitted share (1 − .4)·.5 of what the top lets through reaches the
    // background (measured .16000 .23999 .31251).
    expectColor(plane("texture { pigment { rgbt <.2,.4,.8,.5> } finish { ambient 1 diffuse 0 reflection .4 conserve_energy } } "
                      "texture { pigment { rgbf <1,.5,.25,.5> } finish { ambient 0 diffuse 0 } }",
                      "rgb <.2,.4,.6>"),
                {0.16, 0.24, 0.3125});
}

TEST(PovLayeredTexture, ShadowsAreTintedByEveryLayer) {
    // A pane hidden from the camera (no_image) between the light and a white floor: each of its two
    // surfaces tints by the product of its layers' filter·C + transmit.
    const Vec3 c = plane("pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
                         "box { <-5,-5,-2>, <5,5,-1.5> texture { pigment { rgbt <.2,.4,.8,.5> } } "
                         "texture { pigment { rgbf <1,.5,.25,.5> } } no_image");
    expectColor(c, {0.0625, 0.015625, 0.00390625});
}

TEST(PovLayeredTexture, LayersStartFromTheDefaultTexture) {
    // A layer without a finish has the default finish (ambient .1), not the layer below's (no light).
    expectColor(centre(load("plane { -z, 0 texture { pigment { rgb <.2,.4,.8> } finish { ambient 1 diffuse 0 } } "
                            "texture { pigment { rgbf <1,.5,.25,.5> } } }\n")),
                {0.15, 0.125, 0.1125});
    // ... or #default's; and a finish after a declared layered texture changes its top layer.
    const Vec3 want{0.35, 0.225, 0.1625};
    expectColor(centre(load("#default { finish { ambient .5 diffuse 0 } }\n"
                            "plane { -z, 0 texture { pigment { rgb <.2,.4,.8> } finish { ambient 1 diffuse 0 } } "
                            "texture { pigment { rgbf <1,.5,.25,.5> } } }\n")),
                want);
    expectColor(centre(load("#declare T = texture { pigment { rgb <.2,.4,.8> } finish { ambient 1 diffuse 0 } }\n"
                            "  texture { pigment { rgbf <1,.5,.25,.5> } finish { ambient 0 diffuse 0 } }\n"
                            "plane { -z, 0 texture { T finish { ambient .5 } } }\n")),
                want);
}

// Two textures with different finishes: A dull with a phong highlight, B filtering and reflecting.
const std::string kA = "pigment { rgb <.2,.4,.6> } finish { ambient 0 diffuse .5 phong .2 }";
const std::string kB = "pigment { rgbf <1,.5,.25,.6> } finish { ambient 1 diffuse 0 reflection .3 }";
const Vec3 kShadeA{0.3, 0.4, 0.5};         // .5·C + phong .2
const Vec3 kShadeB{1.3, 0.68, 0.37};  // .4·C + .3·bg + .6·C·bg with bg <1,.8,.6> (povray: 1 (clipped), .68001, .36999)

TEST(PovPatternedTexture, CheckerTexturesKeepTheirFinishes) {
    const std::string checker = "texture { checker texture { " + kA + " } texture { " + kB + " } ";
    const Vec3 b = plane(checker + "}", "rgb <1,.8,.6>");
    expectColor({std::min(b.x, 1.0), b.y, b.z}, {1.0, 0.68001, 0.36999});
    expectColor(plane(checker + "translate y }", "rgb <1,.8,.6>"), kShadeA);
}

TEST(PovPatternedTexture, TextureMapsBlendWholeTextures) {
    // gradient x at the centre pixel (x = .125) moved by .3 and .7: values .825 and .425, so
    // .175·A + .825·B and .575·A + .425·B of the fully shaded textures (measured g, b: .77101
    // .53275 and .97899 .90476 with A's phong 1; here phong .2, computed the same way).
    for (const double shift : {0.3, 0.7}) {
        SCOPED_TRACE(shift);
        const double v = std::fmod(0.125 - shift + 1, 1.0);
        const Vec3 got = plane("texture { gradient x texture_map { [0 " + kA + "] [1 " + kB + "] } translate " +
                                   std::to_string(shift) + "*x }",
                               "rgb <1,.8,.6>");
        expectColor(got, (1 - v) * kShadeA + v * kShadeB, 1e-3);
    }
}

TEST(PovPatternedTexture, AverageWeighsWholeTextures) {
    // T2 reflects the background: (0,0,.5) + .5·(.2,.4,.6). Entries without a weight weigh 1.
    const std::string t1 = "pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 }";
    const std::string t2 = "pigment { rgb <0,0,1> } finish { ambient .5 diffuse 0 reflection .5 }";
    expectColor(plane("texture { average texture_map { [" + t1 + "] [" + t2 + "] } }", "rgb <.2,.4,.6>"),
                {0.55, 0.1, 0.4});  // measured .55000 .10000 .40000
    expectColor(plane("texture { average texture_map { [3 " + t1 + "] [1 " + t2 + "] } }", "rgb <.2,.4,.6>"),
                {0.775, 0.05, 0.2});  // measured .77501 .05000 .20001
}

TEST(PovPatternedTexture, ALayeredTextureInACheckerKeepsItsLayers) {
    // The centre pixel shows the checker's first texture once moved by y: the declared layers,
    // each with ambient 1 (measured .60001 .35001 .22500).
    expectColor(centre(load("#declare TL = texture { pigment { rgb <.2,.4,.8> } finish { ambient 1 diffuse 0 } }\n"
                            "  texture { pigment { rgbf <1,.5,.25,.5> } finish { ambient 1 diffuse 0 } }\n"
                            "plane { -z, 0 texture { checker texture { TL } "
                            "texture { pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } } translate y } }\n")),
                {0.6, 0.35, 0.225});
}

TEST(PovPatternedTexture, PlainTexturesStayPlain) {
    // Only layered and patterned textures go to Scene::povTextures; a plain one keeps the plain path.
    const Scene s = load("plane { -z, 0 texture { pigment { checker rgb 1 rgb 0 } finish { phong 1 } } }\n");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.povSurfaces[size_t(s.objects[0].material.pov)].texture, -1);
    EXPECT_TRUE(s.povTextures.nodes.empty());
}

TEST(PovPatternedTexture, TexturesNestedBeyond4096AreDrawnAsTheirMix) {
    // Each level doubles the textures: 2^13 = 8192 are too many to keep apart; the object's look
    // is then the pattern's mix of pigments (noted), not a table of 8192 textures.
    std::string text = "#declare T0 = texture { pigment { rgb 1 } }\n";
    for (int i = 1; i <= 13; ++i)
        text += "#declare T" + std::to_string(i) + " = texture { checker texture { T" + std::to_string(i - 1) +
                " } texture { T" + std::to_string(i - 1) + " } }\n";
    const test::PovLoaded l =
        test::loadPov(text + "plane { -z, 0 texture { T13 } }\n", "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n");
    ASSERT_EQ(l.warnings.size(), 1u);
    EXPECT_NE(l.warnings[0].find("more than 4096 textures"), std::string::npos) << l.warnings[0];
    EXPECT_EQ(l.scene.povSurfaces[size_t(l.scene.objects[0].material.pov)].texture, -1);
    // 12 levels (4096 textures) are kept.
    const Scene kept = load(text + "plane { -z, 0 texture { T12 } }\n");
    const int node = kept.povSurfaces[size_t(kept.objects[0].material.pov)].texture;
    ASSERT_GE(node, 0);
    EXPECT_EQ(kept.povTextures.layers.size(), 4096u);
}

TEST(PovInteriorTexture, TheInnerSideHasItsOwnTexture) {
    // A sphere's inner side, seen through a clipped cap or through its transmitting outer side
    // (measured 1 .7 0 and .67302 .48843 .34607); from outside the outer texture alone.
    auto sphere = [](const std::string& pigment, const std::string& more) {
        return centre(load("background { rgb <.2,.4,.6> }\n"
                           "light_source { <0,0,-10>, rgb 1 parallel point_at 0 }\n"
                           "sphere { 0, 1 texture { pigment { " + pigment + " } finish { ambient .2 diffuse .5 } } "
                           "interior_texture { pigment { rgb <1,.7,0> } finish { ambient 1 diffuse 0 } } " + more + " }\n"));
    };
    expectColor(sphere("rgb <.5,.4,1>", "clipped_by { plane { z, -.5 inverse } }"), {1.0, 0.7, 0.0});
    expectColor(sphere("rgbt <.5,.4,1,.5>", ""), {0.67302, 0.48843, 0.34607}, 1e-3);
    expectColor(sphere("rgb <.5,.4,1>", ""), {0.34607, 0.27685, 0.69213}, 1e-3);
}

// A triangle's or mesh's outer side is the one its winding's normal points away from (POV-Ray 3.7,
// measured: triangle { <-1,-1,0>, <1,-1,0>, <1,1,0> } seen from -z shows its texture, with its
// corners in the other order its interior_texture; the same for mesh and mesh2; a polygon and a
// disc follow their normals as solids do).
TEST(PovInteriorTexture, TrianglesShowTheirOuterSideAwayFromTheirNormal) {
    const std::string looks = " texture { pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } }"
                              " interior_texture { pigment { rgb <0,0,1> } finish { ambient 1 diffuse 0 } }";
    auto seen = [&](const std::string& object) { return centre(load(object + "\n")); };
    expectColor(seen("triangle { <-1,-1,0>, <1,-1,0>, <1,1,0>" + looks + " }"), {1, 0, 0});
    expectColor(seen("triangle { <-1,-1,0>, <1,1,0>, <1,-1,0>" + looks + " }"), {0, 0, 1});
    expectColor(seen("mesh { triangle { <-1,-1,0>, <1,-1,0>, <1,1,0> }" + looks + " }"), {1, 0, 0});
    expectColor(seen("mesh2 { vertex_vectors { 3, <-1,-1,0>, <1,-1,0>, <1,1,0> } face_indices { 1, <0,1,2> }" + looks + " }"),
                {1, 0, 0});
    expectColor(seen("polygon { 4, <-1,-1>, <1,-1>, <1,1>, <-1,-1>" + looks + " }"), {0, 0, 1});
    expectColor(seen("disc { 0, -z, 2" + looks + " }"), {1, 0, 0});
}

// A smooth triangle (its three normals not all the same) shows its outer side where its normals,
// interpolated at the hit, point towards the viewer, whatever its winding (POV-Ray 3.7, measured
// on mesh2s of one and two faces and on smooth_triangle; meshmaker.inc's MSM meshes, whose faces
// alternate their windings, show one side throughout). Three equal normals leave it flat.
TEST(PovInteriorTexture, SmoothTrianglesShowTheSideTheirNormalsFace) {
    const std::string looks = " texture { pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } }"
                              " interior_texture { pigment { rgb <0,0,1> } finish { ambient 1 diffuse 0 } }";
    auto seen = [&](const std::string& object) { return centre(load(object + "\n")); };
    const std::string toViewer = "<0.1,0,-1>, <0,0.1,-1>, <0,0,-1>", away = "<0.1,0,1>, <0,0.1,1>, <0,0,1>";
    for (const char* faces : {"<0,1,2>", "<0,2,1>"}) {
        const std::string mesh = "mesh2 { vertex_vectors { 3, <-1,-1,0>, <1,-1,0>, <1,1,0> } normal_vectors { 3, ";
        expectColor(seen(mesh + toViewer + " } face_indices { 1, " + faces + " }" + looks + " }"), {1, 0, 0});
        expectColor(seen(mesh + away + " } face_indices { 1, " + faces + " }" + looks + " }"), {0, 0, 1});
    }
    // Normals interpolated at the hit decide, each made a unit vector first: <0.1,0,3> at the
    // first corner is outweighed at the centre by the two pointing at the viewer.
    expectColor(seen("mesh2 { vertex_vectors { 3, <-1,-1,0>, <1,-1,0>, <1,1,0> } normal_vectors { 3, "
                     "<0.1,0,3>, <0,0.1,-1>, <0,0,-1> } face_indices { 1, <0,1,2> }" + looks + " }"),
                {1, 0, 0});
    expectColor(seen("smooth_triangle { <-1,-1,0>, <0.1,0,-1>, <1,1,0>, <0,0.1,-1>, <1,-1,0>, <0,0,-1>" + looks + " }"),
                {1, 0, 0});
    expectColor(seen("mesh { smooth_triangle { <-1,-1,0>, <0.1,0,1>, <1,-1,0>, <0,0.1,1>, <1,1,0>, <0,0,1> }" + looks + " }"),
                {0, 0, 1});
    // interior_texture written before texture keeps its side (POV-Ray 3.7, measured; meshmaker's
    // templates write them in that order).
    expectColor(seen("mesh2 { vertex_vectors { 3, <-1,-1,0>, <1,-1,0>, <1,1,0> } normal_vectors { 3, " + away +
                     " } face_indices { 1, <0,1,2> }"
                     " interior_texture { pigment { rgb <0,0,1> } finish { ambient 1 diffuse 0 } }"
                     " texture { pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } } }"),
                {0, 0, 1});
    expectColor(seen("sphere { 0, 1 interior_texture { pigment { rgb <0,0,1> } finish { ambient 1 diffuse 0 } }"
                     " texture { pigment { rgbt <1,0,0,1> } finish { ambient 1 diffuse 0 } } }"),
                {0, 0, 1});
    // Equal normals: flat, the winding decides.
    expectColor(seen("mesh2 { vertex_vectors { 3, <-1,-1,0>, <1,-1,0>, <1,1,0> } normal_vectors { 3, -z, -z, -z } "
                     "face_indices { 1, <0,2,1> }" + looks + " }"),
                {0, 0, 1});
}

TEST(PovMeshTextureList, OneTextureEveryFaceNamesDrawsTheMesh) {
    // .8·C + phong .2 (measured 1 .60001 .20001), whatever the mesh's own texture; a face
    // without an index keeps the mesh's own texture.
    const std::string mesh = "mesh2 { vertex_vectors { 3, <-2,-2,0>, <2,-2,0>, <0,3,0> } "
                             "texture_list { 1, texture { pigment { rgb <1,.5,0> } finish { ambient .5 diffuse .3 phong .2 } } } ";
    expectColor(plane("pigment { rgb 0 } }\n" + mesh + "face_indices { 1, <0,1,2>, 0 } translate -z"), {1.0, 0.6, 0.2});
    expectColor(plane("pigment { rgb 0 } }\n" + mesh + "face_indices { 1, <0,1,2>, 0 } texture { pigment { rgb <0,0,1> } } translate -z"),
                {1.0, 0.6, 0.2});
    std::vector<std::string> warnings;
    const Scene own = test::buildPov("light_source { <0,0,-10>, rgb 1 parallel point_at 0 }\n" + mesh +
                                         "face_indices { 1, <0,1,2> } texture { pigment { rgb <0,0,1> } } }\n",
                                     &warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(own.objects[0].material.color, Vec3(0, 0, 1));
}

// The colour seen along +z through (x, y).
Vec3 seen(const Scene& s, double x, double y) {
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    return Tracer(s, bvh, rs).tracePrimary(Ray{{x, y, -3}, {0, 0, 1}}, ctx);
}

const std::string kFaceTextures =
    "#declare TR = texture { pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } }\n"
    "#declare TG = texture { pigment { rgb <0,1,0> } finish { ambient .5 diffuse 0 } }\n"
    "#declare TB = texture { pigment { rgb <0,0,1> } finish { ambient .25 diffuse 0 } }\n";

TEST(PovMeshTextureList, EachFaceTakesTheTextureItNames) {
    // Measured with povray 3.7.0.10 (40×20 render of these meshes): mesh2's lower-left face names
    // TG of its list, the upper-right one none (the mesh's TB); the mesh's first triangle has TG,
    // the second none (the mesh's TR).
    const Scene s = load(kFaceTextures +
                         "mesh2 { vertex_vectors { 4, <-1,-1,0>, <1,-1,0>, <-1,1,0>, <1,1,0> }\n"
                         "  texture_list { 2, texture { TR } texture { TG } }\n"
                         "  face_indices { 2, <0,1,2>, 1, <1,3,2> } texture { TB } translate -x }\n"
                         "mesh { triangle { <-1,-1,0>, <1,-1,0>, <-1,1,0> texture { TG } }\n"
                         "  triangle { <1,-1,0>, <1,1,0>, <-1,1,0> } texture { TR } translate x }\n");
    expectColor(seen(s, -1.5, -0.5), {0, 0.5, 0});
    expectColor(seen(s, -0.5, 0.5), {0, 0, 0.25});
    expectColor(seen(s, 0.5, -0.5), {0, 0.5, 0});
    expectColor(seen(s, 1.5, 0.5), {1, 0, 0});
    // Triangles that each name the same declared texture share one part.
    const Scene shared = load(kFaceTextures + "mesh { triangle { <-1,-1,0>, <1,-1,0>, <-1,1,0> texture { TG } }\n"
                                              "  triangle { <1,-1,0>, <1,1,0>, <-1,1,0> texture { TG } }\n"
                                              "  triangle { <1,1,0>, <2,1,0>, <1,2,0> } texture { TR } }\n");
    ASSERT_EQ(shared.objects.size(), 1u);
    ASSERT_NE(shared.objects[0].data, nullptr);
    EXPECT_EQ(shared.objects[0].data->parts.size(), 1u);
}

TEST(PovMeshTextureList, TexturesPerVertexBlendAndIndicesAreChecked) {
    // Three indices after a face: each corner's texture shaded in full and the colours weighted by
    // the point's barycentric weights (measured with povray 3.7.0.10, 20×20 8-bit render of this
    // face: (.301, .162, .093) at (−.35, −.25) and (.552, .112, .056) at (−.55, −.55), within 1/255).
    const Scene s = load(kFaceTextures +
                         "mesh2 { vertex_vectors { 3, <-1,-1,0>, <1,-1,0>, <-1,1,0> }\n"
                         "  texture_list { 3, texture { TR } texture { TG } texture { TB } }\n"
                         "  face_indices { 1, <0,1,2>, 0, 1, 2 } }\n");
    auto blend = [](double x, double y) {
        const double w1 = (x + 1) / 2, w2 = (y + 1) / 2, w0 = 1 - w1 - w2;
        return Vec3{w0 * 1, w1 * 0.5, w2 * 0.25};
    };
    expectColor(seen(s, -0.35, -0.25), blend(-0.35, -0.25), 1e-6);  // the BVH's float barycentrics
    expectColor(seen(s, -0.55, -0.55), blend(-0.55, -0.55), 1e-6);
    expectColor(blend(-0.35, -0.25), {0.301, 0.162, 0.093}, 2e-3);
    expectColor(blend(-0.55, -0.55), {0.552, 0.112, 0.056}, 3e-3);
    try {
        test::buildPov("mesh2 { vertex_vectors { 3, <-1,-1,0>, <1,-1,0>, <-1,1,0> }\n"
                       "  texture_list { 1, texture { pigment { rgb 1 } } } face_indices { 1, <0,1,2>, 2 } }\n");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("scene.pov:2:1: error: mesh2 texture index 2 is out of range (1 textures in texture_list)"),
                  std::string::npos)
            << e.what();
    }
}

// A pigment block with no base of its own modifies the pigment the texture has (measured with
// POV-Ray 3.7: `texture { T pigment { scale 0.25 } }` draws T's checker four times smaller; of a
// layered T only the top layer's pigment changes). Each scene is compared, ray by ray over a
// grid, with the same texture written out in full.
TEST(PovLayeredTexture, APigmentWithoutABaseModifiesTheTexturesPigment) {
    const std::string checker = "pigment { checker rgb <1,0,0> rgb <0,0,1> } finish { ambient 1 diffuse 0 }";
    const std::string ramp = "gradient x color_map { [0 rgbt <0,1,0,1>] [1 rgbt <0,1,0,0.3>] }";
    const std::string top = "pigment { " + ramp + " } finish { ambient 1 diffuse 0 }";
    const std::string topScaled = "pigment { " + ramp + " scale 0.25 } finish { ambient 1 diffuse 0 }";
    const std::string checkerScaled =
        "pigment { checker rgb <1,0,0> rgb <0,0,1> scale 0.25 } finish { ambient 1 diffuse 0 }";
    struct Case {
        std::string scene, same;
    };
    const Case cases[] = {
        {"#declare T = texture { " + checker + " }\nplane { -z, -0.5 texture { T pigment { scale 0.25 } } }",
         "plane { -z, -0.5 texture { " + checkerScaled + " } }"},
        {"#declare T = texture { " + checker + " } texture { " + top +
             " }\nplane { -z, -0.5 texture { T pigment { scale 0.25 } } }",
         "plane { -z, -0.5 texture { " + checker + " } texture { " + topScaled + " } }"},
        // The texture's own transformations come before the block's modifiers.
        {"#declare T = texture { " + checker + " rotate 30*z }\nplane { -z, -0.5 texture { T pigment { scale <0.25, 0.5, 1> } } }",
         "plane { -z, -0.5 texture { pigment { checker rgb <1,0,0> rgb <0,0,1> rotate 30*z scale <0.25, 0.5, 1> } "
         "finish { ambient 1 diffuse 0 } } }"},
        {"#declare T = texture { " + checker + " }\nplane { -z, -0.5 texture { T pigment { rgb <0,1,0> } } }",
         "plane { -z, -0.5 texture { pigment { rgb <0,1,0> } finish { ambient 1 diffuse 0 } } }"}};
    for (const Case& c : cases) {
        const Scene a = load(c.scene), b = load(c.same);
        const Bvh ba(a.objects), bb(b.objects);
        const RenderSettings rs;
        TraceContext ca, cb;
        for (int i = 0; i < 64; ++i) {
            const Ray ray{{-1.9 + 0.061 * i, 1.3 - 0.043 * i, -3}, {0, 0, 1}};
            const Vec3 got = Tracer(a, ba, rs).tracePrimary(ray, ca);
            const Vec3 want = Tracer(b, bb, rs).tracePrimary(ray, cb);
            expectColor(got, want, 1e-9);
        }
    }
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
