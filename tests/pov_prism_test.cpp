// POV-Ray's prism with quadratic, cubic and bezier splines and with conic_sweep (reference
// 3.4.5.1.11): hits and normals against POV-Ray 3.7's trace(), first hits of random rays against
// a brute-force march through a finely sampled outline, inside tests and a note-free build.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "rays/scene/csg.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

const char* const kPrisms[] = {
    "prism { quadratic_spline linear_sweep 0, 1, 6, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1>, <1,-1> }",
    "prism { cubic_spline linear_sweep 0, 1, 7, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1>, <1,-1>, <1,1> }",
    "prism { bezier_spline linear_sweep 0, 1, 8, <1,-1>, <2,0>, <1,0.5>, <1,1>, <1,1>, <0,2>, <-1,0>, <1,-1> }",
    "prism { linear_spline conic_sweep 0.5, 1, 5, <1,1>, <-1,1>, <-1,-1>, <1,-1>, <1,1> }",
    "prism { quadratic_spline conic_sweep 0.25, 1, 6, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1>, <1,-1> }",
};

const Vec3 kFrom[] = {{3, 0.7, 0.3}, {-2.5, 0.9, -2}, {0.2, 3, 0.1}, {0.3, -2, -0.2}, {2, 2, 2}, {0.1, 0.6, -3}};
const Vec3 kDir[] = {{-1, -0.1, 0.05}, {1, -0.05, 0.8}, {0.05, -1, 0.02}, {0.1, 1, 0.1}, {-1, -0.8, -1.1}, {0.02, 0.01, 1}};

struct Traced {
    int shape, ray;
    Vec3 point, normal;  // POV-Ray's trace(); normal zero: no hit
};

// povray 3.7.0.10: #debug of trace(S[s], O[i], D[i], N) (vstr 9 digits; the normals' last digits cut).
const Traced kTraced[] = {
    {0, 0, {1.170930947, 0.517093095, 0.391453453}, {0.976751545, 0, 0.21437448}},
    {0, 1, {-1.051096073, 0.827554804, -0.840876858}, {-0.955580491, 0, -0.2947}},
    {0, 2, {0.3, 1, 0.14}, {0, 1, 0}},
    {0, 3, {0.5, 0, 0}, {0, 1, 0}},
    {0, 5, {0.135627478, 0.617813739, -1.218626101}, {0.148798692, 0, -0.988867}},
    {1, 0, {1.224813872, 0.522481387, 0.388759306}, {0.990993208, 0, 0.13391214}},
    {1, 1, {-1.09, 0.8295, -0.872}, {-0.887405419, 0, -0.4609}},
    {1, 5, {0.135058646, 0.617529323, -1.247067725}, {0.043585955, 0, -0.999049}},
    {2, 0, {1.277913623, 0.527791362, 0.386104319}, {-0.871628237, 0, -0.490167}},
    {2, 1, {-0.033750994, 0.77668755, -0.027000795}, {0.909008465, 0, 0.416777}},
    {2, 5, {0.153301493, 0.626650746, -0.334925352}, {0.793275684, 0, 0.6088626}},
    {3, 0, {}, {}},
    {3, 1, {-0.815789474, 0.815789474, -0.652631579}, {-0.707106781, -0.707106781, 0}},
    {3, 3, {0.555555556, 0.555555556, 0.055555556}, {0.707106781, -0.707106781, 0}},
    {3, 4, {0.75, 1, 0.625}, {0, 1, 0}},
    {3, 5, {0.147524752, 0.623762376, -0.623762376}, {0, -0.707106781, -0.70710}},
    {4, 0, {0.45091894, 0.445091894, 0.427454053}, {0.590338666, -0.783675941, 0.1932673}},
    {4, 1, {-0.859785304, 0.817989265, -0.687828243}, {-0.596294974, -0.781413688, -0.183}},
    {4, 3, {0.544492298, 0.444922981, 0.044492298}, {0.626055550, -0.774883798, 0.0872327}},
    {4, 5, {0.14502761, 0.622513805, -0.748619508}, {0.11133171, -0.774612256, -0.62256}},
};

TEST(PovPrismSplines, HitsAndNormalsMatchPovRayTrace) {
    for (const Traced& c : kTraced) {
        std::vector<std::string> warnings;
        const Scene s = test::buildPov(kPrisms[c.shape], &warnings);
        ASSERT_EQ(s.objects.size(), 1u) << kPrisms[c.shape];
        EXPECT_TRUE(warnings.empty()) << warnings[0];
        const Hit h = test::shootPov(s, kFrom[c.ray], kDir[c.ray]);
        if (length(c.normal) == 0) {
            EXPECT_FALSE(h.valid()) << c.shape << " " << c.ray;
            continue;
        }
        ASSERT_TRUE(h.valid()) << c.shape << " " << c.ray;
        const Vec3 p = kFrom[c.ray] + h.t * normalize(kDir[c.ray]);
        EXPECT_LT(length(p - c.point), 2e-8) << c.shape << " " << c.ray;
        // POV-Ray reports cap normals as +y on both caps and its normals point either way; Rays'
        // point out of the solid.
        const double cosine = std::fabs(dot(h.normal, normalize(c.normal)));
        EXPECT_GT(cosine, 1 - 1e-6) << c.shape << " " << c.ray;
        if (std::fabs(c.normal.y) < 0.9) {
            EXPECT_LT(dot(h.normal, normalize(kDir[c.ray])), 0) << c.shape << " " << c.ray;
        }
    }
}

// An independent outline: each segment's spline sampled at 1,000 points, the even-odd rule over
// that polyline; the solid marched along each ray in steps of 2e-3, the first change bisected.
struct Curve {
    std::vector<double> x, z;
};

Curve sampled(const std::vector<Vec3>& p, int spline) {  // 0 quadratic, 1 cubic: one closed loop
    Curve c;
    const int n = 1000;
    const size_t segs = p.size() - (spline == 0 ? 2 : 3);
    for (size_t i = 0; i < segs; ++i)
        for (int k = 0; k < n; ++k) {
            const double u = double(k) / n;
            Vec3 q;
            if (spline == 0) {
                q = p[i + 1] + u * 0.5 * (p[i + 2] - p[i]) + u * u * 0.5 * (p[i] - 2 * p[i + 1] + p[i + 2]);
            } else {  // Catmull-Rom by its basis
                const double u2 = u * u, u3 = u2 * u;
                q = 0.5 * ((-u3 + 2 * u2 - u) * p[i] + (3 * u3 - 5 * u2 + 2) * p[i + 1] + (-3 * u3 + 4 * u2 + u) * p[i + 2] +
                           (u3 - u2) * p[i + 3]);
            }
            c.x.push_back(q.x);
            c.z.push_back(q.z);
        }
    return c;
}

bool insidePolyline(const Curve& c, double px, double pz) {
    bool in = false;
    for (size_t i = 0, j = c.x.size() - 1; i < c.x.size(); j = i++)
        if ((c.z[i] > pz) != (c.z[j] > pz) && px < c.x[i] + (pz - c.z[i]) * (c.x[j] - c.x[i]) / (c.z[j] - c.z[i])) in = !in;
    return in;
}

TEST(PovPrismSplines, RandomRaysAgreeWithABruteForceMarch) {
    // A wavy outline: quadratic and cubic, linear and conic sweeps.
    const std::vector<Vec3> pts = {{-1, 0, -1}, {1, 0, -1}, {1.5, 0, 0.5}, {0, 0, 1}, {-0.5, 0, 0.2}, {-1.2, 0, 0.8},
                                   {-1, 0, -1}, {1, 0, -1}, {1.5, 0, 0.5}};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(-1, 1);
    for (int spline = 0; spline < 2; ++spline)
        for (int conic = 0; conic < 2; ++conic) {
            const size_t count = spline == 0 ? pts.size() - 1 : pts.size();
            std::string text = std::string("prism { ") + (spline == 0 ? "quadratic_spline " : "cubic_spline ") +
                               (conic ? "conic_sweep " : "linear_sweep ") + "0.3, 1.2, " + std::to_string(count) + ", ";
            std::string pl;
            for (size_t i = 0; i < count; ++i)
                pl += (i ? ", " : "") + std::string("<") + std::to_string(pts[i].x) + "," + std::to_string(pts[i].z) + ">";
            const Scene s = test::buildPov(text + pl + " }");
            ASSERT_EQ(s.objects.size(), 1u);
            const Curve c = sampled(std::vector<Vec3>(pts.begin(), pts.begin() + long(count)), spline);
            auto inside = [&](Vec3 q) {
                if (!(q.y > 0.3 && q.y < 1.2)) return false;
                const double k = conic ? q.y : 1.0;
                return insidePolyline(c, q.x / k, q.z / k);
            };
            int hits = 0;
            for (int i = 0; i < 100; ++i) {
                const Vec3 from = 3.0 * normalize(Vec3{U(rng), U(rng), U(rng)}) + Vec3{0, 0.75, 0};
                const Vec3 to = Vec3{0.8 * U(rng), 0.75 + 0.45 * U(rng), 0.8 * U(rng)};
                const Vec3 d = normalize(to - from);
                double want = -1;
                for (double t = 0; t < 6; t += 2e-3)
                    if (inside(from + t * d)) {
                        double lo = t - 2e-3, hi = t;
                        for (int k = 0; k < 30; ++k) (inside(from + 0.5 * (lo + hi) * d) ? hi : lo) = 0.5 * (lo + hi);
                        want = hi;
                        break;
                    }
                const Hit h = test::shootPov(s, from, d);
                if (want < 0) {
                    EXPECT_FALSE(h.valid()) << spline << conic << " ray " << i;
                    continue;
                }
                ++hits;
                ASSERT_TRUE(h.valid()) << spline << conic << " ray " << i;
                EXPECT_NEAR(h.t, want, 1e-5) << spline << conic << " ray " << i;
                EXPECT_EQ(insideShape(s.objects[0], from + (h.t + 1e-3) * d), 1) << spline << conic << " ray " << i;
                EXPECT_EQ(insideShape(s.objects[0], from + (h.t - 1e-3) * d), 0) << spline << conic << " ray " << i;
                EXPECT_LT(dot(h.normal, d), 0) << spline << conic << " ray " << i;
            }
            EXPECT_GT(hits, 25);
        }
}

TEST(PovPrismSplines, SubPrismsHolesAndInside) {
    // Two quadratic sub-prisms: a square ring's outer and inner outlines (the inner a hole).
    const Scene s = test::buildPov(
        "prism { quadratic_spline 0, 1, 12, <-2,-2>, <2,-2>, <2,2>, <-2,2>, <-2,-2>, <2,-2>,"
        " <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1>, <1,-1> }");
    ASSERT_EQ(s.objects.size(), 1u);
    const Object& o = s.objects[0];
    EXPECT_EQ(insideShape(o, {0, 0.5, 0}), 0);     // the hole
    EXPECT_EQ(insideShape(o, {2.2, 0.5, 0}), 1);   // the ring (the outline bulges to x = 2.5)
    EXPECT_EQ(insideShape(o, {2.2, 1.5, 0}), 0);   // above
    EXPECT_EQ(insideShape(o, {3, 0.5, 0}), 0);
    EXPECT_FALSE(test::shootPov(s, {0, 5, 0}, {0, -1, 0}).valid());
    const Hit cap = test::shootPov(s, {2.2, 5, 0}, {0, -1, 0});
    EXPECT_NEAR(cap.t, 4, 1e-12);
    EXPECT_TRUE(length(cap.normal - Vec3{0, 1, 0}) < 1e-12);
    // Bezier: a closed loop of two segments; conic: the outline at height y scaled by y.
    const Scene b = test::buildPov("prism { bezier_spline conic_sweep 0, 2, 8, <1,0>, <1,1>, <-1,1>, <-1,0>, <-1,0>, <-1,-1>, <1,-1>, <1,0> }");
    ASSERT_EQ(b.objects.size(), 1u);
    EXPECT_EQ(insideShape(b.objects[0], {0.9, 1.5, 0}), 1);
    EXPECT_EQ(insideShape(b.objects[0], {0.9, 0.5, 0}), 0);
    // open: no caps.
    const Scene open = test::buildPov("prism { cubic_spline 0, 1, 7, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1>, <1,-1>, <1,1> open }");
    EXPECT_FALSE(test::shootPov(open, {0, 5, 0}, {0, -1, 0}).valid());
    // An unclosed quadratic outline draws nothing.
    const Scene unclosed = test::buildPov("prism { quadratic_spline 0, 1, 4, <-1,-1>, <1,-1>, <1,1>, <-1,1> }");
    EXPECT_TRUE(unclosed.objects.empty());
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
