#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "rays/accel/bvh.h"
#include "rays/math/abs_power.h"
#include "rays/scene/object.h"
#include "support/objects.h"

using namespace rays;
using rays::test::makeObject;
using rays::test::sphere;

namespace { namespace RAYS_TEST_UNIT {

void expectVec(Vec3 a, Vec3 b, double eps = 1e-9) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(Geometry, SphereHitFromOutsideAndInside) {
    const Object s = sphere({0, 0, 0}, 2);
    ShapeHit h;
    ASSERT_TRUE(intersect(s, Ray{{0, 0, 14}, {0, 0, -1}}, 1e-6, kInfinity, h));
    EXPECT_DOUBLE_EQ(h.t, 12);
    expectVec(h.normal, {0, 0, 1});
    ASSERT_TRUE(intersect(s, Ray{{0, 0, 0}, {1, 0, 0}}, 1e-6, kInfinity, h));
    EXPECT_DOUBLE_EQ(h.t, 2);
    expectVec(h.normal, {1, 0, 0});  // outward even from inside
    EXPECT_FALSE(intersect(s, Ray{{0, 3, 14}, {0, 0, -1}}, 1e-6, kInfinity, h));
    EXPECT_FALSE(intersect(s, Ray{{0, 0, 14}, {0, 0, -1}}, 1e-6, 11.0, h));  // beyond tMax
}

TEST(Geometry, PlaneUsesNormalAndDistance) {
    const Object p = makeObject(ShapeType::Plane, {0, 1, 0}, {}, {}, -4, 0);
    ShapeHit h;
    ASSERT_TRUE(intersect(p, Ray{{0, 0, 0}, {0, -1, 0}}, 1e-6, kInfinity, h));
    EXPECT_DOUBLE_EQ(h.t, 4);
    expectVec(h.normal, {0, 1, 0});
    EXPECT_FALSE(intersect(p, Ray{{0, 0, 0}, {1, 0, 0}}, 1e-6, kInfinity, h));  // parallel
}

TEST(Geometry, TriangleInsideEdgesAndOutside) {
    const Object t = makeObject(ShapeType::Triangle, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 0);
    ShapeHit h;
    ASSERT_TRUE(intersect(t, Ray{{0.25, 0.25, 5}, {0, 0, -1}}, 1e-6, kInfinity, h));
    EXPECT_DOUBLE_EQ(h.t, 5);
    expectVec(h.normal, {0, 0, 1});
    EXPECT_FALSE(intersect(t, Ray{{0.75, 0.75, 5}, {0, 0, -1}}, 1e-6, kInfinity, h));
    EXPECT_FALSE(intersect(t, Ray{{-0.1, 0.5, 5}, {0, 0, -1}}, 1e-6, kInfinity, h));
}

TEST(Geometry, SmoothTriangleInterpolatesNormals) {
    Object t = makeObject(ShapeType::Triangle, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 0);
    t.smooth = true;
    t.n0 = normalize(Vec3{-1, 0, 1});
    t.n1 = normalize(Vec3{1, 0, 1});
    t.n2 = normalize(Vec3{0, 0, 1});
    ShapeHit h;
    ASSERT_TRUE(intersect(t, Ray{{0.5, 0.0, 5}, {0, 0, -1}}, 1e-6, kInfinity, h));
    // Halfway between n0 and n1, and on the side POV-Ray calls inner for smooth triangles (the
    // normals' side is the outer one, whatever the winding): both normals turned there.
    expectVec(h.normal, {0, 0, -1});
    expectVec(h.geomNormal, {0, 0, -1});
}

TEST(Geometry, BoxFacesAndInside) {
    const Object b = makeObject(ShapeType::Box, {-1, -2, -3}, {1, 2, 3}, {}, 0, 0);
    ShapeHit h;
    ASSERT_TRUE(intersect(b, Ray{{0, 0, 10}, {0, 0, -1}}, 1e-6, kInfinity, h));
    EXPECT_DOUBLE_EQ(h.t, 7);
    expectVec(h.normal, {0, 0, 1});
    ASSERT_TRUE(intersect(b, Ray{{0, 0, 0}, {0, 1, 0}}, 1e-6, kInfinity, h));
    EXPECT_DOUBLE_EQ(h.t, 2);
    expectVec(h.normal, {0, 1, 0});
    ASSERT_TRUE(intersect(b, Ray{{-5, 0, 0}, {1, 0, 0}}, 1e-6, kInfinity, h));
    expectVec(h.normal, {-1, 0, 0});
    EXPECT_FALSE(intersect(b, Ray{{5, 5, 5}, {0, 0, -1}}, 1e-6, kInfinity, h));
}

TEST(Geometry, ConeSideAndCaps) {
    // Cone along −z from base (0,0,1) radius 2 to apex (0,0,−3).
    const Object c = makeObject(ShapeType::Cone, {0, 0, 1}, {0, 0, -3}, {}, 2, 0);
    ShapeHit h;
    // Down the axis from +z: hits the base cap at z = 1.
    ASSERT_TRUE(intersect(c, Ray{{0, 0, 10}, {0, 0, -1}}, 1e-6, kInfinity, h));
    EXPECT_NEAR(h.t, 9, 1e-9);
    expectVec(h.normal, {0, 0, 1});
    // From the side at z = −1 (radius 1 there): hits x = −1.
    ASSERT_TRUE(intersect(c, Ray{{-10, 0, -1}, {1, 0, 0}}, 1e-6, kInfinity, h));
    EXPECT_NEAR(h.t, 9, 1e-9);
    // Surface x² + y² = ((z + 3)/2)²: gradient at (−1, 0, −1) is (2x, 2y, −2r·½) = (−2, 0, −1).
    const Vec3 expected = normalize(Vec3{-2, 0, -1});
    expectVec(h.normal, expected, 1e-9);
    // Misses beyond the apex.
    EXPECT_FALSE(intersect(c, Ray{{-10, 0, -3.5}, {1, 0, 0}}, 1e-6, kInfinity, h));
}

TEST(Geometry, NonUniformScaleUsesInverseTransposeNormals) {
    // Unit sphere scaled to an ellipsoid with semi-axes (2, 1, 1).
    const Object e = sphere({0, 0, 0}, 1, Transform::scale({2, 1, 1}));
    ShapeHit h;
    ASSERT_TRUE(intersect(e, Ray{{10, 0, 0}, {-1, 0, 0}}, 1e-6, kInfinity, h));
    EXPECT_NEAR(h.t, 8, 1e-12);  // world t: the direction is not renormalised
    // At (√2, √2/2, 0) on x²/4 + y² = 1 the normal ∝ (x/4, y) = (√2/4, √2/2).
    const Vec3 p{std::sqrt(2.0), std::sqrt(2.0) / 2, 0};
    const Vec3 dir = normalize(Vec3{std::sqrt(2.0) / 4, std::sqrt(2.0) / 2, 0});
    ASSERT_TRUE(intersect(e, Ray{p + 3.0 * dir, -dir}, 1e-6, kInfinity, h));
    EXPECT_NEAR(h.t, 3, 1e-9);
    expectVec(h.normal, dir, 1e-9);
}

TEST(Geometry, TransformedBoundsContainTheShape) {
    const Transform m = Transform::translate({3, 2, -3}) * Transform::rotateCourse({45, 0, 10.5}) *
                        Transform::scale({10, 3.5, 3.5});
    const Object e = sphere({0, 0, 0}, 0.5, m);
    const Bounds b = worldBounds(e);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 d = normalize(Vec3{u(rng), u(rng), u(rng)});
        const Vec3 p = m.point(0.5 * d);
        for (int a = 0; a < 3; ++a) {
            EXPECT_GE(p[a], b.lo[a] - 1e-9);
            EXPECT_LE(p[a], b.hi[a] + 1e-9);
        }
    }
}

// The nearest hit by testing every object (t and object only).
Hit bruteForceClosest(const std::vector<Object>& objects, const Ray& ray, double tMin) {
    Hit brute;
    ShapeHit sh;
    for (size_t k = 0; k < objects.size(); ++k)
        if (intersect(objects[k], ray, tMin, brute.t, sh)) {
            brute.t = sh.t;
            brute.object = int(k);
        }
    return brute;
}

TEST(Bvh, MatchesBruteForceOnRandomRays) {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-10, 10), r(0.05, 1.0), ang(0, 360);
    std::vector<Object> objects;
    for (int i = 0; i < 600; ++i) {
        const Vec3 c{u(rng), u(rng), u(rng)};
        switch (i % 5) {
            case 0: objects.push_back(sphere(c, r(rng))); break;
            case 1:
                objects.push_back(makeObject(ShapeType::Triangle, c, c + Vec3{r(rng), 0, 0}, c + Vec3{0, r(rng), r(rng)}, 0, 0));
                break;
            case 2:
                objects.push_back(makeObject(ShapeType::Box, c, c + Vec3{r(rng), r(rng), r(rng)}, {}, 0, 0,
                                             Transform::rotateCourse({ang(rng), ang(rng), 0})));
                break;
            case 3:
                objects.push_back(makeObject(ShapeType::Cone, c, c + Vec3{0, r(rng), r(rng)}, {}, r(rng), 0));
                break;
            default:
                objects.push_back(sphere({0, 0, 0}, 1, Transform::translate(c) * Transform::scale({r(rng), 0.3, 0.7})));
        }
    }
    objects.push_back(makeObject(ShapeType::Plane, normalize(Vec3{0.1, 1, 0}), {}, {}, -12, 0));
    const Bvh bvh(objects);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray{{u(rng), u(rng), u(rng)}, normalize(Vec3{u(rng), u(rng), u(rng)})};
        const Hit brute = bruteForceClosest(objects, ray, 1e-6);
        const Hit fast = bvh.closest(objects, ray, 1e-6, kInfinity);
        ASSERT_EQ(fast.object, brute.object) << "ray " << i;
        if (brute.valid()) {
            ++hits;
            EXPECT_DOUBLE_EQ(fast.t, brute.t);
            // Triangles are tested in float: near the ray origin (coordinates up to 10 here) the
            // interval ends are only good to about 1e-5, so tiny distances are left out.
            if (brute.t > 1e-2) {
                EXPECT_TRUE(bvh.any(objects, ray, 1e-6, brute.t * (1 + 1e-5))) << "ray " << i;
                EXPECT_FALSE(bvh.any(objects, ray, 1e-6, brute.t * 0.999)) << "ray " << i;
            }
        } else {
            EXPECT_FALSE(bvh.any(objects, ray, 1e-6, kInfinity));
        }
    }
    EXPECT_GT(hits, 5000);  // the test exercises real hits
}

// The object BVH rejects leaf slots with a single-precision bounding-sphere test: it must never
// reject a sphere the exact test hits, also for rays that graze a sphere, start on one (shadow and
// reflection rays), start far away, or have unnormalised directions, in a scene far from the origin.
TEST(Bvh, SphereRejectTestNeverLosesAHit) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1), r(0.01, 2.0), scaleExp(-3, 3);
    const Vec3 offset{1000, -2000, 500};
    std::vector<Object> objects;
    for (int i = 0; i < 3000; ++i)
        objects.push_back(sphere(offset + 40.0 * Vec3{u(rng), u(rng), u(rng)}, r(rng),
                                 i % 3 == 0 ? Transform::scale(Vec3(1.5)) : Transform{}));
    const Bvh bvh(objects);
    auto randomUnit = [&] {
        for (;;) {
            const Vec3 v{u(rng), u(rng), u(rng)};
            if (dot(v, v) > 0.01 && dot(v, v) <= 1) return normalize(v);
        }
    };
    int hits = 0, grazing = 0;
    for (int i = 0; i < 30000; ++i) {
        const Object& target = objects[size_t(rng() % objects.size())];
        const Vec3 c = target.p1;
        const double radius = target.r1;
        Vec3 dir = randomUnit();
        Vec3 origin;
        switch (i % 3) {
            case 0: origin = offset + 60.0 * Vec3{u(rng), u(rng), u(rng)}; break;
            case 1: {  // on the target's surface, offset along the normal like a secondary ray
                const Vec3 n = randomUnit();
                origin = c + radius * n + 1e-4 * n;
                if (dot(dir, n) < 0) dir = -dir;
                break;
            }
            default: {  // tangent to the target, up to a relative 1e-9 inside or outside
                Vec3 side = normalize(cross(dir, randomUnit()));
                origin = c + radius * (1 + 1e-9 * u(rng)) * side - 30.0 * dir;
                ++grazing;
            }
        }
        const Ray ray{origin, dir * std::pow(10.0, scaleExp(rng))};
        const Hit brute = bruteForceClosest(objects, ray, 1e-9);
        const Hit fast = bvh.closest(objects, ray, 1e-9, kInfinity);
        ASSERT_EQ(fast.object, brute.object) << "ray " << i;
        bool blocked = false;
        for (size_t k = 0; k < objects.size() && !blocked; ++k) blocked = occludes(objects[k], ray, 1e-9, kInfinity);
        ASSERT_EQ(bvh.any(objects, ray, 1e-9, kInfinity), blocked) << "ray " << i;
        if (brute.valid()) {
            ++hits;
            EXPECT_EQ(fast.t, brute.t);
            EXPECT_TRUE(bvh.any(objects, ray, 1e-9, std::nextafter(brute.t, kInfinity))) << "ray " << i;
        }
    }
    EXPECT_GT(hits, 12000);
    EXPECT_GT(grazing, 9000);
}

// occludes() and the BVH's closest hit test spheres and world-space triangles without computing
// normals until the final hit; both must agree with intersect() exactly: the same verdict for
// every interval, the same t and the same normals (flat and smooth triangles, spheres).
TEST(Bvh, NormalsForTheFinalHitOnlyMatchIntersect) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    auto point = [&] { return Vec3{u(rng), u(rng), u(rng)}; };
    std::vector<Object> objects;
    for (int i = 0; i < 40; ++i) {  // fewer than 64 triangles: they go into the object BVH
        Object t = makeObject(ShapeType::Triangle, 3.0 * point(), 3.0 * point(), 3.0 * point(), 0, 0);
        if (i % 2) {
            t.smooth = true;
            t.n0 = normalize(point() + Vec3{0, 0, 2});
            t.n1 = normalize(point() + Vec3{0, 0, 2});
            t.n2 = normalize(point() + Vec3{0, 0, 2});
        }
        objects.push_back(t);
    }
    for (int i = 0; i < 40; ++i) objects.push_back(sphere(3.0 * point(), 0.1 + 0.4 * (u(rng) + 1)));
    const Bvh bvh(objects);
    int hits = 0, blocked = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray{5.0 * point(), normalize(point())};
        const double tMax = i % 2 ? kInfinity : 4 * (u(rng) + 1);
        for (const Object& o : objects) {
            ShapeHit h;
            const bool hit = intersect(o, ray, 1e-9, tMax, h);
            ASSERT_EQ(occludes(o, ray, 1e-9, tMax), hit) << "ray " << i;
            blocked += hit;
        }
        const Hit brute = bruteForceClosest(objects, ray, 1e-9);
        const Hit fast = bvh.closest(objects, ray, 1e-9, kInfinity);
        ASSERT_EQ(fast.object, brute.object) << "ray " << i;
        if (!brute.valid()) continue;
        ++hits;
        ShapeHit h;
        ASSERT_TRUE(intersect(objects[size_t(brute.object)], ray, 1e-9, kInfinity, h));
        EXPECT_EQ(fast.t, h.t);
        EXPECT_EQ(fast.normal.x, h.normal.x);
        EXPECT_EQ(fast.normal.y, h.normal.y);
        EXPECT_EQ(fast.normal.z, h.normal.z);
        EXPECT_EQ(fast.geomNormal.x, h.geomNormal.x);
        EXPECT_EQ(fast.geomNormal.y, h.geomNormal.y);
        EXPECT_EQ(fast.geomNormal.z, h.geomNormal.z);
    }
    EXPECT_GT(hits, 4000);
    EXPECT_GT(blocked, 5000);
}

TEST(Bvh, EmptyAndCoincidentCentroids) {
    std::vector<Object> none;
    const Bvh empty(none);
    EXPECT_FALSE(empty.closest(none, Ray{{0, 0, 0}, {0, 0, 1}}, 1e-6, kInfinity).valid());
    // 100 identical spheres: every split degenerates; traversal must still work.
    std::vector<Object> same(100, sphere({0, 0, 0}, 1));
    const Bvh bvh(same);
    const Hit h = bvh.closest(same, Ray{{0, 0, 5}, {0, 0, -1}}, 1e-6, kInfinity);
    ASSERT_TRUE(h.valid());
    EXPECT_DOUBLE_EQ(h.t, 4);
}

TEST(AbsPower, MatchesPowForWholeHalfAndOtherExponents) {
    // Whole exponents by squaring, whole-and-a-half ones with a square root, others by exp2·log2:
    // all within a few ulps of std::pow of |x|, zero included.
    for (const double k : {0.0, 0.5, 1.0, 2.0, 2.5, 3.0, 7.5, 40.0, 64.0, 1.7, 0.3, 65.0, 2.0 / 0.8}) {
        const AbsPower p(k);
        for (const double x : {0.0, 1e-3, 0.37, -0.37, 1.0, 1.5, -2.25, 7.0}) {
            const double want = std::pow(std::fabs(x), k);
            EXPECT_NEAR(p(x), want, 1e-13 * std::max(1.0, want)) << k << " " << x;
        }
    }
    EXPECT_EQ(AbsPower(2.5).whole, 2);
    EXPECT_TRUE(AbsPower(2.5).half);
    EXPECT_EQ(AbsPower(3).whole, 3);
    EXPECT_FALSE(AbsPower(3).half);
    EXPECT_EQ(AbsPower(1.7).whole, -1);
}

}}  // namespace RAYS_TEST_UNIT, namespace
