#include <gtest/gtest.h>

#include "rays/math/transform.h"

using namespace rays;

TEST(Transform, InverseRoundTrip) {
    Transform m = Transform::translate({1, 2, 3}) * Transform::rotateCourse({10, 20, 30}) *
                  Transform::scale({2, 0.5, 3});
    Transform inv = m.inverse();
    Vec3 p{0.3, -1.2, 4.0};
    Vec3 q = inv.point(m.point(p));
    EXPECT_NEAR(q.x, p.x, 1e-12);
    EXPECT_NEAR(q.y, p.y, 1e-12);
    EXPECT_NEAR(q.z, p.z, 1e-12);
}

TEST(Transform, RotateZMapsXToY) {
    Vec3 v = Transform::rotateAxis(2, 90).vector({1, 0, 0});
    EXPECT_NEAR(v.x, 0, 1e-12);
    EXPECT_NEAR(v.y, 1, 1e-12);
}

TEST(Transform, CourseOrderAppliesZFirst) {
    // Course: R = Rx·Ry·Rz. Rotating x by z 90 gives y; then y 90 leaves y; then x 90 gives z.
    Vec3 v = Transform::rotateCourse({90, 90, 90}).vector({1, 0, 0});
    EXPECT_NEAR(v.z, 1, 1e-12);
    // POV-Ray: x first: x stays x, y 90 takes x to -z, z 90 leaves -z.
    Vec3 w = Transform::rotatePovray({90, 90, 90}).vector({1, 0, 0});
    EXPECT_NEAR(w.z, -1, 1e-12);
}
