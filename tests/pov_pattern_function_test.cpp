// Pattern and pigment functions (`function { pattern { ... } }`, `function { pigment { ... } }`,
// src/rays/pov/pattern_function.*): values while parsing against POV-Ray 3.7.0.10's own
// (tests/data/povray/pattern_functions.pov, pigment_functions.pov and object_patterns.pov wrote
// the .txt files beside them), and the same functions in isosurfaces and function patterns at
// render time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "rays/pov/pov_host.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

const std::string kData = std::string(RAYS_SOURCE_DIR) + "/tests/data/povray/";

std::string readFile(const std::string& path) {
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << path;
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The #debug text and warnings of a scene file run through the POV-Ray host.
struct Run {
    std::string debug;
    std::vector<std::string> warnings;
};

Run runPov(const std::string& text) {
    Run r;
    pov::ParsedScene parsed;
    pov::PovHost host(parsed);
    sdl::LanguageOptions lang;
    lang.installedIncludeDir.clear();
    sdl::Diagnostics d;
    d.debug = [&r](const std::string& s) { r.debug += s; };
    d.warning = [&r](const std::string& s) { r.warnings.push_back(s); };
    sdl::Interpreter in(lang, host, d);
    in.runText(text, "scene.pov");
    return r;
}

// "HEAD NAME INDEX v1 v2 ..." lines by "HEAD NAME INDEX".
std::map<std::string, std::vector<double>> valueLines(const std::string& text) {
    std::map<std::string, std::vector<double>> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream f(line);
        std::string head, name, index;
        if (!(f >> head >> name >> index)) continue;
        std::vector<double>& v = out[head + " " + name + " " + index];
        double x;
        while (f >> x) v.push_back(x);
    }
    return out;
}

// Every measured line is printed by Rays too, each value within 1e-6.
void expectMeasured(const std::string& scene) {
    const Run run = runPov(readFile(kData + scene + ".pov"));
    for (const std::string& w : run.warnings) ADD_FAILURE() << w;
    const auto want = valueLines(readFile(kData + scene + ".txt"));
    const auto got = valueLines(run.debug);
    ASSERT_GT(want.size(), 100u);
    for (const auto& [key, values] : want) {
        const auto it = got.find(key);
        ASSERT_NE(it, got.end()) << key;
        ASSERT_EQ(it->second.size(), values.size()) << key;
        const double tol = 1e-6;
        // POV-Ray's colours are single precision: relative to the value past 1 (100 × .gray).
        for (size_t i = 0; i < values.size(); ++i)
            EXPECT_NEAR(it->second[i], values[i], tol * std::max(1.0, std::fabs(values[i]))) << key << " #" << i;
    }
}

TEST(PovPatternFunction, PatternValuesMatchPovRay) {
    // Waves, frequency, phase, transformations and warps apply; block patterns give their index.
    expectMeasured("pattern_functions");
}

TEST(PovPatternFunction, PigmentColoursMatchPovRay) {
    // All five components and .gray, colour lists, maps, nested pigments, built-in maps.
    expectMeasured("pigment_functions");
}

TEST(PovPatternFunction, ObjectPatternsMatchPovRay) {
    // 0 outside, 1 inside: spheres, boxes, cylinders, cones, tori, planes, CSG, inverse, quadrics ...
    expectMeasured("object_patterns");
}

TEST(PovPatternFunction, CalledWhileParsingToPlaceObjects) {
    // Spheres where a checker is 1: the parse samples the pattern (no stand-in, no warning).
    const test::PovLoaded l = test::loadPov(
        "#declare C = function { pattern { checker } }\n"
        "#declare G = function { pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } } }\n"
        "#for (I, 0, 7) #if (C(I + 0.5, 0.5, 0.5) = 1) sphere { <I, 0, 0>, 0.25 } #end #end\n"
        "#declare B = G(0.25, 0, 0).blue;\n"
        "#if (B > 0.2499 & B < 0.2501) sphere { <0, 5, 0>, 1 } #end\n");
    EXPECT_TRUE(l.warnings.empty()) << l.warnings[0];
    ASSERT_EQ(l.scene.objects.size(), 5u);  // I = 1, 3, 5, 7 and the gradient's check
}

TEST(PovPatternFunction, UnrenderedPatternsStillGiveZeroWithAWarning) {
    const test::PovLoaded l = test::loadPov(
        "#declare S = function { pattern { tiling 26 } }\n"
        "#declare V = S(0.3, 0.2, 0.1);\n");
    ASSERT_EQ(l.warnings.size(), 1u);
    EXPECT_NE(l.warnings[0].find("called while parsing (they give 0)"), std::string::npos) << l.warnings[0];
}

TEST(PovPatternFunction, IsosurfaceOnAPatternFunctionIsRendered) {
    // spherical is 1 - r inside r = 1; scaled by 2 the level 0.5 is the sphere of radius 1.
    std::vector<std::string> warnings;
    const Scene s = test::buildPov(
        "#declare P = function { pattern { spherical scale 2 } }\n"
        "isosurface { function { 0.5 - P(x, y, z) } contained_by { box { -2, 2 } } max_gradient 1 }\n",
        &warnings);
    EXPECT_TRUE(warnings.empty()) << warnings[0];
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_NEAR(test::shootPov(s, {5, 0.1, 0.2}, {-1, 0, 0}).t, 5 - std::sqrt(1 - 0.05), 1e-3);
}

TEST(PovPatternFunction, IsosurfaceOnPatternAndPigmentFunctionsMatchesPovRayPixels) {
    // A ball bumped by a marble pattern function and a leopard pigment function's red.
    const Scene s = test::buildPov(
        "global_settings { assumed_gamma 1 }\n"
        "camera { location <0, 2, -5> look_at 0 angle 40 }\n"
        "light_source { <-4, 6, -5> rgb 1 }\n"
        "#declare P = function { pattern { marble scale 0.7 } }\n"
        "#declare G = function { pigment { leopard color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } scale 0.2 } }\n"
        "isosurface { function { sqrt(x*x + y*y + z*z) - 1 - 0.15 * P(x, y, z) - 0.1 * G(x, y, z).red }\n"
        "  contained_by { sphere { 0, 1.4 } } max_gradient 3 pigment { rgb <0.9, 0.6, 0.3> } }\n"
        "plane { y, -1.3 pigment { rgb 0.7 } }\n");
    // 0-255, POV-Ray 3.7.0.10 (+W160 +H120 -D -A +FP)
    const test::PovPixel pixels[] = {
        {80, 60, {200, 166, 121}, "ball"}, {70, 50, {182, 152, 110}, "ball"}, {90, 45, {205, 171, 125}, "ball"},
        {65, 70, {163, 136, 98}, "ball"},  {95, 72, {168, 140, 101}, "ball"}, {80, 35, {206, 172, 125}, "ball"},
        {60, 58, {200, 167, 121}, "ball"}, {100, 55, {137, 113, 81}, "ball"}, {80, 95, {134, 111, 79}, "ball"},
        {20, 100, {170, 170, 170}, "floor"}, {140, 105, {75, 75, 75}, "floor (shadow)"}};
    test::expectPovPixels(test::renderPov(s), pixels);
}

TEST(PovPatternFunction, IsosurfaceOnAPigmentFunctionIsRendered) {
    // The red of a black-to-red onion of period 3: 0.5 at r = 1.5.
    std::vector<std::string> warnings;
    const Scene s = test::buildPov(
        "#declare P = function { pigment { onion color_map { [0 rgb 0] [1 rgb <1, 0, 0>] } scale 3 } }\n"
        "isosurface { function { P(x, y, z).red - 0.5 } contained_by { sphere { 0, 2 } } max_gradient 1 }\n",
        &warnings);
    EXPECT_TRUE(warnings.empty()) << warnings[0];
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_NEAR(test::shootPov(s, {5, 0, 0}, {-1, 0, 0}).t, 3.5, 1e-3);
}

TEST(PovPatternFunction, FunctionPatternCallingAPigmentFunction) {
    // pigment { function { P(x, y, z).green } }: checker's built-in colours are blue and green.
    const test::PovLoaded l = test::loadPov(
        "#declare P = function { pigment { checker } }\n"
        "sphere { 0, 1 pigment { function { P(x, y, z).green } color_map { [0 rgb 0] [1 rgb 1] } } }\n");
    EXPECT_TRUE(l.warnings.empty()) << l.warnings[0];
    const int pig = l.scene.povSurfaces.at(0).pigment;
    ASSERT_GE(pig, 0);
    EXPECT_NEAR(l.scene.pigments.atRoot(pig, {0.5, 0.5, 0.5}).rgb.x, 0, 1e-9);
    EXPECT_NEAR(l.scene.pigments.atRoot(pig, {1.5, 0.5, 0.5}).rgb.x, 1, 1e-9);
}

TEST(PovPatternFunction, HeightFieldOfAPigmentFunctionTakesItsGray) {
    // Measured with POV-Ray 3.7 (trace down onto the field): rgb <0.2, 0.5, 0.9> stands 0.456482
    // high (its gray 0.4565, in 16 bits), pure red 0.296982.
    const Scene s = test::buildPov("height_field { function 4, 4 { pigment { rgb <0.2, 0.5, 0.9> } } }");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_NEAR(5 - test::shootPov(s, {0.5, 5, 0.5}, {0, -1, 0}).t, 0.456482, 2e-5);
}

TEST(PovPatternFunction, HeightFieldFunctionsRunTheirYAgainstTheFieldsZ) {
    // Measured with POV-Ray 3.7 (trace down onto the field at x 0.3): f = y stands 0.9 high at
    // z = 0.1 and 0.1 high at z = 0.9, as does a gradient y pigment: h(x, z) = f(x, 1 − z, 0).
    for (const char* f : {"y", "pigment { gradient y color_map { [0 rgb 0] [1 rgb 1] } }"}) {
        const Scene s = test::buildPov(std::string("height_field { function 16, 16 { ") + f + " } }");
        ASSERT_EQ(s.objects.size(), 1u) << f;
        for (double z : {0.1, 0.3, 0.7, 0.9})
            EXPECT_NEAR(5 - test::shootPov(s, {0.3, 5, z}, {0, -1, 0}).t, 1 - z, 1e-4) << f << " at z " << z;
    }
}

TEST(PovPatternFunction, FunctionPatternsNestThroughPatternFunctions) {
    // Each level runs a function pattern on the same thread: a pigment's function calls a pattern
    // function whose pattern is a function calling another such pattern function.
    const test::PovLoaded l = test::loadPov(
        "#declare Inner = function { pattern { function { x * 0.5 + 0.25 } } }\n"
        "#declare Outer = function { pattern { function { Inner(y, x, z) + x * 0.125 } } }\n"
        "sphere { 0, 1 pigment { function { Outer(x, y, z) + 0 * y } color_map { [0 rgb 0] [1 rgb 1] } } }\n");
    EXPECT_TRUE(l.warnings.empty()) << l.warnings[0];
    const int pig = l.scene.povSurfaces.at(0).pigment;
    ASSERT_GE(pig, 0);
    for (double y : {0.2, 0.4, 0.6})
        EXPECT_NEAR(l.scene.pigments.atRoot(pig, {0.2, y, 0}).rgb.x, y * 0.5 + 0.25 + 0.2 * 0.125, 1e-9) << y;
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
