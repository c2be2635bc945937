// POV-Ray's dispersion (render/pov_dispersion.h) against POV-Ray 3.7: a white/black edge at x = 0
// on a wall behind a glass slab (ior 1.5, dispersion 1.2, 1 unit thick, turned 45° about y) seen
// along +z; each dispersion sample's ray is shifted by its own index, so near the edge some bands
// see white and the others black. The band edges and colours are POV-Ray's (16-bit linear renders
// with dispersion_samples 2 and 7, 800 pixels over 0.1 units from x = −0.38).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rays/accel/bvh.h"
#include "rays/render/pov_dispersion.h"
#include "rays/render/tracer.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

Scene slab(int samples) {
    return test::buildPov(
        "global_settings { assumed_gamma 1.0 max_trace_level 10 }\n"
        "box { <-5, -5, 0>, <5, 5, 1> pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 }\n"
        "  interior { ior 1.5 dispersion 1.2 dispersion_samples " + std::to_string(samples) + " } rotate y*45 translate z*2 }\n"
        "plane { z, 8 pigment { gradient x color_map { [0 rgb 1] [0.5 rgb 1] [0.5 rgb 0] [1 rgb 0] } scale 100 translate -50*x }\n"
        "  finish { ambient 1 diffuse 0 } }\n");
}

// The colour seen along +z from x: the camera column of POV-Ray's measurement at pixel p.
Vec3 seen(const Scene& s, double pixel) {
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    const double x = -0.38 + (pixel + 0.5) * 0.1 / 800;
    return Tracer(s, bvh, rs).tracePrimary(Ray{{x, 0, -10}, {0, 0, 1}}, ctx, nullptr, nullptr);
}

void expectColor(Vec3 got, Vec3 want, double tol) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

TEST(PovDispersion, SamplesSplitTheSpectrumAsPovRayDoes) {
    // The bands' colours add up to POV-Ray's near-white, and N = 2's first half is N = 4's first
    // two quarters.
    expectColor(povDispersionColor(0, 2) + povDispersionColor(1, 2), {0.9938, 1.0, 0.9962}, 1e-4);
    expectColor(povDispersionColor(0, 2), povDispersionColor(0, 4) + povDispersionColor(1, 4), 1e-12);
    EXPECT_DOUBLE_EQ(povDispersionExponent(0, 2), -0.25);
    EXPECT_NEAR(povDispersionExponent(2, 7), -1.0 / 7, 1e-15);
}

TEST(PovDispersion, EachBandRefractsByItsOwnIndex) {
    // POV-Ray, dispersion_samples 2: white up to pixel 236, then (0.9543, 0.7276, 0.0122) (the red
    // half alone sees white) up to 591, then black.
    const Scene two = slab(2);
    expectColor(seen(two, 200), {0.9938, 1.0, 0.9962}, 2e-4);
    expectColor(seen(two, 240), {0.9543, 0.7276, 0.0122}, 2e-4);
    expectColor(seen(two, 588), {0.9543, 0.7276, 0.0122}, 2e-4);
    expectColor(seen(two, 596), {0, 0, 0}, 2e-4);
    // dispersion_samples 7: the bands start at pixels 124, 214, 308, 407, 511, 620 and 735.
    const Scene seven = slab(7);
    const struct {
        double pixel;
        Vec3 color;
    } bands[] = {{170, {0.9573, 1.0, 0.7915}}, {260, {0.9543, 1.0, 0.425}}, {360, {0.9543, 0.8905, 0.098}},
                 {460, {0.9445, 0.5293, 0.0}}, {565, {0.6737, 0.1506, 0.0}}, {680, {0.257, 0.0, 0.0}},
                 {760, {0, 0, 0}}};
    for (const auto& b : bands) {
        SCOPED_TRACE(b.pixel);
        expectColor(seen(seven, b.pixel), b.color, 2e-3);  // band edges between the table's points
    }
    // Without dispersion the edge is sharp at the undispersed index's shift.
    const Scene plain = test::buildPov(
        "box { <-5, -5, 0>, <5, 5, 1> pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 }\n"
        "  interior { ior 1.5 } rotate y*45 translate z*2 }\n"
        "plane { z, 8 pigment { gradient x color_map { [0 rgb 1] [0.5 rgb 1] [0.5 rgb 0] [1 rgb 0] } scale 100 translate -50*x }\n"
        "  finish { ambient 1 diffuse 0 } }\n");
    expectColor(seen(plain, 400), {1, 1, 1}, 1e-9);
    expectColor(seen(plain, 410), {0, 0, 0}, 1e-9);
}

}}  // namespace RAYS_TEST_UNIT
}  // namespace rays
