// POV-Ray's constructive solid geometry (scene/csg.h): inside tests of the solid shapes, hits
// through intersections, differences, merges, unions inside CSG, inverse and clipped_by, their
// normals, materials, bounds and shadows, and a small render compared with POV-Ray 3.7's pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/error.h"
#include "rays/pov/load_pov.h"
#include "rays/render/renderer.h"
#include "rays/render/tracer.h"
#include "support/pov_scene.h"
#include "rays/scene/csg.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

Scene build(const std::string& text, std::vector<std::string>* warnings = nullptr) { return test::buildPov(text, warnings); }

bool near(Vec3 a, Vec3 b, double eps = 1e-9) { return length(a - b) < eps; }

Hit shoot(const Scene& s, Vec3 from, Vec3 dir) { return test::shootPov(s, from, dir); }

std::vector<double> allHits(const Scene& s, Vec3 from, Vec3 dir) { return test::allHitsPov(s, from, dir, 1e-9); }

Object prepared(Object o, const Transform& m = Transform{}) {
    prepareObject(o, m);
    return o;
}

TEST(PovCsgInside, SolidShapesKnowTheirInside) {
    Object sphere;
    sphere.type = ShapeType::Sphere;
    sphere.p0 = {1, 0, 0};
    sphere.r0 = 1;
    const Object s = prepared(sphere, Transform::scale({1, 3, 1}));  // an ellipsoid: local space
    EXPECT_EQ(insideShape(s, {1, 2.9, 0}), 1);  // world (1, 2.9, 0) is object (1, 0.97, 0)
    EXPECT_EQ(insideShape(s, {2.1, 0, 0}), 0);
    EXPECT_EQ(insideShape(prepared(sphere), {1.5, 0, 0}), 1);

    Object box;
    box.type = ShapeType::Box;
    box.p0 = {-1, -1, -1};
    box.p1 = {1, 1, 1};
    const Object b = prepared(box, Transform::rotateAxis(2, 45));
    EXPECT_EQ(insideShape(b, {1.3, 0, 0}), 1);  // inside the turned box's corner
    EXPECT_EQ(insideShape(b, {1, 1, 0}), 0);

    Object cone;  // apex up: radius 1 at y = 0, 0 at y = 2
    cone.type = ShapeType::Cone;
    cone.p0 = {0, 0, 0};
    cone.r0 = 1;
    cone.p1 = {0, 2, 0};
    cone.r1 = 0;
    const Object c = prepared(cone);
    EXPECT_EQ(insideShape(c, {0.4, 1, 0}), 1);
    EXPECT_EQ(insideShape(c, {0.6, 1, 0}), 0);
    EXPECT_EQ(insideShape(c, {0, -0.1, 0}), 0);
    cone.open = true;  // an open cone keeps the closed solid's inside
    EXPECT_EQ(insideShape(prepared(cone), {0.4, 1, 0}), 1);

    Object plane;  // plane { y, 1 }: inside is below
    plane.type = ShapeType::Plane;
    plane.p0 = {0, 1, 0};
    plane.r0 = 1;
    EXPECT_EQ(insideShape(prepared(plane), {5, 0.9, 5}), 1);
    EXPECT_EQ(insideShape(prepared(plane), {5, 1.1, 5}), 0);
    EXPECT_EQ(insideShape(prepared(plane, Transform::translate({0, 1, 0})), {0, 1.9, 0}), 1);

    Object tri;
    tri.type = ShapeType::Triangle;
    tri.p1 = {1, 0, 0};
    tri.p2 = {0, 1, 0};
    EXPECT_EQ(insideShape(prepared(tri), {0.1, 0.1, 0}), -1);  // not a solid
}

// At their boundaries the inside tests answer as POV-Ray 3.7's inside() does (measured at points
// 10^-4 … 10^-16 either side): cylinders and cones hold a point only 1e-10 within their canonical
// forms, a plane's inside reaches 1e-10 beyond it, boxes and tori are closed, spheres open.
TEST(PovCsgInside, BoundariesAnswerAsPovRaysInsideDoes) {
    const Scene s = build(
        "cylinder { <0, -0.5, 0>, <0, 1, 0>, 0.5 }\n"
        "cone { <0, -0.5, 0>, 0.5, <0, 1, 0>, 0.25 }\n"
        "box { -1, 1 }\n"
        "torus { 1, 0.25 }\n"
        "sphere { 0, 1 }\n"
        "plane { y, 1 }\n"
        "cylinder { <0, 0, 0>, <0, 10, 0>, 1 translate 5*x }\n");
    ASSERT_EQ(s.objects.size(), 7u);
    auto in = [&](int i, Vec3 p) { return insideShape(s.objects[size_t(i)], p); };
    // Cylinder (height 1.5, radius 0.5): the top and bottom caps, then the side.
    EXPECT_EQ(in(0, {0.1, 1 - 1.78e-10, 0}), 1);
    EXPECT_EQ(in(0, {0.1, 1 - 1e-10, 0}), 0);
    EXPECT_EQ(in(0, {0.1, 1, 0}), 0);
    EXPECT_EQ(in(0, {0.1, -0.5 + 1.78e-10, 0}), 1);
    EXPECT_EQ(in(0, {0.1, -0.5 + 1e-10, 0}), 0);
    EXPECT_EQ(in(0, {0.5 - 3.16e-11, 0.2, 0}), 1);
    EXPECT_EQ(in(0, {0.5 - 1.78e-11, 0.2, 0}), 0);
    // The tolerance is the canonical form's: ten times as far on a cylinder ten times as long.
    EXPECT_EQ(in(6, {5.1, 10 - 1e-9, 0}), 1);
    EXPECT_EQ(in(6, {5.1, 10 - 5.6e-10, 0}), 0);
    // Cone (apex at y = 2.5, so its canonical axis is 3 long): the small cap and the side.
    EXPECT_EQ(in(1, {0.1, 1 - 3.16e-10, 0}), 1);
    EXPECT_EQ(in(1, {0.1, 1 - 1.78e-10, 0}), 0);
    EXPECT_EQ(in(1, {0.375 - 5.6e-11, 0.25, 0}), 1);
    EXPECT_EQ(in(1, {0.375 - 3.16e-11, 0.25, 0}), 0);
    // Box and torus closed; sphere open.
    EXPECT_EQ(in(2, {0.1, 1, 0}), 1);
    EXPECT_EQ(in(2, {1, 0.1, 0}), 1);
    EXPECT_EQ(in(2, {0.1, 1 + 1e-12, 0}), 0);
    EXPECT_EQ(in(3, {1, 0.25, 0}), 1);
    EXPECT_EQ(in(3, {1, 0.25 + 1e-12, 0}), 0);
    EXPECT_EQ(in(4, {0, 1, 0}), 0);
    EXPECT_EQ(in(4, {0, 1 - 1e-15, 0}), 1);
    // Plane: 1e-10 beyond.
    EXPECT_EQ(in(5, {0, 1 + 5.6e-11, 0}), 1);
    EXPECT_EQ(in(5, {0, 1 + 1e-10, 0}), 0);

    const Scene more = build(
        "quartic { <1,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,0,0, 1,0,0,0,0,0,0,0,0,0, 1,0,0,0,-16> }\n"
        "quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }\n"
        "superellipsoid { <0.5, 0.5> scale 3 }\n"
        "isosurface { function { x*x + y*y + z*z - 1 } contained_by { box { -2, 2 } } }\n"
        "prism { linear_sweep linear_spline -1, 2, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1> }\n"
        "lathe { linear_spline 4, <0,0>, <1,0>, <1,1>, <0,1> }\n");
    ASSERT_EQ(more.objects.size(), 6u);
    auto at = [&](int i, Vec3 p) { return insideShape(more.objects[size_t(i)], p); };
    // x⁴ + y⁴ + z⁴ − 16 at x = 2 + d is about 32·d: inside while below 1e-4.
    EXPECT_EQ(at(0, {2 + 1.78e-6, 0, 0}), 1);
    EXPECT_EQ(at(0, {2 + 3.16e-6, 0, 0}), 0);
    EXPECT_EQ(at(1, {1, 0, 0}), 1);  // a quadric is closed
    EXPECT_EQ(at(1, {1 + 1e-12, 0, 0}), 0);
    // Superellipsoid: 1e-10 of its own size beyond, whatever its exponents.
    EXPECT_EQ(at(2, {3 + 1.78e-10, 0, 0}), 1);
    EXPECT_EQ(at(2, {3 + 3.16e-10, 0, 0}), 0);
    EXPECT_EQ(at(3, {1, 0, 0}), 1);  // isosurface closed
    EXPECT_EQ(at(3, {1 + 1e-12, 0, 0}), 0);
    EXPECT_EQ(at(4, {0.1, -1, 0.1}), 1);  // prism: bottom closed, top open
    EXPECT_EQ(at(4, {0.1, 2, 0.1}), 0);
    EXPECT_EQ(at(5, {1, 0.5, 0}), 1);  // lathe closed
    EXPECT_EQ(at(5, {1 + 1e-12, 0.5, 0}), 0);
}

// So two cylinders sharing a cap plane keep both caps where they overlap in a merge (each cap lies
// outside the other cylinder), as in POV-Ray; before, the overlap showed a hole or speckles.
TEST(PovCsgHits, CoincidentCapsOfAMergeStay) {
    const std::string two =
        "cylinder { <-0.35, -0.5, 0>, <-0.35, 1, 0>, 0.5 } cylinder { <0.35, -0.5, 0>, <0.35, 1, 0>, 0.5 }";
    const Scene m = build("merge { " + two + " pigment { rgbt <1, 0.5, 0.2, 0.6> } }");
    const Scene u = build("object { union { " + two + " } inverse }");
    for (double x : {-0.1, 0.0, 0.05, 0.12}) {
        const Hit a = shoot(m, {x, 3, 0.01}, {0, -1, 0});
        ASSERT_TRUE(a.valid()) << x;
        EXPECT_NEAR(a.t, 2, 1e-9) << x;  // the top cap, in the overlap
        const Hit b = shoot(u, {x, 0.2, 0.01}, {0, 1, 0});  // from inside both, upwards
        ASSERT_TRUE(b.valid()) << x;
        EXPECT_NEAR(b.t, 0.8, 1e-9) << x;
    }
}

TEST(PovCsgHits, DifferenceShowsTheCutFaceInsideTheSphere) {
    std::vector<std::string> warnings;
    const Scene s = build("difference { sphere { 0, 1 } box { <-2, -2, -2>, <2, 2, 0> } }", &warnings);
    EXPECT_TRUE(warnings.empty());
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].type, ShapeType::Csg);
    const Hit h = shoot(s, {0.3, 0.2, -5}, {0, 0, 1});  // through the removed half to the cut
    ASSERT_TRUE(h.valid());
    EXPECT_NEAR(h.t, 5, 1e-9);
    EXPECT_TRUE(near(h.normal, {0, 0, -1}));  // the box's face, turned to face the ray
    EXPECT_TRUE(near(h.geomNormal, {0, 0, -1}));
    ASSERT_NE(h.part, nullptr);
    EXPECT_EQ(h.part->type, ShapeType::Box);
    // From the other side the sphere is kept; outside the sphere the cut face is not there.
    const Hit back = shoot(s, {0, 0, 5}, {0, 0, -1});
    EXPECT_NEAR(back.t, 4, 1e-9);
    EXPECT_TRUE(near(back.normal, {0, 0, 1}));
    EXPECT_FALSE(shoot(s, {1.2, 0, -5}, {0, 0, 1}).valid());
}

TEST(PovCsgHits, IntersectionOfTwoSpheresIsALens) {
    const Scene s = build("intersection { sphere { <-0.5, 0, 0>, 1 } sphere { <0.5, 0, 0>, 1 } }");
    ASSERT_EQ(s.objects.size(), 1u);
    const Hit h = shoot(s, {-5, 0, 0}, {1, 0, 0});
    EXPECT_NEAR(h.t, 4.5, 1e-9);  // the right sphere's surface, inside the left one
    EXPECT_TRUE(near(h.normal, {-1, 0, 0}));
    const Hit top = shoot(s, {0.1, 5, 0}, {0, -1, 0});
    EXPECT_NEAR(top.t, 5 - std::sqrt(1 - 0.36), 1e-9);  // the left sphere's surface, lower there
    EXPECT_FALSE(shoot(s, {1.2, 0, -5}, {0, 0, 1}).valid());  // only in the right sphere
    EXPECT_EQ(allHits(s, {-5, 0, 0}, {1, 0, 0}).size(), 2u);
}

TEST(PovCsgHits, NestedCsgFollowsEachLevelsTransforms) {
    // A box with a hole (the cylinder scaled twice: radius 0.5), turned and moved, cut by a sphere.
    const Scene s = build(
        "intersection {\n"
        "  difference { box { -1, 1 } cylinder { <0, 0, -2>, <0, 0, 2>, 0.25 scale <2, 2, 1> } rotate 90*y }\n"
        "  sphere { 0, 1.2 }\n"
        "  translate <3, 0, 0>\n"
        "}");
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_FALSE(shoot(s, {-5, 0, 0}, {1, 0, 0}).valid());  // the hole now runs along x
    EXPECT_FALSE(shoot(s, {-5, 0.4, 0}, {1, 0, 0}).valid());  // the hole is 0.5 wide
    // Beside the hole the box face at x = 2 is inside the sphere only within 0.663 of the axis.
    const Hit face = shoot(s, {-5, 0.6, 0}, {1, 0, 0});
    EXPECT_NEAR(face.t, 7, 1e-9);
    EXPECT_TRUE(near(face.normal, {-1, 0, 0}));
    const Hit rim = shoot(s, {-5, 0.7, 0}, {1, 0, 0});
    EXPECT_NEAR(rim.t, 8 - std::sqrt(1.44 - 0.49), 1e-9);
    EXPECT_TRUE(near(rim.normal, normalize(Vec3{-std::sqrt(1.44 - 0.49), 0.7, 0})));
}

TEST(PovCsgHits, ABarWithEightHolesTestsItsLeavesBoxes) {
    // Nine leaves, each tried only where the ray meets its window (Csg::leafWindow).
    const Scene s = build(
        "difference { box { <-5, -1, -1>, <5, 1, 1> }\n"
        "  #for (i, 0, 7) cylinder { <-4 + i * 1.1, -2, 0>, <-4 + i * 1.1, 2, 0>, 0.3 } #end }");
    ASSERT_EQ(s.objects.size(), 1u);
    ASSERT_EQ(s.objects[0].csg->leaves.size(), 9u);
    for (int i = 0; i < 8; ++i) {
        const double x = -4 + i * 1.1;
        EXPECT_FALSE(shoot(s, {x + 0.2, 5, 0}, {0, -1, 0}).valid()) << i;  // through hole i
        EXPECT_NEAR(shoot(s, {x + 0.55, 5, 0}, {0, -1, 0}).t, 4, 1e-9) << i;  // the bar between holes
        const Hit wall = shoot(s, {x, 0, 0}, {1, 0, 0});  // from the hole's axis into its wall
        EXPECT_NEAR(wall.t, 0.3, 1e-9) << i;
        EXPECT_TRUE(near(wall.normal, {-1, 0, 0})) << i;  // facing into the hole
    }
}

// Random CSG trees (intersection, difference and merge, three levels deep, of spheres, boxes,
// cylinders, cones and tori, each turned, scaled and moved) against dense steps along random rays,
// judged by the trees' inside test alone: wherever a step finds a point inside, the nearest hit
// is found, at or before it and after the last step outside. The hit search solves each leaf
// only within its ancestors' bounds and inside convex clippers (Csg::leafWindow); this is its
// brute-force check.
std::string randomLeaf(std::mt19937& rng) {
    std::uniform_real_distribution<double> U(-1, 1);
    auto num = [&](double lo, double hi) { return std::to_string(lo + (hi - lo) * 0.5 * (U(rng) + 1)); };
    auto vec = [&](double r) { return "<" + num(-r, r) + ", " + num(-r, r) + ", " + num(-r, r) + ">"; };
    std::string leaf;
    switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
        case 0: leaf = "sphere { " + vec(0.5) + ", " + num(0.4, 1.2) + " }"; break;
        case 1: leaf = "box { " + vec(0.3) + " - 0.6, " + vec(0.3) + " + 0.6 }"; break;
        case 2: leaf = "cylinder { " + vec(1) + ", " + vec(1) + ", " + num(0.2, 0.6) + " }"; break;
        case 3: leaf = "cone { " + vec(1) + ", " + num(0.1, 0.7) + ", " + vec(1) + ", " + num(0, 0.5) + " }"; break;
        default: leaf = "torus { " + num(0.5, 1) + ", " + num(0.1, 0.4) + " }"; break;
    }
    return "object { " + leaf + " rotate " + vec(90) + " scale <" + num(0.7, 1.3) + ", " + num(0.7, 1.3) + ", " +
           num(0.7, 1.3) + "> translate " + vec(0.6) + " }";
}

std::string randomTree(std::mt19937& rng, int depth) {
    if (depth == 0) return randomLeaf(rng);
    static const char* kOps[] = {"intersection", "difference", "merge"};
    const char* op = kOps[std::uniform_int_distribution<int>(0, 2)(rng)];
    const int n = std::uniform_int_distribution<int>(2, 3)(rng);
    std::string t = std::string(op) + " { ";
    for (int i = 0; i < n; ++i) t += randomTree(rng, std::uniform_int_distribution<int>(0, depth - 1)(rng)) + " ";
    return t + "rotate <" + std::to_string(30 * depth) + ", 10, 0> }";
}

TEST(PovCsgHits, RandomTreesAgreeWithDenseInsideSteps) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> U(-1, 1);
    int checked = 0;
    for (int tree = 0; tree < 40; ++tree) {
        const std::string text = randomTree(rng, 3);
        // A merge of opaque parts may come out as its parts, an intersection of parts whose
        // bounds do not meet as nothing.
        const Scene s = build(text);
        auto inside = [&](Vec3 q) {
            for (const Object& o : s.objects)
                if (insideShape(o, q) == 1) return true;
            return false;
        };
        for (int i = 0; i < 60; ++i) {
            const Vec3 from = 6.0 * normalize(Vec3{U(rng), U(rng), U(rng)});
            const Vec3 d = normalize(Vec3{1.5 * U(rng), 1.5 * U(rng), 1.5 * U(rng)} - from);
            const double step = 2e-3;
            for (double t = 6 - 4; t < 6 + 4; t += step) {
                if (!inside(from + t * d)) continue;
                ++checked;
                const Hit h = shoot(s, from, d);
                ASSERT_TRUE(h.valid()) << text << "\nray " << i << " inside at " << t;
                EXPECT_LE(h.t, t + 1e-9) << text << "\nray " << i;
                EXPECT_GE(h.t, t - step - 1e-9) << text << "\nray " << i;
                break;
            }
        }
    }
    EXPECT_GT(checked, 300);
}

// CSG trees of many leaves and wide nodes (a union of 300 spheres subtracted from a box, a merge
// of 200 spheres cut by a sphere, a box less 150 cylinders) use box trees over their leaves and
// over the wide nodes' children (csg_box_tree.h); the same trees without them test every leaf
// and child one by one, as small trees do: both must find the same hits, normals and insides.
TEST(PovCsgHits, WideTreesAgreeWithTheirLeavesTestedOneByOne) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(-1, 1);
    auto spheres = [&](int n, double spread) {
        std::string t;
        for (int i = 0; i < n; ++i)
            t += "sphere { <" + std::to_string(spread * U(rng)) + ", " + std::to_string(spread * U(rng)) + ", " +
                 std::to_string(spread * U(rng)) + ">, " + std::to_string(0.55 + 0.25 * U(rng)) + " }\n";
        return t;
    };
    std::string cylinders;
    for (int i = 0; i < 150; ++i)
        cylinders += "cylinder { <" + std::to_string(5 * U(rng)) + ", -6, " + std::to_string(5 * U(rng)) + ">, <" +
                     std::to_string(5 * U(rng)) + ", 6, " + std::to_string(5 * U(rng)) + ">, 0.2 }\n";
    const std::string scenes[] = {
        "difference { box { -5, 5 } union { " + spheres(300, 6) + "} }",
        "intersection { sphere { 0, 5 } merge { " + spheres(200, 5) + "} }",
        "difference { box { -5, 5 } " + cylinders + "}",
    };
    int hits = 0;
    for (const std::string& text : scenes) {
        const Scene s = build(text);
        ASSERT_EQ(s.objects.size(), 1u);
        const Csg& wide = *s.objects[0].csg;
        ASSERT_GT(wide.leaves.size(), size_t(kCsgCachedLeaves));
        ASSERT_FALSE(wide.leafTree.empty());
        ASSERT_FALSE(wide.childTrees.empty());
        Csg plain = wide;
        plain.leafTree = CsgBoxTree{};
        plain.childTree.clear();
        plain.childTrees.clear();
        for (int i = 0; i < 400; ++i) {
            const Vec3 q{6 * U(rng), 6 * U(rng), 6 * U(rng)};
            EXPECT_EQ(insideCsg(wide, 0, q), insideCsg(plain, 0, q)) << i;
            const Vec3 from = 12.0 * normalize(Vec3{U(rng), U(rng), U(rng)});
            const Ray ray{from, normalize(Vec3{4 * U(rng), 4 * U(rng), 4 * U(rng)} - from)};
            ShapeHit a, b;
            const bool ha = intersectCsg(wide, ray, 1e-9, kInfinity, &a);
            const bool hb = intersectCsg(plain, ray, 1e-9, kInfinity, &b);
            ASSERT_EQ(ha, hb) << i;
            EXPECT_EQ(intersectCsg(wide, ray, 1e-9, kInfinity, nullptr), ha) << i;
            if (!ha) continue;
            ++hits;
            EXPECT_NEAR(a.t, b.t, 1e-9) << i;
            EXPECT_TRUE(near(a.normal, b.normal)) << i;
        }
    }
    EXPECT_GT(hits, 600);
}

// A disc's inside is its plane's half-space away from the normal, unbounded by the radius
// (reference 3.4.5.2.2): desk.pov's paperweight, a sphere cut by a disc. The heights are POV-Ray
// 3.7's trace() from y = 50 straight down at x = 0 ... 8 (z = 0.01).
TEST(PovCsgHits, ADiscCutsLikeItsPlane) {
    const Scene s = build("intersection { sphere { <0, -5, 0>, 10 } disc { 0, -y, 10.1 } }");
    ASSERT_EQ(s.objects.size(), 1u);
    const double traced[9] = {5.0, 4.9499, 4.7980, 4.5394, 4.1651, 3.6602, 3.0, 2.1414, 1.0};
    for (int x = 0; x <= 8; ++x) {
        const Hit h = shoot(s, {double(x), 50, 0.01}, {0, -1, 0});
        ASSERT_TRUE(h.valid()) << x;
        EXPECT_NEAR(50 - h.t, traced[x], 1e-4) << x;
    }
    EXPECT_FALSE(shoot(s, {9, 50, 0.01}, {0, -1, 0}).valid());  // beyond the cap (POV-Ray: none)
    const Hit under = shoot(s, {2, -5, 0}, {0, 1, 0});           // the flat face, from below
    EXPECT_NEAR(under.t, 5, 1e-9);
    EXPECT_TRUE(near(under.normal, {0, -1, 0}));
    EXPECT_EQ(insideShape(s.objects[0], {0, 1, 0}), 1);
    EXPECT_EQ(insideShape(s.objects[0], {0, -1, 0}), 0);
    const Scene d = build("disc { 0, y, 1 }");
    EXPECT_EQ(insideShape(d.objects[0], {20, -1, 0}), 1);  // below, far beyond the radius
    EXPECT_EQ(insideShape(d.objects[0], {0, 1, 0}), 0);
}

TEST(PovCsgHits, UnionInsideCsgKeepsInnerSurfacesAndMergeRemovesThem) {
    const std::string spheres = "sphere { <-0.5, 0, 0>, 1 } sphere { <0.5, 0, 0>, 1 }";
    const Scene u = build("intersection { union { " + spheres + " } box { -10, 10 } }");
    const Scene m = build("merge { " + spheres + " pigment { rgbf <1, 1, 1, 0.5> } }");
    ASSERT_EQ(m.objects.size(), 1u);
    // An opaque merge looks as a union does from outside: its children are objects of their own,
    // when the camera read before it is outside it.
    EXPECT_EQ(build("camera { location <0, 0, -5> look_at 0 } merge { " + spheres + " }").objects.size(), 2u);
    EXPECT_EQ(allHits(u, {-5, 0, 0}, {1, 0, 0}).size(), 4u);
    const std::vector<double> merged = allHits(m, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(merged.size(), 2u);
    EXPECT_NEAR(merged[0], 3.5, 1e-9);
    EXPECT_NEAR(merged[1], 6.5, 1e-9);
}

// A camera inside an opaque merge sees only its outer boundary (POV-Ray 3.7, measured: from the
// centre of one of two overlapping spheres, the other's surface inside it does not show), so the
// merge keeps its tree where a camera ray may start inside it.
TEST(PovCsgHits, ACameraInsideAnOpaqueMergeSeesOnlyItsOuterBoundary) {
    const std::string merge = "merge { sphere { 0, 2 } sphere { <1.5, 0, 0>, 2 } pigment { rgb 1 } }";
    const Scene inside = build("camera { location 0 look_at z } " + merge);
    ASSERT_EQ(inside.objects.size(), 1u);
    EXPECT_NEAR(shoot(inside, {0, 0, 0}, {0, 0, 1}).t, 2, 1e-9);  // not the second sphere's 1.32
    // Read before any camera (the default one sits at the origin), or under an orthographic one or
    // focal blur: the tree stays.
    EXPECT_EQ(build(merge + " camera { location <0, 0, -10> look_at 0 }").objects.size(), 1u);
    EXPECT_EQ(build("camera { orthographic location <0, 0, -10> look_at 0 } " + merge).objects.size(), 1u);
    EXPECT_EQ(build("camera { location <0, 0, -10> look_at 0 aperture 0.1 focal_point 0 } " + merge).objects.size(), 1u);
    EXPECT_EQ(build("camera { location <0, 0, -10> look_at 0 } " + merge).objects.size(), 2u);
}

// POV-Ray 3.7, measured (a camera inside A looking through B, and a box with a union of two
// cylinders subtracted, seen into the hole they leave): a union inverted once or more hides its
// inner surfaces as a merge does; one that is not inverted shows them.
TEST(PovCsgHits, AnInvertedUnionHidesItsInnerSurfaces) {
    const std::string spheres = "sphere { <-0.4, 0, 0>, 1 } sphere { <0.4, 0, 0>, 1 }";
    // From inside A, along +x: B's near side (inside A) at t = 0.3, B's far side at t = 2.3.
    const Vec3 from{-0.9, 0, 0}, along{1, 0, 0};
    auto first = [&](const std::string& text) {
        const Hit h = shoot(build(text), from, along);
        return h.valid() ? h.t : -1.0;
    };
    EXPECT_NEAR(first("union { " + spheres + " inverse }"), 2.3, 1e-9);
    EXPECT_NEAR(first("difference { box { -2, 2 } union { " + spheres + " } }"), 2.3, 1e-9);
    EXPECT_NEAR(first("intersection { box { -2, 2 } union { " + spheres + " inverse } }"), 2.3, 1e-9);
    EXPECT_NEAR(first("object { union { " + spheres + " inverse } inverse }"), 2.3, 1e-9);  // twice
    EXPECT_NEAR(first("difference { box { -2, 2 } object { union { " + spheres + " } inverse } }"), 2.3, 1e-9);
    // Not inverted: the inner surface stays.
    EXPECT_NEAR(first("intersection { box { -2, 2 } union { " + spheres + " } }"), 0.3, 1e-9);
    EXPECT_NEAR(first("union { " + spheres + " }"), 0.3, 1e-9);
}

TEST(PovCsgHits, InverseTurnsASphereIntoAHoleWithInwardNormals) {
    const Scene s = build("intersection { sphere { 0, 2 } sphere { 0, 1 inverse } }");
    const std::vector<double> ts = allHits(s, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(ts.size(), 4u);
    EXPECT_NEAR(ts[1], 4, 1e-9);
    const Hit inner = Bvh(s.objects).closest(s.objects, Ray{{-5, 0, 0}, {1, 0, 0}}, 3.5, kInfinity);
    EXPECT_TRUE(near(inner.normal, {1, 0, 0}));  // the shell's outside there faces the hole
    // A whole CSG inverted: the same hits, the normals turned.
    const Scene d = build("difference { sphere { 0, 1 } box { 0, 2 } inverse }");
    EXPECT_TRUE(near(shoot(d, {-5, 0, 0}, {1, 0, 0}).normal, {1, 0, 0}));
}

TEST(PovCsgMaterials, ChildrenKeepTheirTexturesAndTheRestTakeTheCsgs) {
    const Scene s = build(
        "difference { sphere { 0, 1 } box { <-2, -2, -2>, <2, 2, 0> pigment { rgb <0, 1, 0> } }\n"
        "  pigment { rgb <0, 0, 1> } }");
    const Hit cut = shoot(s, {0.3, 0.2, -5}, {0, 0, 1});
    const Hit ball = shoot(s, {0, 0, 5}, {0, 0, -1});
    ASSERT_TRUE(cut.valid() && ball.valid());
    EXPECT_TRUE(near(shadedObject(s.objects, cut).material.color, {0, 1, 0}));
    EXPECT_TRUE(near(shadedObject(s.objects, ball).material.color, {0, 0, 1}));
}

// cutaway_textures (reference, "Cutaway Textures"; the images match POV-Ray 3.7's pixel for pixel
// on an intersection, a difference, patterned textures and a textured cutter): a surface of a
// child without a texture shows the texture of the textured child holding the point.
// POV-Ray 3.7, measured: a cut inside both a red box and a blue sphere shows (0.5, 0, 0.5), linear
// (the two textures averaged), and inside the sphere only, blue.
TEST(PovCsgMaterials, CutawayTexturesAverageTheTexturesOfEveryObjectCut) {
    const std::string text =
        "global_settings { assumed_gamma 1 }\n"
        "difference { intersection { box { -1, 1 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } }\n"
        "  sphere { 0, 1.3 pigment { rgb <0, 0, 1> } finish { ambient 1 diffuse 0 } } }\n"
        "  sphere { <0, 0, -1>, 0.8 } cutaway_textures }";
    const Scene s = build(text);
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    const Vec3 both = Tracer(s, bvh, rs).tracePrimary(Ray{{0.1, 0.1, -5}, {0, 0, 1}}, ctx);
    EXPECT_TRUE(near(both, {0.5, 0, 0.5}, 1e-6)) << both.x << " " << both.y << " " << both.z;
    const Hit h = shoot(s, {0.1, 0.1, -5}, {0, 0, 1});
    EXPECT_TRUE(h.cutawayBlend);
}

TEST(PovCsgMaterials, CutawayTexturesShowTheTextureOfTheObjectCut) {
    const std::string parts = "sphere { 0, 1 pigment { rgb <1, 0, 0> } } box { <-2, -2, -0.2>, <2, 2, 2> }";
    const Scene cut = build("intersection { " + parts + " cutaway_textures }");
    const Scene plain = build("intersection { " + parts + " }");
    const Hit a = shoot(cut, {0.1, 0.1, -5}, {0, 0, 1}), b = shoot(plain, {0.1, 0.1, -5}, {0, 0, 1});
    ASSERT_TRUE(a.valid() && b.valid());
    EXPECT_NEAR(a.t, 4.8, 1e-9);  // the box's face
    EXPECT_TRUE(near(shadedObject(cut.objects, a).material.color, {1, 0, 0}));
    EXPECT_TRUE(near(shadedObject(plain.objects, b).material.color, {0, 0, 0}));  // the default texture
    // A textured cutter keeps its own.
    const Scene own = build("difference { sphere { 0, 1 pigment { rgb <1, 0, 0> } } "
                            "box { <-2, -2, -2>, <2, 2, -0.2> pigment { rgb <0, 1, 0> } } cutaway_textures }");
    const Hit c = shoot(own, {0.1, 0.1, -5}, {0, 0, 1});
    ASSERT_TRUE(c.valid());
    EXPECT_TRUE(near(shadedObject(own.objects, c).material.color, {0, 1, 0}));
}

TEST(PovCsgBounds, IntersectionIsBoundedAndPlanesCutHalfSpaces) {
    const Scene s = build(
        "intersection { sphere { 0, 1 } plane { y, 0 } }\n"
        "difference { box { -1, 1 } sphere { 0, 5 } }\n"  // never seen: nothing remains? (kept: bounds are not exact)
        "difference { plane { y, 0 } sphere { 0, 1 } }\n"
        "intersection { box { 0, 1 } box { 2, 3 } }\n");  // empty bounds: left out
    ASSERT_EQ(s.objects.size(), 3u);
    const Bounds a = worldBounds(s.objects[0]);
    EXPECT_TRUE(near(a.lo, {-1, -1, -1}));
    EXPECT_TRUE(near(a.hi, {1, 0, 1}, 1e-7));  // the plane's inside reaches a little beyond it
    const Bounds b = worldBounds(s.objects[1]);
    EXPECT_TRUE(near(b.hi, {1, 1, 1}));  // the first child's
    const Bounds c = worldBounds(s.objects[2]);
    EXPECT_GT(c.hi.y, 1e-10);  // the plane's inside reaches 1e-10 beyond it, as POV-Ray's does
    EXPECT_LT(c.hi.y, 1e-7);
    EXPECT_TRUE(std::isinf(c.lo.y) && std::isinf(c.hi.x));
    const Hit h = shoot(s, {0.2, -5, 0}, {0, 1, 0});
    EXPECT_NEAR(h.t, 5 - std::sqrt(0.96), 1e-9);  // the half ball's underside
}

// POV-Ray 3.7 keeps a too-small bounded_by as a gate on the rays (measured: each kind under a
// bound covering a small part of it, with and without the bound): a ray that meets the bound
// anywhere sees the whole object, one that misses it sees nothing; spheres, boxes, planes, discs,
// blobs, polygons, triangles, meshes and height fields drop the bound.
TEST(PovCsgBounds, BoundedByGatesTheRaysOfTheKindsPovRayKeepsItFor) {
    const std::string bound = " bounded_by { box { <-0.3, -0.3, -2>, <0.3, 0.3, 2> } }";
    const Scene cyl = build("cylinder { -x, x, 0.6" + bound + " }");
    ASSERT_EQ(cyl.objects.size(), 1u);
    EXPECT_FALSE(shoot(cyl, {0.8, 0, -5}, {0, 0, 1}).valid());  // misses the bound
    const Hit through = shoot(cyl, {0.2, 0, -5}, {0, 0, 1});
    ASSERT_TRUE(through.valid());
    EXPECT_NEAR(through.t, 5 - 0.6, 1e-9);
    const Hit cap = shoot(cyl, {-5, 0, 0}, {1, 0, 0});  // meets the bound: the cap beyond it shows
    ASSERT_TRUE(cap.valid());
    EXPECT_NEAR(cap.t, 4, 1e-9);
    const Bvh bvh(cyl.objects);  // shadows too
    EXPECT_FALSE(bvh.any(cyl.objects, Ray{{0.8, 0, -5}, {0, 0, 1}}, 1e-9, 10));
    EXPECT_TRUE(bvh.any(cyl.objects, Ray{{0.2, 0, -5}, {0, 0, 1}}, 1e-9, 10));
    // The transformations after bounded_by move the bound, those before it do not.
    const Scene moved = build("cylinder { -x, x, 0.6" + bound + " translate 0.5*x }");
    EXPECT_TRUE(shoot(moved, {0.7, 0, -5}, {0, 0, 1}).valid());
    EXPECT_FALSE(shoot(moved, {0.1, 0, -5}, {0, 0, 1}).valid());
    // CSG kinds are gated; a sphere and a box drop the bound.
    EXPECT_FALSE(shoot(build("union { sphere { <-0.5, 0, 0>, 0.7 } sphere { <0.5, 0, 0>, 0.7 }" + bound + " }"),
                       {0.8, 0, -5}, {0, 0, 1}).valid());
    EXPECT_FALSE(shoot(build("difference { box { -0.8, 0.8 } sphere { 2, 0.1 }" + bound + " }"), {0.6, 0, -5},
                       {0, 0, 1}).valid());
    EXPECT_TRUE(shoot(build("sphere { 0, 1" + bound + " }"), {0.8, 0, -5}, {0, 0, 1}).valid());
    EXPECT_TRUE(shoot(build("box { -0.8, 0.8" + bound + " }"), {0.6, 0, -5}, {0, 0, 1}).valid());
}

TEST(PovCsgShadows, ShadowRaysPassThroughHolesOnly) {
    const Scene s = build("difference { box { -1, 1 } cylinder { <0, -2, 0>, <0, 2, 0>, 0.5 } }");
    const Bvh bvh(s.objects);
    EXPECT_FALSE(bvh.any(s.objects, Ray{{0.1, -5, 0}, {0, 1, 0}}, 1e-9, 10));
    EXPECT_TRUE(bvh.any(s.objects, Ray{{0.7, -5, 0}, {0, 1, 0}}, 1e-9, 10));
    EXPECT_FALSE(bvh.any(s.objects, Ray{{0.7, -5, 0}, {0, 1, 0}}, 1e-9, 3.9));  // before the box
}

TEST(PovCsgClip, ClippedByKeepsTheSurfaceInsideAndLeavesItOpen) {
    const Scene s = build("sphere { 0, 1 clipped_by { plane { y, 0 } } pigment { rgb 1 } }");
    ASSERT_EQ(s.objects.size(), 1u);
    const Hit down = shoot(s, {0, 5, 0}, {0, -1, 0});
    EXPECT_NEAR(down.t, 6, 1e-9);  // through the open top to the inside of the bottom
    EXPECT_TRUE(near(down.normal, {0, -1, 0}));  // the sphere's own normal
    EXPECT_NEAR(shoot(s, {0, -5, 0}, {0, 1, 0}).t, 4, 1e-9);
    // Transformations after clipped_by move the clip too; those before it do not.
    const Scene moved = build("sphere { 0, 1 clipped_by { plane { y, 0 } } translate <0, 0.5, 0> }");
    EXPECT_NEAR(shoot(moved, {-5, 0.25, 0}, {1, 0, 0}).t, 5 - std::sqrt(1 - 0.0625), 1e-9);
    const Scene before = build("sphere { 0, 1 translate <0, 0.5, 0> clipped_by { plane { y, 0 } } }");
    EXPECT_FALSE(shoot(before, {-5, 0.25, 0}, {1, 0, 0}).valid());
}

TEST(PovCsgClip, OpenCylindersHaveNoCaps) {
    const Scene s = build("cylinder { 0, y, 1 open }");
    EXPECT_FALSE(shoot(s, {0, 5, 0}, {0, -1, 0}).valid());
    EXPECT_NEAR(shoot(s, {-5, 0.5, 0}, {1, 0, 0}).t, 4, 1e-9);
    const Scene closed = build("cylinder { 0, y, 1 }");
    EXPECT_NEAR(shoot(closed, {0, 5, 0}, {0, -1, 0}).t, 4, 1e-9);
}

TEST(PovCsgNotes, CsgNeedingTheInsideOfAMeshIsLeftOutWithANote) {
    std::vector<std::string> warnings;
    const Scene s = build(
        "intersection { mesh { triangle { 0, x, y } } sphere { 0, 1 } }\n"
        "object { mesh { triangle { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> } } clipped_by { plane { y, 0 } } }",
        &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("intersection of triangles or meshes (left out)"), std::string::npos);
    ASSERT_EQ(s.objects.size(), 1u);  // a clipped mesh needs no inside
    EXPECT_FALSE(shoot(s, {0, 0.5, -5}, {0, 0, 1}).valid());
    EXPECT_NEAR(shoot(s, {0, -0.5, -5}, {0, 0, 1}).t, 5, 1e-9);
}

// A mesh with an inside_vector has an inside (crossings counted along the vector): CSG may cut it.
// The insides agree with POV-Ray's object pattern (tests/data/povray/object_patterns.pov).
TEST(PovCsgNotes, MeshesWithAnInsideVectorMayBeCut) {
    std::vector<std::string> warnings;
    const Scene s = build(
        "#declare A = <-1,-1,-1>; #declare B = <1.5,-1,-1>; #declare C = <0,1.5,-1>; #declare D = <0,0,1.5>;\n"
        "difference { mesh { triangle { A, B, C } triangle { A, B, D } triangle { B, C, D } triangle { C, A, D }\n"
        "  inside_vector <0.3, 0.2, 1> } sphere { <0, 0, -1>, 0.5 } }",
        &warnings);
    EXPECT_TRUE(warnings.empty());
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(insideShape(s.objects[0], {0, 0, 0}), 1);
    EXPECT_EQ(insideShape(s.objects[0], {0, 0, -0.8}), 0);   // in the sphere cut out
    EXPECT_EQ(insideShape(s.objects[0], {0, 0, 1.4}), 1);    // below the tip
    EXPECT_EQ(insideShape(s.objects[0], {0, 0, 1.6}), 0);    // above it
    // Along z the ray meets the sphere's dent (z = −0.5) instead of the face at z = −1.
    EXPECT_NEAR(shoot(s, {0, 0, -5}, {0, 0, 1}).t, 4.5, 1e-6);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

// A box with a sphere and a cylinder cut out, a lens and a clipped sphere over a floor; the
// pixels were measured from POV-Ray 3.7.0.10 (povray +W160 +H120 -D -A, written as PPM).
TEST(PovCsgRender, PixelsMatchPovRay) {
    const Scene s = build(
        "global_settings { assumed_gamma 1.0 }\n"
        "camera { location <0, 2, -6> look_at <0, 0.3, 0> angle 45 }\n"
        "light_source { <-5, 8, -6> color rgb 1 }\n"
        "plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } }\n"
        "difference {\n"
        "  box { -1, 1 pigment { rgb <0.9, 0.3, 0.2> } }\n"
        "  sphere { <0, 0, 0>, 1.3 pigment { rgb <0.2, 0.4, 0.9> } }\n"
        "  cylinder { <0, -2, 0>, <0, 2, 0>, 0.4 }\n"
        "  rotate 30*y translate <-1.2, 0, 0>\n"
        "  pigment { rgb <0.3, 0.9, 0.3> }\n"
        "}\n"
        "intersection {\n"
        "  sphere { <-0.5, 0, 0>, 1 } sphere { <0.5, 0, 0>, 1 }\n"
        "  pigment { rgb <0.9, 0.8, 0.2> }\n"
        "  rotate 90*y translate <1.6, 0, 0.5>\n"
        "}\n"
        "sphere { <0, 1.5, 1.5>, 0.6 clipped_by { plane { z, 1.5 } } pigment { rgb <0.8, 0.3, 0.8> } }\n");
    const ImageF img = test::renderPov(s);
    const test::PovPixel pixels[] = {
        {40, 75, {39, 56, 85}, "the sphere cut out of the box (its own blue, in shadow)"},
        {30, 60, {167, 167, 158}, "the floor through the hole the sphere cut in the front face"},
        {45, 80, {173, 104, 86}, "the box's red front face"},
        {35, 55, {176, 106, 88}, "the box's red front face, above the hole"},
        {110, 60, {197, 187, 99}, "the lens"},
        {120, 70, {170, 161, 84}, "the lens"},
        {80, 20, {165, 105, 165}, "the clipped sphere"},
    };
    test::expectPovPixels(img, pixels);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

TEST(PovCsgParseTime, InsideAndTraceAnswerForCsgObjects) {
    const Scene s = build(
        "#declare D = difference { sphere { 0, 1 } box { <-2, -2, -2>, <2, 2, 0> } }\n"
        "#if (inside(D, <0, 0, 0.5>)) sphere { <5, 0, 0>, 1 } #end\n"      // kept half: inside
        "#if (inside(D, <0, 0, -0.5>)) sphere { <-5, 0, 0>, 1 } #end\n"    // cut away: outside
        "#declare N = <0, 0, 0>;\n"
        "#declare P = trace(D, <0.3, 0.2, -5>, z, N);\n"
        "sphere { P + <0, 10, 0>, 0.5 }\n");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_TRUE(near(s.objects[0].p0, {5, 0, 0}));
    EXPECT_TRUE(near(s.objects[1].p0, {0.3, 10.2, 0}));  // the cut face at z = 0
}

// trace() and inside() need the shape only: an object whose look is anything (here a finish's
// subsurface) still answers; one whose shape is left out does not (<0, 0, 0>).
TEST(PovCsgParseTime, TraceAnswersWhateverTheTextureAndNotForShapesLeftOut) {
    std::vector<std::string> warnings;
    const Scene s = build(
        "#declare D = sphere { 0, 1 finish { subsurface { translucency 0.5 } } }\n"
        "#declare N = <0, 0, 0>;\n"
        "#declare P = trace(D, <0, 0, -5>, z, N);\n"
        "sphere { P + <0, 10, 0>, 0.5 }\n"
        "#declare H = height_field { sys \"x.sys\" }\n"
        "#declare Q = trace(H, <0.5, 5, 0.5>, -y, N);\n"
        "sphere { Q + <0, 20, 0>, 0.5 }\n",
        &warnings);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_TRUE(near(s.objects[0].p0, {0, 10, -1}));  // the sphere's front
    EXPECT_TRUE(near(s.objects[1].p0, {0, 20, 0}));   // no height field: <0, 0, 0>
    std::vector<std::string> traceNotes;
    for (const std::string& w : warnings)
        if (w.find("trace() of this object") != std::string::npos) traceNotes.push_back(w);
    ASSERT_EQ(traceNotes.size(), 1u);  // for the height field only (line 7, after #version)
    EXPECT_NE(traceNotes[0].find(":7:"), std::string::npos) << traceNotes[0];
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

ImageF renderSmall(const Scene& s) { return test::renderPov(s, 32, 24, 1); }

TEST(PovCsgShadows, LightPassesThroughATransparentChildOfAnOpaqueOnesCsg) {
    const std::string base =
        "camera { location <0, 1, -5> look_at 0 }\n"
        "light_source { <0, 10, 0> color rgb 1 }\n"
        "plane { y, 0 pigment { rgb 1 } }\n";
    const Scene open = build(base + "sphere { <-3, 2, 0>, 0.5 pigment { rgb 1 } }");
    // The first child is opaque, the one over the floor's middle lets all light through.
    const Scene glass = build(base + "merge { sphere { <-3, 2, 0>, 0.5 pigment { rgb 1 } }\n"
                                     "  sphere { <0, 2, 0>, 1 pigment { rgbf <1, 1, 1, 1> } } }");
    const Vec3 lit = renderSmall(open).at(16, 12), through = renderSmall(glass).at(16, 12);
    EXPECT_GT(lit.x, 0.5);
    EXPECT_NEAR(through.x, lit.x, 1e-6);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
