// POV-Ray's text object (scene/text_shape.h, io/ttf_font.h): glyph layout, caps, walls on lines
// and Bézier curves, the inside test, extents and a render, each compared with numbers measured
// from POV-Ray 3.7.0.10 (trace, inside, min_extent / max_extent, pixels). The fonts come from
// Debian's fonts-povray; the tests that need them are skipped when it is not installed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/error.h"
#include "rays/io/ttf_font.h"
#include "rays/pov/load_pov.h"
#include "rays/render/renderer.h"
#include "support/pov_scene.h"
#include "rays/scene/csg.h"
#include "rays/scene/text_shape.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

constexpr const char* kFontDir = "/usr/share/fonts/truetype/povray";

bool haveFonts() { return std::filesystem::exists(std::string(kFontDir) + "/timrom.ttf"); }

#define NEED_FONTS() \
    if (!haveFonts()) GTEST_SKIP() << "fonts-povray is not installed (" << kFontDir << ")"

Scene build(const std::string& text, std::vector<std::string>* warnings = nullptr) { return test::buildPov(text, warnings); }

bool near(Vec3 a, Vec3 b, double eps) { return length(a - b) < eps; }

Hit shoot(const Scene& s, Vec3 from, Vec3 dir) { return test::shootPov(s, from, dir); }

// The scene's only object's text shape.
const TextShape& shapeOf(const Scene& s) {
    EXPECT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].type, ShapeType::Text);
    return *s.objects[0].text;
}

TEST(PovTextHits, StemOfAnIIsHitOnItsFrontFaceAndTheGapMisses) {
    NEED_FONTS();
    // POV-Ray: the stem of timrom's "I" spans x 0.096 .. 0.2 at y = 0.3 (the first glyph's left
    // bearing dropped); the second I starts at 0.342 + 0.096.
    const Scene s = build("text { ttf \"timrom.ttf\" \"II\" 1, 0 }\n");
    const Hit h = shoot(s, {0.15, 0.3, -1}, {0, 0, 1});
    ASSERT_TRUE(h.valid());
    EXPECT_NEAR(h.t, 1.0, 1e-9);
    EXPECT_TRUE(near(h.normal, {0, 0, -1}, 1e-12));
    EXPECT_FALSE(shoot(s, {0.3, 0.3, -1}, {0, 0, 1}).valid());   // between the letters
    EXPECT_FALSE(shoot(s, {0.21, 0.3, -1}, {0, 0, 1}).valid());  // just right of the first stem
    EXPECT_TRUE(shoot(s, {0.45, 0.3, -1}, {0, 0, 1}).valid());   // the second stem
    const Hit back = shoot(s, {0.15, 0.3, 2}, {0, 0, -1});
    ASSERT_TRUE(back.valid());
    EXPECT_NEAR(back.t, 1.0, 1e-9);
    EXPECT_TRUE(near(back.normal, {0, 0, 1}, 1e-12));
}

TEST(PovTextHits, WallsOfLinesAndCurvesMatchPovRaysTrace) {
    NEED_FONTS();
    const Scene i = build("text { ttf \"timrom.ttf\" \"I\" 1, 0 }\n");
    const Hit side = shoot(i, {-1, 0.3, 0.5}, {1, 0, 0});
    ASSERT_TRUE(side.valid());
    EXPECT_NEAR(side.t, 1.096, 1e-6);  // POV-Ray's trace: x = 0.096
    EXPECT_TRUE(near(side.normal, {-1, 0, 0}, 1e-9));  // outward (POV-Ray's trace reports inward wall normals)
    // The "O": its curved outer wall, the inner wall of its hole, and the hole itself.
    const Scene o = build("text { ttf \"timrom.ttf\" \"O\" 1, 0 }\n");
    const Hit a = shoot(o, {-1, 0.34, 0.5}, {1, 0, 0});
    ASSERT_TRUE(a.valid());
    EXPECT_NEAR(a.t - 1, 0.000022, 1e-5);
    // On the curves Rays' exact Bézier hits lie within 5e-4 of POV-Ray's (its own curve solving
    // differs slightly); on lines they agree to POV-Ray's printed digits.
    const Ray rb{{-1, 0.6, 0.5}, normalize(Vec3{1, 0.001, 0.001})};
    const Hit b = shoot(o, rb.origin, rb.dir);
    ASSERT_TRUE(b.valid());
    EXPECT_TRUE(near(rb.at(b.t), {0.106459, 0.601106, 0.501106}, 5e-4)) << rb.at(b.t).x << " " << rb.at(b.t).y;
    EXPECT_TRUE(near(b.normal, {-0.701570, 0.712601, 0}, 5e-3)) << b.normal.x << " " << b.normal.y;  // POV-Ray's, turned outward
    const Hit e = shoot(o, {0.341, 0.34, 0.5}, {0, 1, 0});  // from inside the hole, upwards
    ASSERT_TRUE(e.valid());
    EXPECT_NEAR(0.34 + e.t, 0.661997, 1e-5);
    EXPECT_TRUE(near(e.normal, {0, -1, 0}, 1e-3));
    const Ray rf{{0.341, 0.34, 0.5}, normalize(Vec3{1, 0.3, 0})};
    const Hit f = shoot(o, rf.origin, rf.dir);
    ASSERT_TRUE(f.valid());
    EXPECT_TRUE(near(rf.at(f.t), {0.557051, 0.404815, 0.5}, 5e-4)) << rf.at(f.t).x << " " << rf.at(f.t).y << " " << f.normal.x << " " << f.normal.y;
    EXPECT_FALSE(shoot(o, {0.341, 0.34, -1}, {0, 0, 1}).valid());  // through the hole
    EXPECT_TRUE(shoot(o, {0.05, 0.34, -1}, {0, 0, 1}).valid());
}

TEST(PovTextInside, InsideFollowsTheOutlineAndTheThickness) {
    NEED_FONTS();
    const Scene s = build("text { ttf \"timrom.ttf\" \"IO\" 0.5, 0 translate <1, 0, 0> }\n");
    const Object& t = s.objects.at(0);
    EXPECT_EQ(insideShape(t, {1.15, 0.3, 0.25}), 1);   // in the I's stem
    EXPECT_EQ(insideShape(t, {1.15, 0.3, 0.75}), 0);   // behind it
    EXPECT_EQ(insideShape(t, {1.15, 0.3, -0.1}), 0);   // before it
    EXPECT_EQ(insideShape(t, {1.25, 0.3, 0.25}), 0);   // right of the stem
    // The O (pen 0.342 + 0.032 − 0.023 from the origin) keeps its hole empty.
    const double ox = 1 + 0.342 - 0.023;
    EXPECT_EQ(insideShape(t, {ox + 0.05, 0.34, 0.25}), 1);
    EXPECT_EQ(insideShape(t, {ox + 0.341, 0.34, 0.25}), 0);
    // The language's inside() agrees (POV-Ray 3.7 prints 1, 0, 0 here).
    const Scene q = build(
        "#declare T = text { ttf \"timrom.ttf\" \"I\" 1, 0 }\n"
        "sphere { <inside(T, <0.15, 0.3, 0.5>), inside(T, <0.15, 0.3, 1.5>), inside(T, <0.5, 0.3, 0.5>)>, 1 }\n");
    EXPECT_TRUE(near(q.objects.at(0).p0, {1, 0, 0}, 1e-12));
}

// min_extent / max_extent of texts, as POV-Ray 3.7 prints them (its boxes are 1e-5 wider).
TEST(PovTextLayout, ExtentsMatchPovRay) {
    NEED_FONTS();
    struct Case {
        const char* text;
        Vec3 lo, hi;
    };
    const Case cases[] = {
        {"ttf \"timrom.ttf\" \"POV-Ray\" 1, 0", {0, -0.212, 0}, {3.796, 0.696, 1}},
        {"ttf \"timrom.ttf\" \"AV\" 1, 0", {0, -0.016, 0}, {1.278, 0.696, 1}},      // kerning A-V: -187
        {"ttf \"timrom.ttf\" \"To\" 1, 0", {0, -0.010, 0}, {1.012, 0.680, 1}},
        {"ttf \"timrom.ttf\" \" I\" 1, 0", {0, 0, 0}, {0.573, 0.680, 1}},  // a space first: its origin
        {"ttf \"timrom.ttf\" \"I \" 1, 0", {0, 0, 0}, {0.319, 0.680, 1}},  // a space last: its origin
        {"ttf \"timrom.ttf\" \" \" 1, 0", {0, 0, 0}, {0, 0, 1}},          // a space alone: a point
        {"ttf \"timrom.ttf\" \"-\" 1, 0", {0, 0.215, 0}, {0.250, 0.275, 1}},  // above the baseline: tight
        {"ttf \"timrom.ttf\" \"II\" 0.5, 0.1*x", {0, 0, 0}, {0.738, 0.680, 0.5}},
        {"internal 1 \"II\" 0.5, 0", {0, 0, 0}, {0.638, 0.680, 0.5}},
        {"ttf \"cyrvetic.ttf\" \"Hello\" 0.5, <0.1, 0.2, 0>", {0, 0, 0}, {2.558, 1.334, 0.5}},
        {"ttf \"timrom.ttf\" \"II\" 1, 0.1", {0, 0, 0}, {0.738, 0.780, 1}},          // a float offset: <0.1, 0.1, 0.1>
        {"ttf \"timrom.ttf\" \"II\" 1, <0, 0, 0.5>", {0, 0, 0}, {0.638, 0.680, 1}},  // offset's z is not used
        {"ttf \"timrom.ttf\" \"I\" -1, 0", {0, 0, -1}, {0.296, 0.680, 0}},           // towards -z
        {"ttf \"crystal.ttf\" \"Wave\" 1, 0", {0, -0.00781, 0}, {1.96388, 0.68897, 1}},
        {"ttf \"povlogo.ttf\" \"P\" 1, 0", {0, 0.00195, 0}, {0.66992, 1.00195, 1}},
        {"internal 7 \"P\" 1, 0", {0, 0.00195, 0}, {0.66992, 1.00195, 1}},  // out of range: font 0, povlogo
        {"ttf \"cyrvetic\" \"Hello\" 0.5, <0.1, 0.2, 0>", {0, 0, 0}, {2.558, 1.334, 0.5}},  // ".ttf" added
    };
    for (const Case& c : cases) {
        const Scene s = build(std::string("text { ") + c.text + " }\n");
        const Bounds b = worldBounds(s.objects.at(0));
        EXPECT_TRUE(near(b.hi, c.hi, 2e-4)) << c.text << ": " << b.hi.x << " " << b.hi.y << " " << b.hi.z;
        EXPECT_TRUE(near(b.lo, c.lo, 2e-4)) << c.text << ": " << b.lo.x << " " << b.lo.y << " " << b.lo.z;
    }
}

// Texts with the same string, font, thickness and offset share one outline (a scene of many
// letter blocks lays each letter out once); others get their own. The font is looked for once
// per name (FontCache::pathOf), by the scene's builder and by those of trace() and the extents.
TEST(PovTextLayout, TheSameTextSharesItsOutlines) {
    NEED_FONTS();
    const Scene s = build(
        "#declare T = text { ttf \"timrom.ttf\" \"A\" 1, 0 }\n"
        "#declare E = max_extent(T);\n"
        "object { T translate x } object { T rotate 30*y }\n"
        "text { ttf \"timrom.ttf\" \"A\" 1, 0 }\n"
        "text { ttf \"timrom.ttf\" \"A\" 0.5, 0 }\n"
        "text { ttf \"timrom.ttf\" \"B\" 1, 0 }\n");
    ASSERT_EQ(s.objects.size(), 5u);
    EXPECT_EQ(s.objects[0].text, s.objects[1].text);
    EXPECT_EQ(s.objects[0].text, s.objects[2].text);
    EXPECT_NE(s.objects[0].text, s.objects[3].text);
    EXPECT_NE(s.objects[0].text, s.objects[4].text);
    EXPECT_EQ(s.texts.size(), 3u);
}

TEST(PovTextLayout, LongStringsTestOnlyNearbyGlyphs) {
    NEED_FONTS();
    std::string line;
    for (int i = 0; i < 200; ++i) line += "IO";
    const Scene s = build("text { ttf \"timrom.ttf\" \"" + line + "\" 1, 0 }\n");
    const TextShape& t = shapeOf(s);
    ASSERT_EQ(t.glyphs.size(), 400u);
    for (size_t i = 1; i < t.glyphs.size(); ++i) {
        EXPECT_LE(t.glyphs[i - 1].xMin, t.glyphs[i].xMin);
        EXPECT_GE(t.xMaxPrefix[i], t.xMaxPrefix[i - 1]);
    }
    // The 101st I: pen 100·(0.342 + 0.746) (no kerning between I and O in timrom).
    const double x = 100 * (0.342 + 0.746) + 0.15;
    const Hit h = shoot(s, {x, 0.3, -1}, {0, 0, 1});
    ASSERT_TRUE(h.valid());
    EXPECT_NEAR(h.t, 1.0, 1e-9);
    EXPECT_FALSE(shoot(s, {x + 0.1, 0.3, -1}, {0, 0, 1}).valid());
}

TEST(PovTextHits, FlatTextOfThicknessZeroIsHit) {
    NEED_FONTS();
    const Scene s = build("text { ttf \"timrom.ttf\" \"I\" 0, 0 }\n");  // POV-Ray's trace hits it at z = 0
    const Hit h = shoot(s, {0.15, 0.3, -3}, {0, 0, 1});
    ASSERT_TRUE(h.valid());
    EXPECT_NEAR(h.t, 3.0, 1e-9);
    EXPECT_FALSE(shoot(s, {0.25, 0.3, -3}, {0, 0, 1}).valid());
}

TEST(PovTextLayout, StringsAreUtf8WithLatin1Bytes) {
    EXPECT_EQ(decodeText("A\xC3\xA9z"), (std::u32string{U'A', 0xE9, U'z'}));  // é in UTF-8
    EXPECT_EQ(decodeText("\xE9t\xE9"), (std::u32string{0xE9, U't', 0xE9}));    // é as a Latin-1 byte
    EXPECT_EQ(decodeText("\xE2\x82\xAC"), std::u32string{0x20AC});              // €
}

TEST(PovTextErrors, MissingFontIsAnErrorAtTheTtfKeyword) {
    try {
        build("sphere { 0, 1 }\ntext { ttf \"no_such_font.ttf\" \"A\" 1, 0 }\n");
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("scene.pov:3:8: error: cannot find the font file \"no_such_font.ttf\""), std::string::npos) << m;
    }
}

TEST(PovTextCsg, DifferenceCutsTheTextOutOfABox) {
    NEED_FONTS();
    const Scene s = build(
        "difference { box { <-0.5, -0.5, 0.2>, <1.5, 1.5, 0.8> } text { ttf \"timrom.ttf\" \"I\" 0.5, 0 } }\n");
    ASSERT_EQ(s.objects.size(), 1u);
    ASSERT_EQ(s.objects[0].type, ShapeType::Csg);
    const Hit stem = shoot(s, {0.15, 0.3, -1}, {0, 0, 1});  // through the stem: the hole's bottom
    ASSERT_TRUE(stem.valid());
    EXPECT_NEAR(stem.t, 1.5, 1e-9);
    EXPECT_TRUE(near(stem.normal, {0, 0, -1}, 1e-12));  // the text's back cap, turned to face the hole
    const Hit beside = shoot(s, {0.5, 0.3, -1}, {0, 0, 1});  // the box's front face
    ASSERT_TRUE(beside.valid());
    EXPECT_NEAR(beside.t, 1.2, 1e-9);
}

// "Rays" in timrom over a floor, lit from the upper left; pixels measured from POV-Ray 3.7.0.10
// (povray +W160 +H120 -D -A).
TEST(PovTextRender, PixelsMatchPovRay) {
    NEED_FONTS();
    const Scene s = build(
        "global_settings { assumed_gamma 1.0 }\n"
        "camera { location <1.4, 1.2, -3> look_at <1.4, 0.3, 0> angle 50 }\n"
        "light_source { <-3, 5, -6> color rgb 1 }\n"
        "plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }\n"
        "text { ttf \"timrom.ttf\" \"Rays\" 0.3, 0 pigment { rgb <0.9, 0.3, 0.2> } }\n");
    const ImageF img = test::renderPov(s);
    const test::PovPixel pixels[] = {
        {10, 56, {185, 112, 92}, "the R's stem, front face"},
        {64, 52, {182, 110, 91}, "the y's front face"},
        {100, 50, {174, 105, 86}, "the s's front face"},
        {30, 64, {85, 48, 39}, "the a's wall in shade"},
        {44, 50, {153, 153, 144}, "the floor seen through the a's bowl"},
        {80, 100, {163, 163, 153}, "the floor before the text"},
    };
    test::expectPovPixels(img, pixels);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays

namespace { namespace RAYS_TEST_UNIT {

TEST(PovTextOutline, AQuadraticIsSplitOnceWhereYTurnsWhateverTheRounding) {
    // Fuzz finding 28 (fuzz_font): splitting the two pieces again found a turning point in (0, 1)
    // from rounding every time, and recursed until the stack ran out. This quad (found by a search
    // like the fuzzer's) did so; now it gives two pieces, each monotone in y.
    rays::TextShape shape;
    shape.glyphs.emplace_back();
    shape.addQuad(0x1.ac6b851eb851fp-2, -0x1.e2147ae147ae1p-3, -0x1.78ca3d70a3d71p-1, -0x1.51051eb851eb8p-1,
                  -0x1.82147ae147ae1p-3, 0x1.adeb851eb851fp-3);
    ASSERT_EQ(shape.segments.size(), 2u);
    for (const rays::TextSegment& e : shape.segments) {
        EXPECT_TRUE(e.quad);
        EXPECT_GE(e.cy, std::min(e.ay, e.by));
        EXPECT_LE(e.cy, std::max(e.ay, e.by));
    }
    EXPECT_EQ(shape.segments[0].bx, shape.segments[1].ax);
    EXPECT_EQ(shape.segments[0].by, shape.segments[1].ay);
}

}}  // namespace RAYS_TEST_UNIT, namespace
