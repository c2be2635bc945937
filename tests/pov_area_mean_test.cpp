// POV-Ray's weighing of an area light's samples (render/pov_area_mean.h), sample by sample; the
// renders it reproduces are in tests/pov_lights_test.cpp (PovAreaLight).
#include <gtest/gtest.h>

#include <vector>

#include "rays/render/pov_area_mean.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

// The weight of each sample along one axis of n samples (the other axis has one).
std::vector<double> weights(int n) {
    std::vector<double> w;
    for (int k = 0; k < n; ++k)
        w.push_back(povAreaMean(n, 1, -1, [&](int u, int) { return Vec3(u == k ? 1.0 : 0.0); }).x);
    return w;
}

void expectWeights(int n, const std::vector<double>& want) {
    const std::vector<double> got = weights(n);
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) EXPECT_DOUBLE_EQ(got[i], want[i]) << "n " << n << " sample " << i;
}

TEST(PovAreaMean, OddCountsShareTheirMiddleSampleEvenCountsSplitApart) {
    expectWeights(1, {1});
    expectWeights(2, {0.5, 0.5});
    expectWeights(3, {0.25, 0.5, 0.25});                        // the trapezoid rule
    expectWeights(5, {0.125, 0.25, 0.25, 0.25, 0.125});
    expectWeights(4, {0.25, 0.25, 0.25, 0.25});                 // the plain mean
    expectWeights(6, {0.125, 0.25, 0.125, 0.125, 0.25, 0.125});  // two threes, side by side
    expectWeights(8, std::vector<double>(8, 0.125));
}

TEST(PovAreaMean, TheTwoAxesWeighIndependently) {
    // 3 × 5: the product of the axes' weights.
    const double w3[3] = {0.25, 0.5, 0.25}, w5[5] = {0.125, 0.25, 0.25, 0.25, 0.125};
    for (int u = 0; u < 3; ++u)
        for (int v = 0; v < 5; ++v)
            EXPECT_DOUBLE_EQ(povAreaMean(3, 5, -1, [&](int a, int b) { return Vec3(a == u && b == v ? 1.0 : 0.0); }).x,
                             w3[u] * w5[v]);
}

TEST(PovAreaMean, AdaptiveStopsWhereAPartsCornersAgree) {
    // 9 × 9 samples, all lit but the middle column: unseen when the whole light's corners decide
    // (adaptive 0); seen from depth 1 on, where the middle column is a corner.
    auto mean = [](int adaptive) {
        return povAreaMean(9, 9, adaptive, [](int u, int) { return Vec3(u == 4 ? 0.0 : 1.0); }).x;
    };
    EXPECT_DOUBLE_EQ(mean(0), 1.0);
    EXPECT_DOUBLE_EQ(mean(1), 0.875);
    EXPECT_DOUBLE_EQ(mean(-1), 0.875);
    // A column off the halving points (u = 3) is seen only where the parts holding it are split.
    auto off = [](int adaptive) {
        return povAreaMean(9, 9, adaptive, [](int u, int) { return Vec3(u == 3 ? 0.0 : 1.0); }).x;
    };
    EXPECT_DOUBLE_EQ(off(2), 1.0);    // [2, 4] at depth 2: its corners lit
    EXPECT_DOUBLE_EQ(off(3), 0.875);  // split once more: u = 3 weighs 1/8
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
