#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "rays/io/scene_parser.h"
#include "rays/render/shading.h"
#include "rays/render/tracer.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

Material mat(double kd, double ks, double rough) {
    Material m;
    m.color = {1, 0.5, 0.25};
    m.diffuse = kd;
    m.specular = ks;
    m.roughness = rough;
    m.ior = 1.5;
    return m;
}

Scene sceneFrom(const std::string& body) {
    ParseOptions opt;
    opt.warn = [](const std::string&) {};
    return parseScene("camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n" + body,
                      "t.pov", opt);
}

TEST(Shading, BlinnPhongMatchesCourseFormula) {
    const Material m = mat(0.4, 0.5, 0.5);
    const Vec3 N{0, 0, 1}, L = normalize(Vec3{1, 0, 1}), V{0, 0, 1}, Lc{1.5, 1.5, 1.5};
    const LightTerms t = blinnPhong(m, N, L, V, Lc);
    const double nl = dot(N, L);
    EXPECT_NEAR(t.diffuse.x, 1.5 * 0.4 * 1.0 * nl, 1e-12);
    EXPECT_NEAR(t.diffuse.y, 1.5 * 0.4 * 0.5 * nl, 1e-12);
    const double nh = dot(N, normalize(L + V));
    const double spec = 1.5 * 0.5 * std::pow(nh, 2.0 / 0.25 - 2.0);
    EXPECT_NEAR(t.specular.x, spec, 1e-12);
    EXPECT_NEAR(t.specular.z, spec * 0.25, 1e-12);
}

TEST(Shading, BlinnPhongSpecularIsNotGatedByNdotL) {
    // Course reference behaviour: a light just below the horizon still gives a highlight.
    const Material m = mat(0.4, 0.5, 0.5);
    const Vec3 N{0, 0, 1}, L = normalize(Vec3{1, 0, -0.1}), V = normalize(Vec3{-1, 0, 1});
    const LightTerms t = blinnPhong(m, N, L, V, Vec3(1.0));
    EXPECT_EQ(t.diffuse.x, 0);
    EXPECT_GT(t.specular.x, 0);
}

TEST(Shading, CookTorranceMatchesFormulaAtNormalIncidence) {
    const Material m = mat(0.6, 0.4, 0.3);
    const Vec3 N{0, 0, 1};
    const LightTerms t = cookTorrance(m, N, N, N, Vec3(1.0));
    // N = L = V = H: D = 1/(π α²), G = 1, F = F0, denominator 4·1.
    const double alpha = 0.3 * 0.3;
    const double D = 1.0 / (std::numbers::pi * alpha * alpha);
    const double F0 = std::pow((1.5 - 1) / (1.5 + 1), 2);
    EXPECT_NEAR(t.specular.x, 0.4 * D * F0 / 4.0, 1e-9);
    EXPECT_NEAR(t.diffuse.x, 0.6, 1e-12);
}

TEST(Shading, CookTorranceWithoutSpecularIsLambert) {
    const Material m = mat(0.7, 0.0, 0.3);
    const Vec3 N{0, 1, 0}, L = normalize(Vec3{0.3, 1, 0.2}), V = normalize(Vec3{-0.5, 1, 0});
    const LightTerms ct = cookTorrance(m, N, L, V, Vec3(1.0));
    const LightTerms bp = blinnPhong(m, N, L, V, Vec3(1.0));
    EXPECT_NEAR(ct.diffuse.x, bp.diffuse.x, 1e-15);
    EXPECT_EQ(ct.specular.x, 0);
}

TEST(Shading, SchlickEndpoints) {
    EXPECT_NEAR(schlickFresnel(1.5, 1.0), 0.04, 1e-12);
    EXPECT_NEAR(schlickFresnel(1.5, 0.0), 1.0, 1e-12);
    EXPECT_NEAR(schlickFresnel(1.0, 0.5), std::pow(0.5, 5), 1e-12);
}

TEST(Tracer, WeightsFollowFilterAndReflection) {
    const Scene s = sceneFrom(
        "light_source {<0, 100, 100> color rgb <1,1,1>}\n"
        "sphere { <0,0,0>, 3 pigment { color rgbf <1,1,1,0.6> } finish { ambient 0.2 reflection 0.5 ior 1.5 } }\n");
    const Bvh bvh(s.objects);
    RenderSettings rs;
    std::vector<TraceRecord> log;
    TraceContext st;
    Tracer(s, bvh, rs).tracePrimary(Ray{{0, 0, 14}, {0, 0, -1}}, st, &log);
    ASSERT_GE(log.size(), 2u);
    EXPECT_NEAR(log[0].wLocal, 0.4 * 0.5, 1e-12);
    EXPECT_NEAR(log[0].wReflection, 0.4 * 0.5, 1e-12);
    EXPECT_NEAR(log[0].wTransmission, 0.6, 1e-12);
    // With -fresnel at normal incidence F = 0.04 moves weight from transmission to reflection.
    rs.fresnel = true;
    log.clear();
    Tracer(s, bvh, rs).tracePrimary(Ray{{0, 0, 14}, {0, 0, -1}}, st, &log);
    EXPECT_NEAR(log[0].wReflection, 0.2 + 0.6 * 0.04, 1e-12);
    EXPECT_NEAR(log[0].wTransmission, 0.6 * 0.96, 1e-12);
}

TEST(Tracer, TotalInternalReflectionMovesTransmissionToReflection) {
    const Scene s = sceneFrom("sphere { <0,0,0>, 1 pigment { color rgbf <1,1,1,1> } finish { ior 2.0 } }\n");
    const Bvh bvh(s.objects);
    RenderSettings rs;
    std::vector<TraceRecord> log;
    TraceContext st;
    // A ray from inside at a grazing angle: sin θ = 0.9 > 1/2.
    const Vec3 start{0, 0.9, 0};
    Tracer(s, bvh, rs).tracePrimary(Ray{start, {1, 0, 0}}, st, &log);
    ASSERT_GE(log.size(), 2u);
    EXPECT_NEAR(log[0].wTransmission, 0.0, 1e-12);
    EXPECT_NEAR(log[0].wReflection, 1.0, 1e-12);
    EXPECT_EQ(log[1].kind, TraceRecord::Kind::Reflection);
}

TEST(Tracer, BeersLawAttenuatesWithDistance) {
    // A red-tinted glass slab seen against a white emitter-like backdrop (ambient 1).
    const std::string scene =
        "box { <-5,-5,-1>, <5,5,1> pigment { color rgbf <1,0.5,0.5,1> } finish { ior 1.0 } }\n"
        "plane { <0,0,1>, -10 pigment { color rgb <1,1,1> } finish { ambient 1 } }\n";
    const Scene s = sceneFrom(scene);
    const Bvh bvh(s.objects);
    RenderSettings rs;
    TraceContext st;
    const Vec3 plain = Tracer(s, bvh, rs).tracePrimary(Ray{{0, 0, 14}, {0, 0, -1}}, st);
    EXPECT_NEAR(plain.x, 1.0, 1e-9);
    EXPECT_NEAR(plain.y, 0.5, 1e-9);  // tinted by the pigment while inside
    rs.beers = true;
    const Vec3 beer = Tracer(s, bvh, rs).tracePrimary(Ray{{0, 0, 14}, {0, 0, -1}}, st);
    EXPECT_NEAR(beer.x, 1.0, 1e-9);
    // 2 units inside (less the 0.001 start offset): exp(−(1 − 0.5)·0.15·d).
    EXPECT_NEAR(beer.y, std::exp(-0.5 * 0.15 * 1.999), 1e-6);
}

TEST(Tracer, RecursionDepthLimitsTheTree) {
    // Two facing mirrors: the tree is as deep as the limit allows.
    const Scene s = sceneFrom(
        "plane { <0,0,1>, -1 pigment { color rgb 1 } finish { reflection 1 } }\n"
        "plane { <0,0,-1>, -20 pigment { color rgb 1 } finish { reflection 1 } }\n");
    const Bvh bvh(s.objects);
    RenderSettings rs;
    TraceContext st;
    for (int depth : {0, 1, 6}) {
        rs.maxDepth = depth;
        std::vector<TraceRecord> log;
        Tracer(s, bvh, rs).tracePrimary(Ray{{0, 0, 14}, {0, 0, -1}}, st, &log);
        EXPECT_EQ(int(log.size()), depth + 1);
    }
}

TEST(Tracer, NoShadowRayTowardsALightTheSurfaceFacesAwayFrom) {
    // A light far to the right: the sphere's left half faces away from it.
    auto scene = [](const std::string& finish) {
        return sceneFrom("light_source {<100, 0, 0> color rgb <1,1,1>}\n"
                         "sphere { <0,0,0>, 3 pigment { color rgb <1,1,1> } finish { ambient 0.1 diffuse 0.8 " +
                         finish + " } }\n");
    };
    const Ray left{{-2, 0, 14}, {0, 0, -1}}, right{{2, 0, 14}, {0, 0, -1}};
    RenderSettings rs;
    auto shadowRays = [&](const Scene& s, const Ray& ray, PathInfo* info, Vec3* color = nullptr) {
        const Bvh bvh(s.objects);
        TraceContext ctx;
        const Vec3 c = Tracer(s, bvh, rs).tracePrimary(ray, ctx, nullptr, info);
        if (color) *color = c;
        return ctx.stats.shadowRays;
    };
    const Scene diffuseOnly = scene("");
    Vec3 c;
    // Lit side: traced. Far side: no light can come from there, nothing to trace.
    EXPECT_EQ(shadowRays(diffuseOnly, right, nullptr), 1u);
    EXPECT_EQ(shadowRays(diffuseOnly, left, nullptr, &c), 0u);
    EXPECT_NEAR(c.x, 0.1, 1e-12);  // ambient only
    // The feature lines' records count blocked lights: then the ray is traced, and it is blocked.
    PathInfo info;
    EXPECT_EQ(shadowRays(diffuseOnly, left, &info), 1u);
    EXPECT_EQ(info.blockedLights, 1);
    // Blinn-Phong's specular lobe is not gated by N·L: with a specular term the ray is traced.
    EXPECT_EQ(shadowRays(scene("specular 0.5 roughness 0.1"), left, nullptr), 1u);
    // Cook-Torrance gives nothing for N·L ≤ 0, specular or not.
    rs.shading = ShadingModel::CookTorrance;
    EXPECT_EQ(shadowRays(scene("specular 0.5 roughness 0.1"), left, nullptr), 0u);
}

// The shortcut before normalising the light direction: whenever it says "facing away", the
// normalised dot product the shading uses is not positive either (same images), and it does say
// so for directions clearly behind the surface, at any distance.
TEST(Shading, ClearlyFacingAwayAgreesWithTheNormalisedTest) {
    uint64_t state = 12345;
    auto uniform = [&] {  // xorshift64*, in [-1, 1)
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        return double((state * 0x2545F4914F6CDD1DULL) >> 11) * 0x1p-52 - 1.0;
    };
    int shortcuts = 0;
    for (int i = 0; i < 200000; ++i) {
        const Vec3 N = normalize(Vec3{uniform(), uniform(), uniform()});
        Vec3 toLight = std::ldexp(1.0, int(uniform() * 40)) * Vec3{uniform(), uniform(), uniform()};
        if (i % 2) toLight = toLight - dot(toLight, N) * N + 1e-14 * uniform() * length(toLight) * N;  // grazing
        if (length(toLight) == 0) continue;
        const double nl = dot(toLight / length(toLight), N);
        if (clearlyFacingAway(toLight, N)) {
            ++shortcuts;
            EXPECT_LE(nl, 0.0) << i;
        } else {
            EXPECT_GT(nl, -1e-9) << i;  // only near-zero or positive cases are left to the full test
        }
    }
    EXPECT_GT(shortcuts, 40000);
    EXPECT_TRUE(clearlyFacingAway({0, 0, -1e-3}, {0, 0, 1}));
    EXPECT_TRUE(clearlyFacingAway({1e6, 3e6, -1}, {0, 0, 1}));
    EXPECT_FALSE(clearlyFacingAway({1, 0, 0}, {0, 0, 1}));   // exactly grazing
    EXPECT_FALSE(clearlyFacingAway({0, 0, 0}, {0, 0, 1}));   // light at the point
    EXPECT_FALSE(clearlyFacingAway({0, 0, 1e-3}, {0, 0, 1}));
}

}}  // namespace RAYS_TEST_UNIT, namespace
