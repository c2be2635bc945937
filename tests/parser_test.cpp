#include <gtest/gtest.h>

#include <sys/stat.h>

#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "rays/error.h"
#include "rays/io/scene_parser.h"
#include "support/error_text.h"
#include "support/process.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

const char* kCamera = "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n";

Scene parse(const std::string& body, std::vector<std::string>* warnings = nullptr) {
    ParseOptions opt;
    opt.warn = [warnings](const std::string& w) {
        if (warnings) warnings->push_back(w);
    };
    return parseScene(std::string(kCamera) + body, "t.pov", opt);
}

// Message of the Error thrown while parsing text (which must fail).
std::string errorOf(const std::string& text) {
    return rays::test::errorText([&] {
        ParseOptions opt;
        opt.warn = [](const std::string&) {};
        parseScene(text, "t.pov", opt);
    });
}

TEST(Parser, ReadsCourseSceneStructure) {
    const Scene s = parse(
        "light_source {<-100, 100, 100> color rgb <1.5, 1.5, 1.5>}\n"
        "sphere { <0, 0, 0>, 2 pigment { color rgb <1.0, 0.0, 1.0>} finish {ambient 0.2 diffuse 0.4} }\n"
        "plane {<0, 2, 0>, -4 pigment {color rgbf <0.2, 0.2, 0.8, 0.5>} finish {ambient 0.4, diffuse 0.8}}\n");
    ASSERT_EQ(s.cameras.size(), 1u);
    EXPECT_DOUBLE_EQ(s.cameras[0].right.x, 1.33333);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_DOUBLE_EQ(s.lights[0].color.y, 1.5);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.objects[0].type, ShapeType::Sphere);
    EXPECT_DOUBLE_EQ(s.objects[0].r0, 2);
    EXPECT_DOUBLE_EQ(s.objects[0].material.ambient, 0.2);
    EXPECT_EQ(s.objects[1].type, ShapeType::Plane);
    EXPECT_DOUBLE_EQ(s.objects[1].p0.y, 1.0);  // normal normalised
    EXPECT_DOUBLE_EQ(s.objects[1].r0, -4.0);   // distance kept as written
    EXPECT_DOUBLE_EQ(s.objects[1].material.filter, 0.5);
}

TEST(Parser, FinishDefaultsFollowTheCourse) {
    const Material m = parse("sphere { <0,0,0>, 1 }").objects[0].material;
    EXPECT_EQ(m.ambient, 0);
    EXPECT_EQ(m.diffuse, 0);
    EXPECT_EQ(m.specular, 0);
    EXPECT_EQ(m.roughness, 1);
    EXPECT_EQ(m.reflection, 0);
    EXPECT_EQ(m.ior, 1);
    EXPECT_EQ(m.filter, 0);
}

TEST(Parser, LexicalFormsOfTheCorpus) {
    const Scene s = parse(
        "/* block\ncomment */ sphere{<.707,-.3,0.>,20. pigment{color rgb<1e-1,0,0>}finish{ambient .3,diffuse 1.0,}}"
        "sphere { <0,1, 0 >, 1 pigment { color rgb <1,1,1,0.25> } }");  // no final newline
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_DOUBLE_EQ(s.objects[0].p0.x, 0.707);
    EXPECT_DOUBLE_EQ(s.objects[0].p0.y, -0.3);
    EXPECT_DOUBLE_EQ(s.objects[0].r0, 20.0);
    EXPECT_DOUBLE_EQ(s.objects[0].material.color.x, 0.1);
    EXPECT_DOUBLE_EQ(s.objects[0].material.ambient, 0.3);
    EXPECT_DOUBLE_EQ(s.objects[1].material.filter, 0.25);  // 4-component rgb = rgbf
}

TEST(Parser, BoxConeAndTransformsInAnyOrder) {
    const Scene s = parse(
        "box { <1,1,1>, <-1,-1,-1> translate <1,0,0> pigment { color rgb <1,0,0> } scale 2 rotate <0,90,0> }\n"
        "cone { <0,0,1>, 2, <0,0,-3>, 0 pigment {color rgb <0.5,0.5,0.8>} }\n");
    ASSERT_EQ(s.objects.size(), 2u);
    const Object& box = s.objects[0];
    EXPECT_EQ(box.type, ShapeType::Box);
    EXPECT_EQ(box.p0, Vec3(-1, -1, -1));  // corners sorted
    EXPECT_TRUE(box.transformed);
    // M = Ry(90)·S(2)·T(1,0,0): object point (0,0,0) lands at Ry(90)·(2,0,0) = (0,0,-2).
    const Vec3 back = box.toObject.point({0, 0, -2});
    EXPECT_NEAR(back.x, 0, 1e-12);
    EXPECT_NEAR(back.y, 0, 1e-12);
    EXPECT_NEAR(back.z, 0, 1e-12);
    EXPECT_EQ(s.objects[1].type, ShapeType::Cone);
    EXPECT_FALSE(s.objects[1].transformed);
}

TEST(Parser, ExpressionsAndScalarScale) {
    const Scene s = parse("sphere { <0,0,0>, 1 scale 2 translate 3*x rotate -90*y }");
    const Vec3 c = s.objects[0].toObject.point({0, 0, 3});  // (3,0,0) rotated by −90° about y
    EXPECT_NEAR(c.x, 0, 1e-12);
    EXPECT_NEAR(c.z, 0, 1e-12);
}

TEST(Parser, UnsupportedPovrayKeywordsWarnAndAreSkipped) {
    std::vector<std::string> warnings;
    const Scene s = parse(
        "global_settings { assumed_gamma 1.0 }\n"
        "sphere { <0,0,0>, 1 finish { phong 0.5 ambient 0.2 } no_shadow }\n"
        "sphere { <0,0,0>, 1 finish { phong 0.5 } }\n"
        "torus { 1, 0.25 pigment { color rgb 1 } }\n",
        &warnings);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_DOUBLE_EQ(s.objects[0].material.ambient, 0.2);
    std::string all;
    for (const std::string& w : warnings) all += w + "\n";
    EXPECT_NE(all.find("t.pov:2:1: warning: 'global_settings'"), std::string::npos) << all;
    EXPECT_NE(all.find("'phong'"), std::string::npos) << all;
    EXPECT_NE(all.find("'no_shadow'"), std::string::npos) << all;
    EXPECT_NE(all.find("'torus'"), std::string::npos) << all;
    EXPECT_NE(all.find("'phong' ignored 1 more time"), std::string::npos) << all;
}

TEST(Parser, ErrorsCarryFileLineAndColumn) {
    const std::string cam = kCamera;  // line 1
    EXPECT_EQ(errorOf(cam + "spher { <0,0,0>, 1 }"), "t.pov:2:1: error: unknown keyword 'spher'");
    EXPECT_EQ(errorOf(cam + "sphere { <0,0,0>, 1\n"), "t.pov:2:8: error: '{' of 'sphere' is never closed (end of file reached)");
    EXPECT_EQ(errorOf(cam + "}\n"), "t.pov:2:1: error: unbalanced '}': no block is open");
    EXPECT_EQ(errorOf(cam + "sphere { <0,0,0>, 1.2.3 }"), "t.pov:2:19: error: malformed number '1.2.3'");
    EXPECT_EQ(errorOf(cam + "sphere { <0,0,0>, 3e }"), "t.pov:2:19: error: malformed number '3e'");
    EXPECT_EQ(errorOf(cam + "sphere { <0,0>, 1 }"), "t.pov:2:10: error: expected a 3-component vector for sphere centre, found 2 components");
    EXPECT_EQ(errorOf(cam + "sphere { <0 0 0>, 1 }"), "t.pov:2:13: error: expected ',' or '>' in vector, found number 0");
    EXPECT_EQ(errorOf(cam + "sphere { <0,0,0> }"), "t.pov:2:18: error: expected sphere radius, found '}'");
    EXPECT_EQ(errorOf(cam + "sphere { <0,0,0>, -1 }"), "t.pov:2:19: error: sphere radius must be greater than 0");
    EXPECT_EQ(errorOf(cam + "sphere { <0,0,0>, 0 }"), "t.pov:2:19: error: sphere radius must be greater than 0");
    EXPECT_EQ(errorOf(cam + "plane { <0,0,0>, 1 }"), "t.pov:2:9: error: plane normal has zero length");
    EXPECT_EQ(errorOf("camera { location <0,0,5> up <0,0,1> right <1,0,0> look_at <0,0,0> }"),
              "t.pov:1:1: error: camera 'up' is parallel to the view direction");
    EXPECT_EQ(errorOf(cam + "/* never closed"), "t.pov:2:1: error: unterminated /* comment");
    EXPECT_EQ(errorOf("sphere { <0,0,0>, 1 }"), "t.pov: error: scene has no camera");
    EXPECT_EQ(errorOf(cam + "sphere { <0,0,0>, 1 scale <1,0,1> }"), "t.pov:2:21: error: scale has a zero component");
    EXPECT_EQ(errorOf(cam + "sphere { <0,0,0>, 1 pigment { color rgb <1,1> } }"),
              "t.pov:2:41: error: expected a 3-component colour, found 2 components");
    EXPECT_EQ(errorOf(cam + "sphere { <0,0,0>, 1 finish { roughness 0 } }"),
              "t.pov:2:30: error: roughness must be greater than 0");
    EXPECT_EQ(errorOf(cam + "sphere { <0,0,0>, 1 $ }"), "t.pov:2:21: error: unexpected character '$'");
}

TEST(Parser, MissingFileIsAnErrorNamingThePath) {
    try {
        loadScene("/nonexistent/dir/scene.pov");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/dir/scene.pov: error: cannot open scene file");
    }
}

// A regular file is mapped, anything else (a pipe: `rays render <(generate-scene)`) is read as a
// stream; both give the same scene.
TEST(Parser, LoadsFilesAndPipesAlike) {
    test::TempDir dir;
    ASSERT_FALSE(dir.path().empty());
    const std::string text = std::string(kCamera) + "sphere { <1,2,3>, 0.5 pigment { color rgb <1,0,0> } }\n";
    const std::string file = (dir.path() / "scene.pov").string();
    std::ofstream(file) << text;
    const Scene fromFile = loadScene(file);
    ASSERT_EQ(fromFile.objects.size(), 1u);
    EXPECT_EQ(fromFile.objects[0].p0.z, 3.0);

    const std::string fifo = (dir.path() / "pipe.pov").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::thread writer([&] { std::ofstream(fifo) << text; });
    Scene fromPipe;
    try {
        fromPipe = loadScene(fifo);
    } catch (...) {
        writer.join();
        throw;
    }
    writer.join();
    ASSERT_EQ(fromPipe.objects.size(), 1u);
    EXPECT_EQ(fromPipe.objects[0].p0.z, 3.0);
    EXPECT_EQ(fromPipe.objects[0].line, fromFile.objects[0].line);
}

}}  // namespace RAYS_TEST_UNIT, namespace
