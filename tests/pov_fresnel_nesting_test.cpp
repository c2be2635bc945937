// Fresnel reflection where a ray leaves an object while still inside another: POV-Ray 3.7 reflects
// nothing there by fresnel (measured: a glass sphere inside a sky object loses its internal
// reflections; constant reflection is traced as usual). Expected colours were rendered by povray
// 3.7.0.10 as one pixel along the camera's centre ray (16-bit PPM, sRGB decoded, assumed_gamma 1).
#include <gtest/gtest.h>

#include <string>

#include "rays/accel/bvh.h"
#include "rays/render/tracer.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

// The colour along the centre ray of `camera { location <0,0,-5> look_at 0 }` with a glass sphere
// (fresnel reflection only, ior 1.5) off the axis and `around` added.
Vec3 centre(const std::string& around) {
    const Scene s = test::loadPov("#version 3.7;\nglobal_settings { assumed_gamma 1.0 max_trace_level 15 }\n"
                                  "camera { location <0,0,-5> look_at 0 angle 30 }\nbackground { rgb 0.3 }\n"
                                  "sphere { <0.3,0.2,0>, 1 texture { pigment { rgbf <0.98, 1.0, 0.98, 1> } "
                                  "finish { ambient 0 diffuse 0 reflection { 0,1 fresnel } } } interior { ior 1.5 } }\n" +
                                  around + "\n")
                        .scene;
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    return Tracer(s, bvh, rs).tracePrimary(Ray{{0, 0, -5}, {0, 0, 1}}, ctx);
}

void expectColor(Vec3 got, Vec3 want) {
    EXPECT_NEAR(got.x, want.x, 2e-4);
    EXPECT_NEAR(got.y, want.y, 2e-4);
    EXPECT_NEAR(got.z, want.z, 2e-4);
}

TEST(PovFresnelNesting, InternalReflectionsStopWhereTheRayIsInsideAnotherObject) {
    // Alone: internal reflections bounce as usual.
    expectColor(centre(""), {0.31184, 0.32420, 0.31184});
    // The camera outside the plane's inside (z > 50): the same rules.
    expectColor(centre("plane { -z, -50 pigment { rgb 0.8 } finish { ambient 0.7 diffuse 0 } }"), {0.56156, 0.58421, 0.56156});
    // The same plane with the camera inside it (z < 50): no fresnel reflection inside the glass.
    expectColor(centre("plane { z, 50 pigment { rgb 0.8 } finish { ambient 0.7 diffuse 0 } }"), {0.54993, 0.57210, 0.54993});
    // The glass inside a clear sphere that the camera is outside of: as inside the plane.
    expectColor(centre("sphere { 0, 3 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } }"), {0.30022, 0.31210, 0.30022});
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
