// Bvh on small scenes like the course's cornell.pov (a room of triangles, two transformed
// boxes): the triangle tree's hits carry the same numbers as intersect() (the flat normal is
// computed once at build), and an object tree without spheres (no reject test) finds the same
// nearest hits and blockers as testing every object.
#include <gtest/gtest.h>

#include <random>

#include "rays/accel/bvh.h"
#include "rays/scene/object.h"
#include "support/objects.h"

using namespace rays;
using rays::test::makeObject;

namespace { namespace RAYS_TEST_UNIT {

// A 10×10×10 room of 16 triangles (most of the scene: they go to the triangle tree) and two
// rotated, scaled boxes.
std::vector<Object> room() {
    std::vector<Object> o;
    auto quad = [&](Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
        o.push_back(makeObject(ShapeType::Triangle, a, b, c, 0, 0));
        o.push_back(makeObject(ShapeType::Triangle, a, c, d, 0, 0));
    };
    quad({-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5});
    quad({5, 0, 5}, {5, 10, 5}, {5, 10, -5}, {5, 0, -5});
    quad({-5, 0, 5}, {-5, 0, -5}, {-5, 10, -5}, {-5, 10, 5});
    quad({5, 10, -5}, {-5, 10, -5}, {-5, 0, -5}, {5, 0, -5});
    quad({-5, 10, 5}, {-5, 10, -5}, {-1, 10, -5}, {-1, 10, 5});
    quad({5, 10, 5}, {1, 10, 5}, {1, 10, -5}, {5, 10, -5});
    quad({-1, 10, 5}, {-1, 10, 1}, {1, 10, 1}, {1, 10, 5});
    quad({-1, 10, -1}, {-1, 10, -5}, {1, 10, -5}, {1, 10, -1});
    o.push_back(makeObject(ShapeType::Box, {-1, -1, -1}, {1, 1, 1}, {}, 0, 0,
                           Transform::translate({1.4, 1.5, 2.5}) * Transform::scale({1.5, 1.5, 1.5}) *
                               Transform::rotateCourse({0, -20, 0})));
    o.push_back(makeObject(ShapeType::Box, {-1, -1, -1}, {1, 1, 1}, {}, 0, 0,
                           Transform::translate({-1.9, 3, -1.5}) * Transform::scale({1.5, 3, 1.5}) *
                               Transform::rotateCourse({0, 20, 0})));
    return o;
}

Vec3 randomDirection(std::mt19937& rng) {
    std::normal_distribution<double> n;
    for (;;) {
        const Vec3 d{n(rng), n(rng), n(rng)};
        if (length(d) > 1e-3) return normalize(d);
    }
}

TEST(BvhSmallScene, NearestHitsAndBlockersAreThoseOfEveryObjectsExactTest) {
    const std::vector<Object> objects = room();
    const Bvh bvh(objects);
    ASSERT_EQ(bvh.triangleCount(), 16u);  // the room went to the triangle tree, the boxes did not
    std::mt19937 rng(28);
    std::uniform_real_distribution<double> u(-4.9, 4.9), h(0.1, 9.9), reach(0.1, 12);
    int boxHits = 0, triangleHits = 0, blocked = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray{{u(rng), h(rng), u(rng)}, randomDirection(rng)};
        Hit want;
        want.t = kInfinity;
        ShapeHit sh;
        for (size_t k = 0; k < objects.size(); ++k) {
            if (!intersect(objects[k], ray, 1e-9, want.t, sh)) continue;
            want.t = sh.t;
            want.object = int(k);
            want.normal = sh.normal;
            want.geomNormal = sh.geomNormal;
        }
        const Hit got = bvh.closest(objects, ray, 1e-9, kInfinity);
        ASSERT_EQ(got.object, want.object) << i;
        if (!want.valid()) continue;
        ASSERT_EQ(got.t, want.t) << i;  // bit for bit: the same formulas
        ASSERT_EQ(got.normal, want.normal) << i;
        ASSERT_EQ(got.geomNormal, want.geomNormal) << i;
        (objects[size_t(want.object)].type == ShapeType::Box ? boxHits : triangleHits)++;
        // A shadow ray of random length: blocked exactly when some object is within it.
        const double tEnd = reach(rng);
        bool any = false;
        for (const Object& o : objects) any = any || occludes(o, ray, 1e-9, tEnd);
        ASSERT_EQ(bvh.any(objects, ray, 1e-9, tEnd), any) << i;
        blocked += any;
    }
    EXPECT_GT(boxHits, 1000);
    EXPECT_GT(triangleHits, 10000);
    EXPECT_GT(blocked, 0);
}

// Shadow rays first check whether they cross any of the room's few planes (the triangle tree is
// walked only when one does): a segment that ends just past a wall is blocked by it, one that
// ends short of it is not (by more than the float tree's widening of the end), from inside and
// from outside the room, on every wall.
TEST(BvhSmallScene, ShadowRaysEndingAtAWallAreDecidedByTheWall) {
    const std::vector<Object> objects = room();
    const Bvh bvh(objects);
    struct Wall {
        Vec3 inside, normal;  // a point in the room in front of the wall, the wall's outward normal
        double dist;          // from that point to the wall
    };
    // Above the boxes (their tops are below y = 6), or beside them.
    const Wall walls[] = {{{-3, 8, -3}, {1, 0, 0}, 8}, {{3, 8, 3}, {-1, 0, 0}, 8}, {{-3, 8, 2}, {0, 0, -1}, 7},
                          {{-3, 4, 2}, {0, -1, 0}, 4}, {{-3, 8, 3}, {0, 1, 0}, 2}};
    for (const Wall& w : walls) {
        const Ray in{w.inside, w.normal};
        EXPECT_TRUE(bvh.any(objects, in, 1e-9, w.dist * (1 + 1e-9))) << w.normal.x << w.normal.y << w.normal.z;
        EXPECT_FALSE(bvh.any(objects, in, 1e-9, w.dist - 1e-4)) << w.normal.x << w.normal.y << w.normal.z;
        const Ray out{w.inside + (w.dist + 1) * w.normal, -w.normal};  // from outside, towards the room
        EXPECT_TRUE(bvh.any(objects, out, 1e-9, 1 + 1e-9)) << w.normal.x << w.normal.y << w.normal.z;
        EXPECT_FALSE(bvh.any(objects, out, 1e-9, 1 - 1e-4)) << w.normal.x << w.normal.y << w.normal.z;
    }
    // Through the ceiling's hole nothing blocks; beside it the ceiling does.
    EXPECT_FALSE(bvh.any(objects, Ray{{0, 9, 0}, {0, 1, 0}}, 1e-9, 5));
    EXPECT_TRUE(bvh.any(objects, Ray{{2, 9, 0}, {0, 1, 0}}, 1e-9, 5));
}

// A set of many planes (here, triangles tilted every way) leaves the plane check out: blockers are
// still found exactly as every object's own test finds them.
TEST(BvhSmallScene, ManyPlanesStillFindEveryBlocker) {
    std::vector<Object> objects;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-5, 5);
    for (int i = 0; i < 40; ++i) {
        const Vec3 c{u(rng), u(rng), u(rng)};
        objects.push_back(makeObject(ShapeType::Triangle, c, c + Vec3{u(rng), u(rng), 0} * 0.3,
                                     c + Vec3{0, u(rng), u(rng)} * 0.3, 0, 0));
    }
    const Bvh bvh(objects);
    ASSERT_EQ(bvh.triangleCount(), 40u);
    int blocked = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray{{u(rng), u(rng), u(rng)}, randomDirection(rng)};
        bool any = false;
        for (const Object& o : objects) any = any || occludes(o, ray, 1e-9, 8);
        ASSERT_EQ(bvh.any(objects, ray, 1e-9, 8), any) << i;
        blocked += any;
    }
    EXPECT_GT(blocked, 100);
}

// With a few objects, a ray is checked against each one's world box before its exact test: rays
// that run exactly in the plane of a box face (a zero direction component, 0 · ∞ in the slab
// test) must still find what the exact tests find.
TEST(BvhSmallScene, RaysInTheirBoxesFacePlanesAreNotRejected) {
    std::vector<Object> objects;
    objects.push_back(makeObject(ShapeType::Box, {-1, -1, -1}, {1, 1, 1}, {}, 0, 0, Transform{}));
    objects.push_back(makeObject(ShapeType::Sphere, {}, {4, 0, 0}, {}, 0, 1));
    const Bvh bvh(objects);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-3, 3);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        // Origin on a face plane of the box or of the sphere's box, direction in that plane.
        Vec3 o{u(rng), u(rng), -5}, d{u(rng), u(rng), 0};
        const double planes[] = {-1, 1, 5, 3};
        const int axis = i % 2;
        o[axis] = planes[(i / 2) % 4];
        d[axis] = 0;
        d.z = 1;
        const Ray ray{o, normalize(d)};
        Hit want;
        want.t = kInfinity;
        ShapeHit sh;
        for (size_t k = 0; k < objects.size(); ++k)
            if (intersect(objects[k], ray, 1e-9, want.t, sh)) want.t = sh.t, want.object = int(k);
        const Hit got = bvh.closest(objects, ray, 1e-9, kInfinity);
        ASSERT_EQ(got.object, want.object) << i;
        bool any = false;
        for (const Object& ob : objects) any = any || occludes(ob, ray, 1e-9, 20);
        ASSERT_EQ(bvh.any(objects, ray, 1e-9, 20), any) << i;
        hits += want.valid();
    }
    EXPECT_GT(hits, 100);
}

}}  // namespace RAYS_TEST_UNIT, namespace
