// Parsing a big scene file in two pieces on two threads (parseInPieces, ParseOptions::threads):
// the scene must be the one a single parser reads, item for item and with the same line numbers,
// and whatever only a single parser gets right (errors, warnings and their order, textures, an
// `edges` block, a cut that falls inside a comment or a block) must go to a single parser.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "rays/error.h"
#include "rays/io/scene_parser.h"
#include "support/error_text.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

// A course scene of about 360 KB: spheres (transformed, some of them not similarity-transformed),
// triangles, boxes, cones and lights, a camera at the top and a second one past the middle, and
// a comment line after every fiftieth object.
std::string bigScene(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-5, 5), r(0.05, 0.6), a(0, 360);
    auto num = [&](double x) { return std::to_string(x); };
    auto vec = [&]() { return "<" + num(u(rng)) + ", " + num(u(rng)) + ", " + num(u(rng)) + ">"; };
    const std::string finish =
        "  pigment { color rgbf <0.9, 0.6, 0.4, 0.1> }\n  finish { ambient 0.1 diffuse 0.6 specular 0.4 roughness "
        "0.1 reflection 0.3 ior 1.4 }\n}\n";
    std::string text = "camera { location <0, 0, 14> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }\n";
    text += "light_source { <4, 6, -3> color rgb <1, 1, 1> }\n\n";
    for (int i = 0; i < 1800; ++i) {
        if (i == 1000) text += "camera { location <1, 2, -9> look_at <0, 0, 0> }\nlight_source { " + vec() + " color rgb 0.5 }\n";
        if (i % 50 == 0) text += "// item " + std::to_string(i) + "\n";
        switch (i % 4) {
            case 0:
                text += "sphere { <0, 0, 0>, 1\n  rotate " + vec() + "\n  scale " +
                        (i % 8 ? num(r(rng)) : "<" + num(r(rng)) + ", 0.3, 0.5>") + "\n  translate " + vec() + "\n" + finish;
                break;
            case 1: text += "triangle {\n  " + vec() + ",\n  " + vec() + ",\n  " + vec() + "\n" + finish; break;
            case 2: text += "box { " + vec() + ", " + vec() + "\n  rotate <" + num(a(rng)) + ", 0, 0>\n" + finish; break;
            default: text += "cone { " + vec() + ", " + num(r(rng)) + ", " + vec() + ", " + num(r(rng)) + "\n" + finish;
        }
        text += "\n";
    }
    return text;
}

ParseOptions options(int threads, std::vector<std::string>* warnings = nullptr) {
    ParseOptions o;
    o.threads = threads;
    o.warn = [warnings](const std::string& w) {
        if (warnings) warnings->push_back(w);
    };
    return o;
}

void expectSameVec(Vec3 a, Vec3 b) {
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
    EXPECT_EQ(a.z, b.z);
}

void expectSameScene(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.cameras.size(), b.cameras.size());
    for (size_t i = 0; i < a.cameras.size(); ++i) {
        expectSameVec(a.cameras[i].location, b.cameras[i].location);
        expectSameVec(a.cameras[i].lookAt, b.cameras[i].lookAt);
    }
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (size_t i = 0; i < a.lights.size(); ++i) {
        expectSameVec(a.lights[i].position, b.lights[i].position);
        expectSameVec(a.lights[i].color, b.lights[i].color);
    }
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (size_t i = 0; i < a.objects.size(); ++i) {
        const Object& x = a.objects[i];
        const Object& y = b.objects[i];
        ASSERT_EQ(int(x.type), int(y.type)) << "object " << i;
        ASSERT_EQ(x.line, y.line) << "object " << i;
        ASSERT_EQ(x.col, y.col) << "object " << i;
        for (const auto& [p, q] : {std::pair{x.p0, y.p0}, {x.p1, y.p1}, {x.p2, y.p2}}) expectSameVec(p, q);
        EXPECT_EQ(x.r0, y.r0);
        EXPECT_EQ(x.r1, y.r1);
        EXPECT_EQ(x.localSpace, y.localSpace);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) EXPECT_EQ(x.toObject.m[r][c], y.toObject.m[r][c]);
        expectSameVec(x.material.color, y.material.color);
        EXPECT_EQ(x.material.filter, y.material.filter);
        EXPECT_EQ(x.material.reflection, y.material.reflection);
        EXPECT_EQ(x.material.ior, y.material.ior);
    }
}

// The start of the first item at or after pos (items are separated by empty lines).
size_t itemAfter(const std::string& text, size_t pos) { return text.find("\n\n", pos) + 2; }

TEST(ParsePieces, GivesTheSceneOfOneParser) {
    const std::string text = bigScene(1);
    ASSERT_GT(text.size(), 300000u);
    const Scene whole = parseScene(text, "big.pov", options(1));
    const std::optional<Scene> pieces = parseInPieces(text, "big.pov", options(2));
    ASSERT_TRUE(pieces.has_value()) << "the file should have been cut";
    expectSameScene(*pieces, whole);
    EXPECT_EQ(pieces->cameras.size(), 2u);
    EXPECT_EQ(pieces->objects.size(), 1800u);
    // parseScene takes the same path by default.
    expectSameScene(parseScene(text, "big.pov", options(0)), whole);
}

TEST(ParsePieces, SmallFilesAndOneThreadReadWhole) {
    const std::string text = bigScene(2);
    EXPECT_FALSE(parseInPieces(text, "big.pov", options(1)).has_value());
    EXPECT_FALSE(parseInPieces(text.substr(0, 200000), "big.pov", options(2)).has_value());
}

// An error past the middle: the message (file:line:col) is the single parser's.
TEST(ParsePieces, ErrorsInTheSecondHalfAreReportedAsByOneParser) {
    std::string text = bigScene(3);
    text.insert(itemAfter(text, text.size() / 2 + 5000), "sphere { <1, 2, 3>, 0.5 pigment { color rgb <1, 0, 0> } finish { ambient 2x } }\n");
    const std::string one = rays::test::errorText([&] { parseScene(text, "big.pov", options(1)); });
    const std::string two = rays::test::errorText([&] { parseScene(text, "big.pov", options(2)); });
    EXPECT_NE(one.find("big.pov:"), std::string::npos) << one;
    EXPECT_EQ(two, one);
    EXPECT_FALSE(parseInPieces(text, "big.pov", options(2)).has_value());
}

// Warnings from either half, and the summary of repeated ones, come out as from one parser.
TEST(ParsePieces, WarningsComeOutAsFromOneParser) {
    const std::string warned = "sphere { <0, 1, 0>, 0.3 no_shadow pigment { color rgb 1 } }\n";
    for (const bool secondHalfToo : {false, true}) {
        std::string text = bigScene(4);
        if (secondHalfToo) text.insert(itemAfter(text, text.size() / 2 + 3000), warned);
        text.insert(itemAfter(text, 1000), warned);
        text.insert(itemAfter(text, 9000), warned);
        std::vector<std::string> one, two;
        const Scene whole = parseScene(text, "big.pov", options(1, &one));
        const Scene pieces = parseScene(text, "big.pov", options(2, &two));
        ASSERT_GE(one.size(), 2u);
        EXPECT_EQ(two, one);
        expectSameScene(pieces, whole);
    }
}

// A cut that would fall inside a block comment or inside a block (lines past the middle that start
// like items but are not top-level ones) leaves the first piece unfinished: one parser reads it.
TEST(ParsePieces, CutsInsideCommentsOrBlocksAreRefused) {
    // Items commented out from before the middle to well after it.
    std::string commented = bigScene(5);
    commented.insert(itemAfter(commented, commented.size() / 2 + 20000), "*/\n");
    commented.insert(itemAfter(commented, commented.size() / 2 - 20000), "/*\n");
    // A mesh block of triangles, one per line start, across the middle.
    std::string meshed = bigScene(6);
    std::string mesh = "mesh {\n";
    for (int i = 0; i < 400; ++i)
        mesh += "triangle { <" + std::to_string(i) + ", 0, 0>, <1, " + std::to_string(i) + ", 0>, <0, 0, 1> }\n";
    mesh += "  pigment { color rgb 1 }\n}\n";
    meshed.insert(itemAfter(meshed, meshed.size() / 2 - mesh.size() / 2), mesh);
    for (const std::string& text : {commented, meshed}) {
        const Scene whole = parseScene(text, "big.pov", options(1));
        EXPECT_FALSE(parseInPieces(text, "big.pov", options(2)).has_value());
        expectSameScene(parseScene(text, "big.pov", options(2)), whole);
    }
}

// What the second piece may not hold: an `edges` block (it sets the scene's line settings), and
// the whole file then reads as one.
TEST(ParsePieces, AnEdgesBlockPastTheMiddleGoesToOneParser) {
    std::string text = bigScene(6);
    text.insert(itemAfter(text, text.size() / 2 + 3000), "edges { crease crease_angle 40 }\n");
    EXPECT_FALSE(parseInPieces(text, "big.pov", options(2)).has_value());
    const Scene whole = parseScene(text, "big.pov", options(1));
    const Scene pieces = parseScene(text, "big.pov", options(2));
    EXPECT_EQ(pieces.edges.creaseAngle, 40);
    EXPECT_EQ(pieces.edges.creaseAngle, whole.edges.creaseAngle);
    expectSameScene(pieces, whole);
}

}}  // namespace RAYS_TEST_UNIT, namespace
