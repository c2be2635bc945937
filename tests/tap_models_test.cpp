// Stencil taps decided from tangent planes (npr/tap_models.h): a ridge and a valley seen from the
// front, with the true visible facet known, and the cases the planes must leave to a ray.
#include <gtest/gtest.h>

#include <cmath>

#include "rays/npr/tap_models.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

// A record on the plane through p with the (viewer-facing) normal n.
EdgeRecord facet(Vec3 p, Vec3 n) {
    n = normalize(n);
    EdgeRecord r{0, 0, 0, 0, 10.0f, {float(p.x), float(p.y), float(p.z)}, {float(n.x), float(n.y), float(n.z)}};
    return r;
}

// The eye looks along +z from z = -10.
Ray eyeRay(double x) { return Ray{{x, 0, -10}, {0, 0, 1}}; }

TEST(TapModels, TangentPlaneDistance) {
    const EdgeRecord wall = facet({3, 1, 5}, {0, 0, -1});
    EXPECT_NEAR(tangentPlaneT(eyeRay(0.4), wall), 15.0, 1e-9);
    // Unnormalised directions give the parameter along that direction.
    EXPECT_NEAR(tangentPlaneT(Ray{{0, 0, -10}, {0, 0, 2}}, wall), 7.5, 1e-9);
    // Grazing: the ray nearly parallel to the plane.
    EXPECT_LT(tangentPlaneT(Ray{{0, 0, -10}, {1, 0, 0.01}}, wall), 0);
    // Behind the eye.
    EXPECT_LT(tangentPlaneT(eyeRay(0), facet({0, 0, -20}, {0, 0, -1})), 0);
}

TEST(TapModels, RidgeShowsTheFartherPlaneHit) {
    // Convex crease along the y axis: z = |x| (the ridge points at the eye).
    const EdgeRecord left = facet({-1, 0, 1}, {-1, 0, -1}), right = facet({1, 0, 1}, {1, 0, -1});
    for (double x : {-0.8, -0.3, -0.05}) {
        EXPECT_EQ(creaseSide(eyeRay(x), left, right), 0) << x;
        EXPECT_EQ(creaseSide(eyeRay(x), right, left), 1) << x;
    }
    for (double x : {0.05, 0.3, 0.8}) {
        EXPECT_EQ(creaseSide(eyeRay(x), left, right), 1) << x;
        EXPECT_EQ(creaseSide(eyeRay(x), right, left), 0) << x;
    }
}

TEST(TapModels, ValleyShowsTheNearerPlaneHit) {
    // Concave crease: z = -|x| (the valley points away from the eye).
    const EdgeRecord left = facet({-1, 0, -1}, {1, 0, -1}), right = facet({1, 0, -1}, {-1, 0, -1});
    EXPECT_EQ(creaseSide(eyeRay(-0.3), left, right), 0);
    EXPECT_EQ(creaseSide(eyeRay(0.3), left, right), 1);
    EXPECT_EQ(creaseSide(eyeRay(-0.3), right, left), 1);
    EXPECT_EQ(creaseSide(eyeRay(0.3), right, left), 0);
}

TEST(TapModels, UndecidedCasesAreLeftToARay) {
    // Coplanar records: no crease for the planes to place.
    EXPECT_EQ(creaseSide(eyeRay(0.2), facet({-1, 0, 3}, {0, 0, -1}), facet({1, 0, 3}, {0, 0, -1})), -1);
    // One facet seen edge-on.
    EXPECT_EQ(creaseSide(eyeRay(0.2), facet({-1, 0, 3}, {0, 0, -1}), facet({1, 0, 3}, {1, 0, 0})), -1);
}

}}  // namespace RAYS_TEST_UNIT, namespace
