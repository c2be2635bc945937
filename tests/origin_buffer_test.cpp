// OriginBuffer (accel/origin_buffer.h): the candidate lists for rays from a
// pinhole eye and for shadow rays towards a point light must give exactly the
// BVH's answers (they only choose which exact tests run), for every kind of
// bounded object, origins inside or touching objects, and big flat objects; and
// they must actually be selective.
#include "rays/accel/origin_buffer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "rays/accel/bvh.h"
#include "rays/io/scene_parser.h"
#include "rays/render/renderer.h"
#include "rays/render/tracer.h"
#include "rays/scene/object.h"
#include "support/objects.h"

using namespace rays;
using rays::test::makeObject;
using rays::test::sphere;

namespace { namespace RAYS_TEST_UNIT {

// Every kind of bounded object, some of them big or flat, around the origin; a
// plane too. With manyTriangles the triangles go to the BVH's triangle tree (64
// or more), else into the buffers.
std::vector<Object> mixedScene(std::mt19937& rng, bool manyTriangles) {
    std::uniform_real_distribution<double> u(-6, 6), r(0.02, 0.8), ang(0, 360);
    std::vector<Object> objects;
    for (int i = 0; i < 900; ++i) {
        const Vec3 c{u(rng), u(rng), u(rng)};
        switch (i % 6) {
            case 0:
            case 1:
                objects.push_back(sphere(c, r(rng)));
                break;
            case 2:
                if (!manyTriangles && i % 36 != 2) {
                    objects.push_back(sphere(c, r(rng)));
                    break;
                }
                objects.push_back(
                    makeObject(ShapeType::Triangle, c, c + Vec3{r(rng), 0, 0}, c + Vec3{0, r(rng), r(rng)}, 0, 0));
                break;
            case 3:
                objects.push_back(makeObject(ShapeType::Box, c, c + Vec3{r(rng), r(rng), r(rng)}, {}, 0, 0,
                                             Transform::rotateCourse({ang(rng), ang(rng), 0})));
                break;
            case 4:
                objects.push_back(makeObject(ShapeType::Cone, c, c + Vec3{0, r(rng), r(rng)}, {}, r(rng), 0));
                break;
            default:  // an ellipsoid (tested in its own space) and a rotated, scaled-up
                      // sphere
                objects.push_back(sphere({0, 0, 0}, 1, Transform::translate(c) * Transform::scale({r(rng), 0.3, 0.7})));
        }
    }
    // Big ones: a floor of two triangles under everything, a sphere the size of
    // the scene's half.
    objects.push_back(makeObject(ShapeType::Triangle, {-40, -7, -40}, {40, -7, -40}, {40, -7, 40}, 0, 0));
    objects.push_back(makeObject(ShapeType::Triangle, {-40, -7, -40}, {40, -7, 40}, {-40, -7, 40}, 0, 0));
    objects.push_back(sphere({9, 2, -3}, 4));
    // Things just below the floor: a ray that meets the floor first often meets
    // them right after.
    std::uniform_real_distribution<double> near(-3, 3);
    for (int i = 0; i < 60; ++i) objects.push_back(sphere({near(rng), -7.27, near(rng)}, 0.25));
    objects.push_back(makeObject(ShapeType::Plane, normalize(Vec3{0.1, 1, 0}), {}, {}, -30, 0));
    return objects;
}

OriginBuffer buffer(const Bvh& bvh, const std::vector<Object>& objects, Vec3 origin, double dilation) {
    OriginBuffer b;
    b.build(bvh.originBounds(objects), origin, dilation);
    return b;
}

Vec3 randomDirection(std::mt19937& rng) {
    std::normal_distribution<double> n;
    for (;;) {
        const Vec3 d{n(rng), n(rng), n(rng)};
        if (length(d) > 1e-3) return normalize(d);
    }
}

// Primary rays: the nearest hit from the eye's lists is the BVH's, bit for bit,
// from eyes outside everything, inside a sphere, near a box, just above the
// floor (with things below it).
TEST(OriginBuffer, RaysFromTheEyeFindTheBvhsNearestHit) {
    std::mt19937 rng(11);
    int hits = 0;
    for (const bool manyTriangles : {false, true}) {
        const std::vector<Object> objects = mixedScene(rng, manyTriangles);
        const Bvh bvh(objects);
        for (const Vec3 eye :
             {Vec3{0, 0, 20}, Vec3{9, 2, -3}, Vec3{0.5, 0.3, -0.2}, Vec3{-15, 15, 15}, Vec3{1, -6.6, 2}}) {
            const OriginBuffer eyeBuffer = buffer(bvh, objects, eye, 0.0);
            ASSERT_FALSE(eyeBuffer.empty());
            for (int i = 0; i < 6000; ++i) {
                Vec3 dir = randomDirection(rng);
                if (i % 50 == 0) dir = normalize(Vec3{1, 1, double(i % 3) - 1});  // along cube edges
                const Ray ray{eye, dir};
                const Hit ref = bvh.closest(objects, ray, 1e-6, kInfinity);
                const Hit got = bvh.closestFrom(eyeBuffer.cells(dir), objects, ray, 1e-6, kInfinity);
                ASSERT_EQ(got.valid(), ref.valid()) << "ray " << i;
                if (!ref.valid()) continue;
                ++hits;
                ASSERT_EQ(got.t, ref.t) << "ray " << i;
                if (got.object != ref.object) continue;  // two objects at exactly the same distance
                EXPECT_EQ(got.normal.x, ref.normal.x);
                EXPECT_EQ(got.normal.y, ref.normal.y);
                EXPECT_EQ(got.normal.z, ref.normal.z);
                EXPECT_EQ(got.geomNormal.z, ref.geomNormal.z);
            }
        }
    }
    EXPECT_GT(hits, 20000);
}

// A shadow ray as the tracer casts it, from P + kSurfaceOffset N (P where probe first meets the
// scene, N facing the probe) towards a point light, traced by the BVH and by the light's buffer.
struct ShadowVerdicts {
    bool shaded = false;  ///< the probe met the scene
    bool bvh = false, buffer = false;  ///< blocked, by each
};
ShadowVerdicts shadowBothWays(const Bvh& bvh, const std::vector<Object>& objects, const OriginBuffer& lightBuffer,
                              Vec3 light, const Ray& probe) {
    ShadowVerdicts v;
    const Hit h = bvh.closest(objects, probe, 1e-6, kInfinity);
    if (!h.valid()) return v;
    v.shaded = true;
    const Vec3 P = probe.at(h.t);
    const Vec3 N = dot(probe.dir, h.geomNormal) < 0 ? h.normal : -h.normal;
    const Vec3 toLight = light - P;
    const double dist = length(toLight);
    const double offset = Tracer::kSurfaceOffset;
    const Ray shadow{P + offset * N, toLight / dist};
    v.bvh = bvh.anyBlocker(objects, shadow, 1e-6, dist - offset) != Bvh::kNoBlocker;
    v.buffer = bvh.anyBlockerFrom(lightBuffer.cells(P - light), objects, shadow, 1e-6, dist - offset, dist) !=
               Bvh::kNoBlocker;
    return v;
}

// Shadow rays as the tracer casts them: from P + 0.001 N towards a point light.
// The light's lists (grown by that offset) must find a blocker exactly when the
// BVH does, for lights outside, inside an object and right next to one.
TEST(OriginBuffer, ShadowRaysToAPointLightFindTheBvhsBlockers) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-8, 8);
    const double offset = Tracer::kSurfaceOffset;
    int blocked = 0, lit = 0;
    for (const bool manyTriangles : {false, true}) {
        const std::vector<Object> objects = mixedScene(rng, manyTriangles);
        const Bvh bvh(objects);
        for (const Vec3 light : {Vec3{3, 12, 5}, Vec3{9, 2, -1}, Vec3{0.2, -0.1, 0.3}, Vec3{-30, 4, 2}}) {
            const OriginBuffer lightBuffer = buffer(bvh, objects, light, offset * 1.01);
            for (int i = 0; i < 6000; ++i) {
                // A shading point: where a random ray meets the scene, its normal
                // facing that ray.
                const Ray probe{{u(rng), u(rng), u(rng)}, randomDirection(rng)};
                const ShadowVerdicts v = shadowBothWays(bvh, objects, lightBuffer, light, probe);
                if (!v.shaded) continue;
                ASSERT_EQ(v.buffer, v.bvh) << "point " << i;
                ++(v.bvh ? blocked : lit);
            }
        }
    }
    EXPECT_GT(blocked, 4000);
    EXPECT_GT(lit, 4000);
}

// A shadow ray leaves P offset along the normal: it may meet an object that the segment from the
// light to P itself passes by. Here the segment runs 0.0005 above a unit sphere and the ray,
// starting 0.001 below P, goes through it; the light's lists are grown by the offset for that.
TEST(OriginBuffer, ShadowRaysOffsetFromTheSurfaceStayCovered) {
    const std::vector<Object> objects = {
        sphere({0, 0, 0}, 1), makeObject(ShapeType::Triangle, {5, 1.0005, -1}, {6, 1.0005, 1}, {4, 1.0005, 1}, 0, 0)};
    const Bvh bvh(objects);
    const Vec3 light{-5, 1.0005, 0}, P{5, 1.0005, 0}, N{0, -1, 0};
    const double offset = Tracer::kSurfaceOffset, dist = length(P - light);
    const Ray shadow{P + offset * N, (light - P) / dist};
    ASSERT_NE(bvh.anyBlocker(objects, shadow, 1e-6, dist - offset), Bvh::kNoBlocker);
    const OriginBuffer grown = buffer(bvh, objects, light, offset * 1.01);
    EXPECT_EQ(bvh.anyBlockerFrom(grown.cells(P - light), objects, shadow, 1e-6, dist - offset, dist), 0);
}

// A floor made of coplanar triangles of both windings (they share one plane, whose answer a walk
// remembers: Bvh::PlaneMemo), a second, lower floor in another plane, and spheres just above and
// below both: the lists must still give the BVH's answers, for eyes and lights above, between and
// below the floors, with rays that cross one floor, both or neither.
TEST(OriginBuffer, CoplanarFloorTrianglesGiveTheBvhsAnswers) {
    std::vector<Object> objects;
    for (int k = 0; k < 4; ++k) {  // four tiles, two of each winding
        const double x0 = -20 + 20 * (k % 2), z0 = -20 + 20 * (k / 2);
        const Vec3 a{x0, -1, z0}, b{x0 + 20, -1, z0}, c{x0 + 20, -1, z0 + 20}, d{x0, -1, z0 + 20};
        if (k % 2) {
            objects.push_back(makeObject(ShapeType::Triangle, a, b, c, 0, 0));
            objects.push_back(makeObject(ShapeType::Triangle, a, c, d, 0, 0));
        } else {
            objects.push_back(makeObject(ShapeType::Triangle, a, c, b, 0, 0));
            objects.push_back(makeObject(ShapeType::Triangle, a, d, c, 0, 0));
        }
    }
    objects.push_back(makeObject(ShapeType::Triangle, {-6, -2.5, -6}, {6, -2.5, -6}, {0, -2.5, 6}, 0, 0));
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(-5, 5), r(0.05, 0.4);
    for (int i = 0; i < 400; ++i) {
        const double y = i % 4 == 0 ? -1.3 : (i % 4 == 1 ? -2.8 : u(rng) * 0.3 + 0.5);
        objects.push_back(sphere({u(rng), y, u(rng)}, r(rng)));
    }
    const Bvh bvh(objects);
    int hits = 0, blocked = 0, lit = 0;
    for (const Vec3 origin : {Vec3{1, 6, -9}, Vec3{0.5, -1.2, 0.2}, Vec3{2, -6, 3}, Vec3{-3, -0.99, 1}}) {
        const OriginBuffer eye = buffer(bvh, objects, origin, 0.0);
        const OriginBuffer light = buffer(bvh, objects, origin, Tracer::kSurfaceOffset * 1.01);
        ASSERT_FALSE(eye.empty());
        for (int i = 0; i < 4000; ++i) {
            const Vec3 dir = randomDirection(rng);
            const Ray ray{origin, dir};
            const Hit ref = bvh.closest(objects, ray, 1e-6, kInfinity);
            const Hit got = bvh.closestFrom(eye.cells(dir), objects, ray, 1e-6, kInfinity);
            ASSERT_EQ(got.valid(), ref.valid()) << "ray " << i;
            if (ref.valid()) {
                ++hits;
                ASSERT_EQ(got.t, ref.t) << "ray " << i;
            }
            // A shadow ray from a point of the scene back to the origin as a light.
            const double y = i % 2 ? u(rng) * 0.8 : -2.7 + 0.05 * u(rng);  // every other one below both floors
            const Ray probe{{u(rng), y, u(rng)}, randomDirection(rng)};
            const ShadowVerdicts v = shadowBothWays(bvh, objects, light, origin, probe);
            if (!v.shaded) continue;
            ASSERT_EQ(v.buffer, v.bvh) << "point " << i;
            ++(v.bvh ? blocked : lit);
        }
    }
    EXPECT_GT(hits, 8000);
    EXPECT_GT(blocked, 1000);
    EXPECT_GT(lit, 1000);
}

// The lists are selective: from outside a lattice of 8,000 small spheres a
// direction's lists hold a few dozen objects at most, not thousands.
TEST(OriginBuffer, ListsHoldOnlyTheObjectsNearTheDirection) {
    std::vector<Object> objects;
    for (int x = 0; x < 20; ++x)
        for (int y = 0; y < 20; ++y)
            for (int z = 0; z < 20; ++z) objects.push_back(sphere({x - 9.5, y - 9.5, z - 9.5}, 0.2));
    const Bvh bvh(objects);
    const OriginBuffer b = buffer(bvh, objects, {3, 40, 7}, 0.0);
    std::mt19937 rng(3);
    size_t total = 0, most = 0;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
        const Vec3 target{double(rng() % 20) - 9.5, double(rng() % 20) - 9.5, double(rng() % 20) - 9.5};
        const OriginBuffer::Cells c = b.cells(target - Vec3{3, 40, 7});
        ASSERT_TRUE(c.valid);
        const size_t listed = size_t(c.fine.last - c.fine.first) + size_t(c.coarse.last - c.coarse.first);
        EXPECT_GT(listed, 0u);  // the target sphere itself
        total += listed;
        most = std::max(most, listed);
    }
    EXPECT_LT(double(total) / n, 40.0);
    EXPECT_LT(most, 200u);
    // Sorted by distance: the first entry of a list is never farther than the
    // last.
    const OriginBuffer::Cells c = b.cells(Vec3{-3, -40, -7});
    for (const OriginBuffer::Entry* e = c.fine.first; e + 1 < c.fine.last; ++e) EXPECT_LE(e->minDist, e[1].minDist);
    EXPECT_FALSE(b.cells(Vec3{0, 0, 0}).valid);
}

// Whole renders: with the buffers (built for scenes of 256 objects or more)
// every pixel is the one the tracer computes with the BVH alone.
TEST(OriginBuffer, RendersMatchTheBvhAlone) {
    std::string text = R"(
camera { location <1.5, 2.5, -7> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0.5, 0> }
light_source { <4, 6, -3> color rgb <1, 1, 1> }
light_source { <-3, 2, -4> color rgb <0.5, 0.5, 0.6> }
light_source { <0, 0.45, 0> color rgb <0.3, 0.3, 0.3> }
triangle { <-20, -1, -20>, <20, -1, -20>, <20, -1, 20> pigment { color rgb 0.8 } finish { ambient 0.2 diffuse 0.7 reflection 0.2 } }
triangle { <-20, -1, -20>, <20, -1, 20>, <-20, -1, 20> pigment { color rgb 0.8 } finish { ambient 0.2 diffuse 0.7 reflection 0.2 } }
box { <-0.5, -1, -0.5>, <0.5, 0, 0.5> rotate <0, 20, 0> translate <2, 0, 1> pigment { color rgb <0.2, 0.7, 0.3> } finish { diffuse 0.7 reflection 0.3 } }
)";
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-3, 3), r(0.05, 0.35);
    for (int i = 0; i < 400; ++i)
        text += "sphere { <" + std::to_string(u(rng)) + ", " + std::to_string(u(rng) * 0.5 + 0.8) + ", " +
                std::to_string(u(rng)) + ">, " + std::to_string(r(rng)) +
                " pigment { color rgb <0.9, 0.6, 0.4> } finish { ambient 0.1 "
                "diffuse 0.6 specular 0.4 roughness 0.1 "
                "reflection 0.4 } }\n";
    const Scene scene = parseScene(text, "t.pov", ParseOptions{});
    const Bvh bvh(scene.objects);
    RenderSettings s;
    s.width = 96;
    s.height = 72;
    s.threads = 2;
    TraceStats stats;
    const ImageF img = render(scene, bvh, s, stats);
    const SharedOrigins built = Tracer::buildSharedOrigins(scene, bvh, &scene.cameras[0].location, 96 * 72, 1);
    ASSERT_FALSE(built.eye.empty());
    ASSERT_EQ(built.lights.size(), 3u);
    const Tracer bvhOnly(scene, bvh, s);
    const ViewSetup view = resolveView(scene, s);
    TraceContext ctx;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const Vec3 ref = renderPixel(bvhOnly, view, s, x, s.height - 1 - y, ctx, nullptr);
            const Vec3 got = img.at(x, y);
            ASSERT_EQ(got.x, ref.x) << x << "," << y;
            ASSERT_EQ(got.y, ref.y) << x << "," << y;
            ASSERT_EQ(got.z, ref.z) << x << "," << y;
        }
}

// Which buffers a render gets: none for few objects or for more objects than a quarter of the
// image's samples (the build would cost more than the queries save), and no more than fit in the
// memory budget, point lights first; never for area or parallel lights.
TEST(OriginBuffer, RendersGetTheBuffersThatPay) {
    std::string text = R"(
camera { location <0, 0, -8> look_at <0, 0, 0> }
light_source { <4, 6, -3> color rgb 1 }
light_source { <-4, 6, -3> color rgb 1 area_light <1, 0, 0>, <0, 0, 1>, 2, 2 }
light_source { <0, 6, -3> color rgb 1 parallel point_at <0, 0, 0> }
light_source { <4, -6, -3> color rgb 1 }
light_source { <-4, -6, -3> color rgb 1 }
)";
    for (int i = 0; i < 300; ++i)
        text += "sphere { <" + std::to_string(i % 10) + ", " + std::to_string(i / 10 % 10) + ", " + std::to_string(i / 100) +
                ">, 0.3 }\n";
    const Scene scene = parseScene(text, "t.pov", ParseOptions{});
    ASSERT_EQ(scene.lights.size(), 5u);
    const Bvh bvh(scene.objects);
    const Vec3 eye = scene.cameras[0].location;
    auto built = [](const SharedOrigins& o) {
        std::string s = o.eye.empty() ? "-" : "e";
        for (const OriginBuffer& b : o.lights) s += b.empty() ? "-" : "L";
        return s;
    };
    EXPECT_EQ(built(Tracer::buildSharedOrigins(scene, bvh, &eye, 640 * 480, 1)), "eL--LL");
    EXPECT_EQ(built(Tracer::buildSharedOrigins(scene, bvh, nullptr, 640 * 480, 1)), "-L--LL");
    // 300 objects, 1,000 samples: not worth it.
    const SharedOrigins few = Tracer::buildSharedOrigins(scene, bvh, &eye, 1000, 1);
    EXPECT_EQ(built(few), "-");
    // Room for two buffers: the first two point lights.
    EXPECT_EQ(built(Tracer::buildSharedOrigins(scene, bvh, &eye, 640 * 480, 1,
                                               2.5 * Tracer::kSharedOriginsBytesPerObject * 300)),
              "-L--L-");
    // Fewer than 256 objects: the BVH alone.
    const Scene small = parseScene(R"(
camera { location <0, 0, -8> look_at <0, 0, 0> }
light_source { <4, 6, -3> color rgb 1 }
sphere { <0, 0, 0>, 1 }
)",
                                   "s.pov", ParseOptions{});
    const Bvh smallBvh(small.objects);
    EXPECT_EQ(built(Tracer::buildSharedOrigins(small, smallBvh, &eye, 640 * 480, 1)), "-");
}

}}  // namespace RAYS_TEST_UNIT, namespace
