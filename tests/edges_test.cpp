// Feature lines on synthetic scenes with exact answers: drawn lines are scored against the true
// feature pixels (projected analytic curves) with a 1-pixel tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <mutex>
#include <thread>
#include <numbers>
#include <set>
#include <string>

#include "rays/accel/bvh.h"
#include "rays/io/scene_parser.h"
#include "rays/npr/feature_lines.h"
#include "rays/npr/stencil.h"
#include "rays/npr/stencil_pass.h"
#include "rays/render/renderer.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

constexpr int kW = 200, kH = 150;

Scene sceneFrom(const std::string& text) {
    ParseOptions opt;
    opt.warn = [](const std::string&) {};
    return parseScene(text, "t.pov", opt);
}

// The lines of the given types; stats (optional) receives the rays they cast.
LineCoverage lines(const Scene& scene, uint32_t types, EdgeMethod method, double width = 1.5, int threads = 0,
                   int w = kW, int h = kH, TraceStats* stats = nullptr) {
    const Bvh bvh(scene.objects);
    RenderSettings s;
    s.width = w;
    s.height = h;
    s.threads = threads;
    EdgeSettings e;
    e.types = types;
    e.method = method;
    e.width = width;
    TraceStats local;
    return drawFeatureLines(scene, bvh, s, e, nullptr, stats ? *stats : local);
}

// Image position (x right, y DOWN, in pixels) of world point p: solves
// p − eye = s·(a·right + b·up + forward) (right and up need not be orthogonal to forward).
bool project(const Camera& c, Vec3 p, double& x, double& y) {
    const Vec3 q = Transform::fromColumns(c.right, c.up, c.forward(), {}).inverse().vector(p - c.location);
    if (q.z <= 0) return false;
    const double a = q.x / q.z, b = q.y / q.z;
    x = (a + 0.5) * kW;
    y = kH - (b + 0.5) * kH;
    return x >= 0 && y >= 0 && x < kW && y < kH;
}

using PixelSet = std::set<std::pair<int, int>>;

// Sum of the coverage over the image.
float totalInk(const LineCoverage& lc) {
    float ink = 0;
    for (float c : lc.coverage) ink += c;
    return ink;
}

// The circle centre + cos(2πu)·a + sin(2πu)·b, u in [0, 1), as a curve for truthPixels.
std::function<Vec3(double)> circle(Vec3 centre, Vec3 a, Vec3 b) {
    return [=](double u) {
        const double angle = 2 * std::numbers::pi * u;
        return centre + std::cos(angle) * a + std::sin(angle) * b;
    };
}

// Pixels containing visible samples of a curve. visible(p) decides visibility.
PixelSet truthPixels(const Camera& cam, const std::function<Vec3(double)>& curve,
                     const std::function<bool(Vec3)>& visible = {}) {
    PixelSet out;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p = curve(i / 20000.0);
        double x, y;
        if (!project(cam, p, x, y)) continue;
        if (visible && !visible(p)) continue;
        out.insert({int(x), int(y)});
    }
    return out;
}

// A point is visible when the camera ray toward it hits nothing clearly closer.
std::function<bool(Vec3)> visibleIn(const Scene& scene, const Bvh& bvh) {
    return [&scene, &bvh](Vec3 p) {
        const Vec3 eye = scene.cameras[0].location;
        const double dist = length(p - eye);
        const Hit h = bvh.closest(scene.objects, Ray{eye, (p - eye) / dist}, 1e-6, kInfinity);
        return !h.valid() || h.t > dist * (1 - 1e-4);
    };
}

struct Score {
    double precision = 0, recall = 0;
    size_t drawn = 0, truth = 0;
};

bool near(const PixelSet& set, int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (set.count({x + dx, y + dy})) return true;
    return false;
}

Score score(const LineCoverage& lc, const PixelSet& truth, const std::function<bool(int, int)>& inRegion = {}) {
    PixelSet drawn;
    for (int y = 0; y < lc.height; ++y)
        for (int x = 0; x < lc.width; ++x)
            if (lc.at(x, y) > 0.3f && (!inRegion || inRegion(x, y))) drawn.insert({x, y});
    Score s;
    s.drawn = drawn.size();
    s.truth = truth.size();
    size_t good = 0, found = 0;
    for (const auto& [x, y] : drawn) good += near(truth, x, y);
    for (const auto& [x, y] : truth) found += near(drawn, x, y);
    s.precision = drawn.empty() ? 0 : double(good) / double(drawn.size());
    s.recall = truth.empty() ? 0 : double(found) / double(truth.size());
    return s;
}

const char* kCamera = "camera { location <0, 0, 10> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }\n";

class EdgeMethods : public ::testing::TestWithParam<EdgeMethod> {};

std::string methodName(const ::testing::TestParamInfo<EdgeMethod>& info) {
    return info.param == EdgeMethod::Stencil ? "Stencil" : "Image";
}

void expectGood(const Score& s, const char* what) {
    EXPECT_GE(s.precision, 0.95) << what << ": drawn " << s.drawn << ", truth " << s.truth;
    EXPECT_GE(s.recall, 0.95) << what << ": drawn " << s.drawn << ", truth " << s.truth;
    EXPECT_GT(s.truth, 20u) << what;
}

TEST_P(EdgeMethods, SphereSilhouetteIsItsProjectedCircle) {
    const Scene scene = sceneFrom(std::string(kCamera) + "sphere { <0, 0, 0>, 2 pigment { color rgb 1 } }\n");
    // Tangent circle seen from distance 10: plane z = r²/D, radius r·√(1 − r²/D²).
    const double z = 0.4, rad = 2 * std::sqrt(1 - 0.04);
    const PixelSet truth = truthPixels(scene.cameras[0], circle({0, 0, z}, {rad, 0, 0}, {0, rad, 0}));
    expectGood(score(lines(scene, kEdgeSilhouette, GetParam()), truth), "silhouette");
}

TEST_P(EdgeMethods, IntersectionCircleOfTwoSpheres) {
    const Scene scene = sceneFrom(
        "camera { location <0, 3, 6> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }\n"
        "sphere { <-0.6, 0, 0>, 1 pigment { color rgb 1 } }\n"
        "sphere { <0.6, 0, 0>, 1 pigment { color rgb <1, 0, 0> } }\n");
    const Bvh bvh(scene.objects);
    const PixelSet truth = truthPixels(scene.cameras[0], circle({0, 0, 0}, {0, 0.8, 0}, {0, 0, 0.8}), visibleIn(scene, bvh));
    expectGood(score(lines(scene, kEdgeIntersection, GetParam()), truth), "intersection");
}

TEST_P(EdgeMethods, CubeEdgesAreCreasesAndOutline) {
    const Scene scene = sceneFrom(std::string(kCamera) +
                                  "box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> rotate <25, 35, 0> pigment { color rgb 1 } }\n");
    const Bvh bvh(scene.objects);
    const Transform m = Transform::rotateCourse({25, 35, 0});
    PixelSet truth;
    // The 12 edges: vary one coordinate, fix the other two at ±1.5.
    for (int axis = 0; axis < 3; ++axis)
        for (int corner = 0; corner < 4; ++corner) {
            const PixelSet edge = truthPixels(scene.cameras[0], [&](double u) {
                Vec3 p;
                p[axis] = -1.5 + 3 * u;
                p[(axis + 1) % 3] = (corner & 1) ? 1.5 : -1.5;
                p[(axis + 2) % 3] = (corner & 2) ? 1.5 : -1.5;
                return m.point(p);
            }, visibleIn(scene, bvh));
            truth.insert(edge.begin(), edge.end());
        }
    expectGood(score(lines(scene, kEdgeSilhouette | kEdgeCrease, GetParam()), truth), "cube edges");
    // Creases alone: the interior edges (both faces visible) and none of the background.
    const LineCoverage creases = lines(scene, kEdgeCrease, GetParam());
    float outside = 0;
    for (int x = 0; x < kW; ++x) outside = std::max(outside, creases.at(x, 0));
    EXPECT_EQ(outside, 0.0f);
}

// The stencil decides taps between crease facets from the records' tangent planes.
TEST(StencilTaps, CreasesNeedNoTapRays) {
    const Scene scene = sceneFrom(std::string(kCamera) +
                                  "box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> rotate <25, 35, 0> pigment { color rgb 1 } }\n");
    TraceStats stats;
    const LineCoverage lc = lines(scene, kEdgeCrease, EdgeMethod::Stencil, 1.5, 0, kW, kH, &stats);
    EXPECT_GT(totalInk(lc), 100.0f);
    // Besides the pixel centres, rays only for taps next to the outline, where the background is
    // among the four records (tracing every mixed tap takes about 1400).
    EXPECT_GE(stats.primaryRays, uint64_t(kW) * kH);
    EXPECT_LT(stats.primaryRays - uint64_t(kW) * kH, 100u);
}

// A shadow boundary on the one surface in view is placed on the plane's tangent plane: the taps
// cast shadow rays only. The occluder is above and behind the camera.
TEST(StencilTaps, ShadowBoundaryOnOneSurfaceNeedsOnlyShadowRays) {
    const Scene scene = sceneFrom(
        "camera { location <0, 20, 0> up <0, 0, -1> right <1.33333, 0, 0> look_at <0, 0, 0> }\n"
        "light_source { <0, 30, 0> color rgb 1 }\n"
        "plane { <0, 1, 0>, 0 pigment { color rgb 1 } finish { diffuse 1 } }\n"
        "sphere { <0, 25, 0>, 1 pigment { color rgb 1 } }\n");
    TraceStats stats;
    const LineCoverage lc = lines(scene, kEdgeShadow, EdgeMethod::Stencil, 1.5, 0, kW, kH, &stats);
    EXPECT_EQ(stats.primaryRays, uint64_t(kW) * kH);
    EXPECT_GT(stats.shadowRays, uint64_t(kW) * kH);
    // The shadow of the sphere: a circle of radius 30·tan(asin(1/5)).
    const double r = 30 * std::tan(std::asin(0.2));
    expectGood(score(lc, truthPixels(scene.cameras[0], circle({0, 0, 0}, {r, 0, 0}, {0, 0, r}))), "shadow circle");
}

// Bands drawn while rows arrive (in any order, from several threads, as render()'s onRows reports
// them) give exactly the coverage of drawing every band at the end.
TEST(StencilPass, BandsDrawnAsRowsArriveMatchDrawingAtTheEnd) {
    const Scene scene = sceneFrom(std::string(kCamera) +
                                  "light_source { <5, 8, 10> color rgb 1 }\n"
                                  "plane { <0, 1, 0>, -2 pigment { color rgb 1 } }\n"
                                  "box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> rotate <25, 35, 0> pigment { color rgb 1 } }\n"
                                  "sphere { <2, 1, 1>, 1 pigment { color rgb <1, 0, 0> } }\n");
    const Bvh bvh(scene.objects);
    RenderSettings s;
    s.width = kW;
    s.height = kH;
    s.threads = 3;
    EdgeSettings e;
    e.types = kEdgeAll;
    LineRecords records(scene, kW, kH);
    TraceStats stats;
    render(scene, bvh, s, stats, {}, nullptr, [&](int x, int y, const PathInfo& info) { records.store(x, y, info); });

    TraceStats atEnd, streamed, duringRender;
    const LineCoverage reference = StencilPass(scene, bvh, s, e, records).finish(atEnd);
    ASSERT_GT(totalInk(reference), 100.0f);

    // Rows reported in 7-row pieces, bottom up, by three threads taking pieces in turn.
    StencilPass pass(scene, bvh, s, e, records);
    std::vector<std::thread> threads;
    for (int w = 0; w < 3; ++w)
        threads.emplace_back([&, w] {
            for (int piece = w; piece * 7 < kH; piece += 3) {
                const int y1 = kH - piece * 7;
                pass.rowsDone(std::max(0, y1 - 7), y1, w);
            }
        });
    for (std::thread& t : threads) t.join();
    const LineCoverage fromRows = pass.finish(streamed);
    EXPECT_EQ(fromRows.coverage, reference.coverage);

    // And through render()'s onRows, with the render's own threads.
    LineRecords again(scene, kW, kH);
    StencilPass during(scene, bvh, s, e, again);
    int calls = 0;
    std::mutex m;
    render(scene, bvh, s, stats, {}, nullptr, [&](int x, int y, const PathInfo& info) { again.store(x, y, info); },
           [&](const ImageF&, int y0, int y1, int w) {
               {
                   std::lock_guard<std::mutex> lock(m);
                   ++calls;
               }
               during.rowsDone(y0, y1, w);
           });
    EXPECT_EQ(calls, (kH + 15) / 16);  // once per row of 16-pixel tiles
    EXPECT_EQ(during.finish(duringRender).coverage, reference.coverage);
    EXPECT_EQ(duringRender.primaryRays, atEnd.primaryRays);
}

TEST_P(EdgeMethods, SphereOutlineSeenInAMirror) {
    // The camera looks at a mirror; the sphere is behind the camera and visible only reflected,
    // as a virtual sphere at z = −8 seen from 13 units away.
    const Scene scene = sceneFrom(
        "camera { location <0, 0, 5> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }\n"
        "plane { <0, 0, 1>, 0 pigment { color rgb 1 } finish { reflection 1 } }\n"
        "sphere { <0, 0, 8>, 1 pigment { color rgb <1, 0, 0> } finish { ambient 1 } }\n");
    const double D = 13, z = -8 + 1 / D, rad = std::sqrt(1 - 1 / (D * D));
    const PixelSet truth = truthPixels(scene.cameras[0], circle({0, 0, z}, {rad, 0, 0}, {0, rad, 0}));
    // Projection through the mirror equals projecting the virtual point with the same camera.
    expectGood(score(lines(scene, kEdgeReflection, GetParam()), truth), "reflected outline");
}

TEST_P(EdgeMethods, ShadowBoundaryOfASphereOnAPlane) {
    // Light 2 units above the sphere's centre: the shadow cone has a half-angle of 30°, so the
    // shadow on the floor is a circle of radius 4·tan 30°, and the sphere's own terminator is the
    // circle 60° from its top.
    const Scene scene = sceneFrom(
        "camera { location <0, 20, 0> up <0, 0, -1> right <1.33333, 0, 0> look_at <0, 0, 0> }\n"
        "light_source { <0, 4, 0> color rgb 1 }\n"
        "plane { <0, 1, 0>, 0 pigment { color rgb 1 } finish { diffuse 1 } }\n"
        "sphere { <0, 2, 0>, 1 pigment { color rgb 1 } finish { diffuse 1 } }\n");
    const Bvh bvh(scene.objects);
    const double shadowR = 4 * std::tan(std::numbers::pi / 6);
    PixelSet truth = truthPixels(scene.cameras[0], circle({0, 0, 0}, {shadowR, 0, 0}, {0, 0, shadowR}), visibleIn(scene, bvh));
    const PixelSet terminator = truthPixels(scene.cameras[0], circle({0, 2.5, 0}, {0.866, 0, 0}, {0, 0, 0.866}), visibleIn(scene, bvh));
    truth.insert(terminator.begin(), terminator.end());
    expectGood(score(lines(scene, kEdgeShadow, GetParam()), truth), "shadow boundary");
}

TEST_P(EdgeMethods, LineWidthMatchesTheRequest) {
    // A straight vertical silhouette: a white box covering the right half of the view.
    const Scene scene = sceneFrom(std::string(kCamera) + "box { <0.3, -50, -1>, <50, 50, 0> pigment { color rgb 1 } }\n");
    for (double width : {1.0, 2.0, 4.0}) {
        const LineCoverage lc = lines(scene, kEdgeSilhouette, GetParam(), width);
        double ink = 0;
        for (int x = 0; x < kW; ++x) ink += lc.at(x, kH / 2);
        EXPECT_NEAR(ink, width, 0.2 * width) << "width " << width;
    }
}

TEST_P(EdgeMethods, NoLinesOnASinglePlane) {
    // Filling the view, at a slant: nothing at all.
    const Scene down = sceneFrom(
        "camera { location <0, 6, 10> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }\n"
        "light_source { <5, 10, 5> color rgb 1 }\n"
        "plane { <0, 1, 0>, -1 pigment { color rgb 1 } finish { diffuse 1 reflection 0.3 } }\n");
    const LineCoverage lc = lines(down, kEdgeAll, GetParam());
    float maxCoverage = 0;
    for (float c : lc.coverage) maxCoverage = std::max(maxCoverage, c);
    EXPECT_EQ(maxCoverage, 0.0f);
    // Up to the horizon: the horizon is the plane's silhouette against the empty background;
    // grazing views near it must not add depth or crease lines.
    const Scene horizon = sceneFrom(
        "camera { location <0, 1, 10> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 1, 0> }\n"
        "light_source { <5, 10, 5> color rgb 1 }\n"
        "plane { <0, 1, 0>, -1 pigment { color rgb 1 } finish { diffuse 1 } }\n");
    const LineCoverage h = lines(horizon, kEdgeAll & ~kEdgeSilhouette, GetParam());
    maxCoverage = 0;
    for (float c : h.coverage) maxCoverage = std::max(maxCoverage, c);
    EXPECT_EQ(maxCoverage, 0.0f);
}

TEST_P(EdgeMethods, SameLinesForAnyThreadCount) {
    const Scene scene = sceneFrom(
        "camera { location <0, 2, 8> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }\n"
        "light_source { <5, 10, 5> color rgb 1 }\n"
        "plane { <0, 1, 0>, -1 pigment { color rgb 1 } finish { diffuse 1 reflection 0.3 } }\n"
        "sphere { <-1, 0, 0>, 1 pigment { color rgb 1 } finish { diffuse 1 } }\n"
        "box { <-0.5, -1, -0.5>, <0.5, 1, 0.5> rotate <0, 30, 0> translate <1, 0, 0> pigment { color rgb <1, 0, 0> } }\n");
    const LineCoverage one = lines(scene, kEdgeAll, GetParam(), 1.5, 1);
    const LineCoverage many = lines(scene, kEdgeAll, GetParam(), 1.5, 3);
    EXPECT_EQ(one.coverage, many.coverage);
}

INSTANTIATE_TEST_SUITE_P(Edges, EdgeMethods, ::testing::Values(EdgeMethod::Stencil, EdgeMethod::Image), methodName);

TEST(Stencil, RingsAndStrength) {
    // One ring of 8 rays for small radii, 8 + 16 for two rings.
    EXPECT_EQ(makeStencil(0.9).size(), 8u);
    EXPECT_EQ(makeStencil(1.7).size(), 24u);
    EXPECT_DOUBLE_EQ(stencilStrength(0, 24), 0.0);
    EXPECT_DOUBLE_EQ(stencilStrength(12, 24), 1.0);
    EXPECT_DOUBLE_EQ(stencilStrength(6, 24), 0.5);
    EXPECT_DOUBLE_EQ(stencilStrength(24, 24), 0.0);
}

TEST(EdgeSettingsParse, NamesAndErrors) {
    EXPECT_EQ(parseEdgeTypes("silhouette,crease"), uint32_t(kEdgeSilhouette | kEdgeCrease));
    EXPECT_EQ(parseEdgeTypes("all"), uint32_t(kEdgeAll));
    EXPECT_EQ(parseEdgeTypes("none"), 0u);
    EXPECT_THROW(parseEdgeTypes("silhouete"), Error);
    EdgeSettings e;
    e.width = 9;
    EXPECT_THROW(validateEdgeSettings(e), Error);
}

TEST(EdgesBlock, SceneFileSetsTheSameControls) {
    const Scene scene = sceneFrom(std::string(kCamera) +
                                  "edges { silhouette crease edge_method image edge_width 3 edge_color rgb <1, 0, 0> crease_angle 45 lines_only }\n");
    EXPECT_EQ(scene.edges.types, uint32_t(kEdgeSilhouette | kEdgeCrease));
    EXPECT_EQ(scene.edges.method, EdgeMethod::Image);
    EXPECT_DOUBLE_EQ(scene.edges.width, 3);
    EXPECT_DOUBLE_EQ(scene.edges.color.x, 1);
    EXPECT_DOUBLE_EQ(scene.edges.creaseAngle, 45);
    EXPECT_TRUE(scene.edges.linesOnly);
}

}}  // namespace RAYS_TEST_UNIT, namespace
