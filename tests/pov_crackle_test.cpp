// crackle's form, metric, offset and solid (pattern/crackle.h): the value statistics of POV-Ray
// 3.7.0.10 over 4,000 random points of [−25, 25]³ (`function { pattern { crackle ... } }` printed
// with #debug), and the nearest-seed search against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "rays/pattern/crackle.h"
#include "rays/pattern/noise.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

// Points uniform in [−25, 25]³ from a fixed LCG.
std::vector<Vec3> randomPoints(int n) {
    uint64_t s = 12345;
    auto next = [&] {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return double(s >> 11) * 0x1.0p-53;
    };
    std::vector<Vec3> out;
    for (int i = 0; i < n; ++i) out.push_back(Vec3{next(), next(), next()} * 50.0 - Vec3(25));
    return out;
}

// Mean and spread of the pigment `crackle <modifiers>` (grey ramp) of a scene's sphere.
std::pair<double, double> stats(const std::string& modifiers) {
    const test::PovLoaded b = test::loadPov("sphere { 0, 1 pigment { crackle " + modifiers +
                                           " color_map { [0 rgb 0] [1 rgb 1] } } }");
    const PovSurface& surface = b.scene.povSurfaces.at(size_t(b.scene.objects.at(0).material.pov));
    double sum = 0, sum2 = 0;
    const std::vector<Vec3> points = randomPoints(4000);
    for (const Vec3& p : points) {
        const double v = b.scene.pigments.atRoot(surface.pigment, p).rgb.x;
        sum += v;
        sum2 += v * v;
    }
    const double mean = sum / double(points.size());
    return {mean, std::sqrt(sum2 / double(points.size()) - mean * mean)};
}

TEST(PovCrackle, ValuesSpreadAsPovRaysDo) {
    struct Case {
        const char* modifiers;
        double mean, sd;  // POV-Ray's
    };
    const Case cases[] = {{"", 0.1928, 0.1538},
                          {"form <1, 0, 0>", 0.5215, 0.1696},
                          {"form <0, 1, 0>", 0.7137, 0.1392},
                          {"form <0, 0, 1>", 0.8364, 0.1162},
                          {"form <0.5, 0.5, -0.6>", 0.1239, 0.0939},
                          {"metric 1 form <1, 0, 0>", 0.7433, 0.2151},
                          {"metric 1", 0.2771, 0.2204},
                          {"metric 3 form <1, 0, 0>", 0.4705, 0.1530},
                          {"metric 4 form <1, 0, 0>", 0.4507, 0.1467},
                          {"offset 0.5 form <1, 0, 0>", 0.7317, 0.1168},
                          {"offset 0.5 metric 1 form <1, 0, 0>", 0.9819, 0.0564},
                          {"solid", 0.5076, 0.1224}};
    for (const Case& c : cases) {
        const auto [mean, sd] = stats(c.modifiers);
        EXPECT_NEAR(mean, c.mean, 0.02) << c.modifiers;
        EXPECT_NEAR(sd, c.sd, 0.02) << c.modifiers;
    }
}

// The three nearest seeds among the 9×9×9 cubes round p (a seed farther than 4 cubes is never
// among them for these points).
double bruteForce(Vec3 p, const pattern::Crackle& c) {
    std::vector<double> d;
    const int64_t x0 = int64_t(std::floor(p.x)), y0 = int64_t(std::floor(p.y)), z0 = int64_t(std::floor(p.z));
    for (int64_t k = z0 - 4; k <= z0 + 4; ++k)
        for (int64_t j = y0 - 4; j <= y0 + 4; ++j)
            for (int64_t i = x0 - 4; i <= x0 + 4; ++i) {
                const Vec3 e = pattern::crackleSeed(i, j, k) - p;
                const double m = c.metric;
                d.push_back(std::pow(std::pow(std::fabs(e.x), m) + std::pow(std::fabs(e.y), m) + std::pow(std::fabs(e.z), m) +
                                         std::pow(std::fabs(c.offset), m),
                                     1 / m));
            }
    std::sort(d.begin(), d.end());
    return std::clamp(c.form.x * d[0] + c.form.y * d[1] + c.form.z * d[2], 0.0, 1.0);
}

TEST(PovCrackle, NearestSeedsAreExact) {
    const pattern::Crackle forms[] = {{{-1, 1, 0}, 2, 0, false},  {{0, 0, 1}, 2, 0, false},   {{0.3, 0, 0}, 1, 0.7, false},
                                      {{-0.2, 0, 0.9}, 2, 0, false}, {{0, 0, 0.5}, 4, 0.3, false}, {{0.4, 0.4, -0.4}, 3, 0, false}};
    for (const pattern::Crackle& c : forms)
        for (const Vec3& p : randomPoints(300)) EXPECT_NEAR(pattern::crackleValue(p, c), bruteForce(p, c), 1e-12) << p.x << " " << p.y;
}

// Metric 2 keeps the seeds of the cubes round the last ones looked at (per thread): points
// walking in small steps, three walks interleaved as a sample's rays are, and the cubes they share
// or evict, still find the exact nearest seeds (and a solid cell's seed).
TEST(PovCrackle, NearestSeedsAreExactAlongInterleavedWalks) {
    const pattern::Crackle forms[] = {{{-1, 1, 0}, 2, 0, false}, {{0.2, -0.4, 0.9}, 2, 0.3, false}};
    const pattern::Crackle solid{{-1, 1, 0}, 2, 0, true};
    Vec3 at[3] = {{-3.7, 0.2, 5.1}, {0.4, -8.3, -2.2}, {12.5, 3.3, -0.9}};
    const Vec3 step[3] = {{0.013, 0.007, -0.011}, {-0.009, 0.017, 0.004}, {0.021, -0.003, 0.015}};
    for (int i = 0; i < 600; ++i)
        for (int w = 0; w < 3; ++w) {
            const Vec3 p = at[w] += step[w];
            for (const pattern::Crackle& c : forms) EXPECT_NEAR(pattern::crackleValue(p, c), bruteForce(p, c), 1e-12) << p.x;
            Vec3 nearest;
            double best = INFINITY;
            for (int k = -2; k <= 2; ++k)
                for (int j = -2; j <= 2; ++j)
                    for (int l = -2; l <= 2; ++l) {
                        const Vec3 s = pattern::crackleSeed(int64_t(std::floor(p.x)) + l, int64_t(std::floor(p.y)) + j,
                                                            int64_t(std::floor(p.z)) + k);
                        if (length(s - p) < best) best = length(s - p), nearest = s;
                    }
            EXPECT_EQ(pattern::crackleValue(p, solid), std::clamp(pattern::noise(nearest), 0.0, 1.0)) << p.x;
        }
}

TEST(PovCrackle, EachCubesSeedLiesUniformlyInIt) {
    double sum[3] = {}, sum2[3] = {};
    const int n = 20000;
    for (int c = 0; c < n; ++c) {
        const int64_t i = c % 37 - 18, j = c / 37 % 29 - 14, k = c / (37 * 29) - 9;
        const Vec3 s = pattern::crackleSeed(i, j, k);
        const Vec3 f = s - Vec3{double(i), double(j), double(k)};
        for (int a = 0; a < 3; ++a) {
            ASSERT_GT(f[a], 0);
            ASSERT_LT(f[a], 1);
            sum[a] += f[a];
            sum2[a] += f[a] * f[a];
        }
    }
    for (int a = 0; a < 3; ++a) {  // uniform: mean 1/2, variance 1/12
        EXPECT_NEAR(sum[a] / n, 0.5, 0.01);
        EXPECT_NEAR(sum2[a] / n - (sum[a] / n) * (sum[a] / n), 1.0 / 12, 0.003);
    }
}

TEST(PovCrackle, SolidCellsHoldOneValue) {
    const pattern::Crackle solid{{-1, 1, 0}, 2, 0, true};
    const pattern::Crackle edges{{-1, 1, 0}, 2, 0, false};
    int inside = 0;
    for (const Vec3& p : randomPoints(300)) {
        if (pattern::crackleValue(p, edges) < 0.05) continue;  // near a cell wall
        ++inside;
        const Vec3 q = p + Vec3{0.004, -0.003, 0.002};  // closer to the same seed than to any other
        EXPECT_EQ(pattern::crackleValue(p, solid), pattern::crackleValue(q, solid));
        EXPECT_NE(pattern::crackleValue(p, edges), pattern::crackleValue(q, edges));
    }
    EXPECT_GT(inside, 200);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
