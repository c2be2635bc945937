// POV-Ray's subsurface light transport (render/pov_subsurface.h, render/tracer_subsurface.cpp).
// Figures measured with POV-Ray 3.7.0.10 at 16 bits and File_Gamma 1 on a box of pigment
// <0.8, 0.5, 0.2>, diffuse 0.6 and ior 1.3 lit head-on by a parallel light of colour 1
// (docs/povray-lighting.md, "Subsurface light transport"): the middle of the lit face shows
// about diffuse·pigment through the boundary ((1 − F(0))² of a little more than it); near an
// edge and where the box is thin it darkens as the light leaves elsewhere; a surface with
// nothing of the object behind it (a plane, a disc, a triangle) shows twice what the box shows.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/render/pov_lighting.h"
#include "rays/render/pov_subsurface.h"
#include "rays/render/renderer.h"
#include "rays/render/tracer.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

// ∫ Rd(r) 2πr dr over the plane, by the midpoint rule on a logarithmic grid of r.
double integratedProfile(const Dipole& d) {
    double sum = 0;
    const double lo = 1e-7 * d.zr, hi = 60 / d.sigmaTr;
    const int steps = 200000;
    const double k = std::log(hi / lo) / steps;
    for (int i = 0; i < steps; ++i) {
        const double r = lo * std::exp((i + 0.5) * k);
        sum += dipoleProfile(d, r) * 2 * std::numbers::pi * r * (r * k);
    }
    return sum;
}

TEST(PovSubsurfaceDipole, TheProfileIntegratesToTheTotalReflectance) {
    for (double A : {1.0, 2.6, 8.5}) {  // boundaries of ior 1, 1.3 and 2
        for (double Rd : {0.05, 0.3, 0.66, 0.9}) {
            const Dipole d = makeDipole(Rd, 0.01, A);
            EXPECT_NEAR(dipoleTotalReflectance(d.albedo, A), Rd, 1e-9) << A << " " << Rd;  // the inversion
            EXPECT_NEAR(integratedProfile(d), Rd, 2e-3 * Rd) << A << " " << Rd;
        }
    }
}

TEST(PovSubsurfaceDipole, TotalsAndScales) {
    EXPECT_DOUBLE_EQ(dipoleTotalReflectance(1.0, 2.0), 1.0);
    EXPECT_DOUBLE_EQ(dipoleTotalReflectance(0.0, 2.0), 0.0);
    // Lower albedo, less light back; a mean free path ten times longer spreads it ten times wider.
    const Dipole a = makeDipole(0.5, 0.01, 2.0), b = makeDipole(0.5, 0.1, 2.0);
    EXPECT_NEAR(b.sigmaTr * 10, a.sigmaTr, 1e-9 * a.sigmaTr);
    EXPECT_NEAR(dipoleProfile(a, 0.02), 100 * dipoleProfile(b, 0.2), 1e-9 * dipoleProfile(a, 0.02));
}

std::string scene(const std::string& globals, const std::string& shape, double translucency,
                  const std::string& light = "light_source { <0, 1000, 0> rgb 1 parallel point_at 0 }") {
    return "global_settings { assumed_gamma 1 " + globals + " }\n" + light + "\n" + shape +
           " pigment { rgb <0.8, 0.5, 0.2> } finish { ambient 0 diffuse 0.6 subsurface { translucency " +
           std::to_string(translucency) + " } } interior { ior 1.3 } }\n";
}

const std::string kSubsurface = "subsurface { samples 400, 10 }";
const std::string kBox = "box { <-3, -1, -3>, <3, 0, 3>";

// The colour seen looking straight down at (x, ·, z).
Vec3 lookDown(const Scene& s, double x, double z) {
    const Bvh bvh(s.objects);
    RenderSettings rs;
    Tracer tracer(s, bvh, rs);
    TraceContext ctx;
    return tracer.tracePrimary(Ray{{x, 5, z}, {0, -1, 0}}, ctx, nullptr, nullptr);
}

TEST(PovSubsurface, AWideLitFaceShowsTheDiffusePigmentThroughTheBoundary) {
    std::vector<std::string> warnings;
    const Scene s = test::buildPov(scene(kSubsurface, kBox, 0.1), &warnings);
    EXPECT_TRUE(s.pov.subsurface.enabled);
    EXPECT_EQ(s.pov.subsurface.samples, 400);
    EXPECT_EQ(s.pov.subsurface.singleSamples, 10);
    for (const std::string& w : warnings) EXPECT_EQ(w.find("not rendered yet"), std::string::npos) << w;
    // The half space's total reflectance for the albedo found from diffuse·pigment (with A = 1.5,
    // rendered with A = 1), through (1 − F(0)) in and out; POV-Ray's <0.5018, 0.3230, 0.1396>.
    const double through = 1 - fresnelReflectance(1, 1 / 1.3);
    const Vec3 c = lookDown(s, 0.3, -0.2);
    const Vec3 pov{0.5018, 0.3230, 0.1396};
    for (int i = 0; i < 3; ++i) {
        const double v = 0.6 * Vec3{0.8, 0.5, 0.2}[i];
        const double expected = through * through * dipoleTotalReflectance(dipoleAlbedoFor(v, 1.5), 1.0);
        EXPECT_NEAR(c[i], expected, 0.02 * expected) << i;
        EXPECT_NEAR(c[i], pov[i], 0.1 * pov[i]) << i;
    }
    // Without global_settings' subsurface block POV-Ray lights the finish as a plain one (measured).
    const Vec3 plain = lookDown(test::buildPov(scene("", kBox, 0.1)), 0.3, -0.2);
    EXPECT_NEAR(plain.x, 0.48, 1e-9);
    EXPECT_NEAR(plain.z, 0.12, 1e-9);
}

TEST(PovSubsurface, LightLeavesThroughEdgesSoTheyDarken) {
    // Translucency 2 mm (0.2 units at the default 10 mm a unit): POV-Ray's face falls from 0.496
    // to 0.29 at the edge over some 0.6 units (red); Rays' from 0.496 to 0.27.
    const Scene s = test::buildPov(scene(kSubsurface, kBox, 2));
    const double middle = lookDown(s, 0, 0).x;
    double previous = 0;
    for (double x : {2.97, 2.9, 2.75, 2.5, 2.0}) {
        const double v = lookDown(s, x, 0).x;
        EXPECT_GT(v, previous) << x;
        previous = v;
    }
    EXPECT_LT(lookDown(s, 2.97, 0).x, 0.7 * middle);
    EXPECT_GT(lookDown(s, 2.97, 0).x, 0.4 * middle);
}

TEST(PovSubsurface, LightShinesThroughAThinSlabAsInPovRay) {
    // Lit from below only: a plain finish's top is dark, a translucent slab's top glows. POV-Ray's
    // top (translucency 2 mm): 0.05 thick <0.4675, 0.2927, 0.1158>, 0.3 thick <0.2432, 0.1114,
    // 0.0154> (Rays: <0.490, 0.311, 0.122> and <0.264, 0.138, 0.038>).
    const std::string below = "light_source { <0, -1000, 0> rgb 1 parallel point_at 0 }";
    const std::string thin = "box { <-3, -0.05, -3>, <3, 0, 3>", thick = "box { <-3, -0.3, -3>, <3, 0, 3>";
    EXPECT_EQ(lookDown(test::buildPov(scene("", thin, 2, below)), 0, 0), Vec3{});
    const Vec3 a = lookDown(test::buildPov(scene(kSubsurface, thin, 2, below)), 0, 0);
    EXPECT_NEAR(a.x, 0.4675, 0.06 * 0.4675);
    EXPECT_NEAR(a.y, 0.2927, 0.07 * 0.2927);
    EXPECT_NEAR(a.z, 0.1158, 0.07 * 0.1158);
    const Vec3 b = lookDown(test::buildPov(scene(kSubsurface, thick, 2, below)), 0, 0);
    EXPECT_NEAR(b.x, 0.2432, 0.1 * 0.2432);
    EXPECT_LT(b.y, 0.6 * b.x);
    EXPECT_LT(b.z, 0.05);  // the blue, most absorbed, hardly comes through
}

TEST(PovSubsurface, ASurfaceWithNothingBehindItShowsTwiceWhatASolidsFaceShows) {
    // POV-Ray (translucency 0.5 mm, head-on): a triangle <0.987, 0.627, 0.261>, a disc, a polygon
    // and a plane alike, a box, sphere, cylinder or closed mesh <0.50, 0.32, 0.14>.
    const Vec3 box = lookDown(test::buildPov(scene(kSubsurface, kBox, 0.1)), 0.3, -0.2);
    for (const char* open : {"plane { y, 0", "disc { 0, y, 4", "triangle { <-3, 0, -3>, <3, 0, -3>, <0, 0, 3>",
                             "polygon { 4, <-3, 0, -3>, <3, 0, -3>, <3, 0, 3>, <-3, 0, 3>"}) {
        const Vec3 c = lookDown(test::buildPov(scene(kSubsurface, open, 0.1)), 0.3, -0.2);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], 2 * box[i], 0.02 * box[i]) << open << " " << i;
    }
    // Light enters a flat shape from either side: a disc lit from below glows on top too.
    const std::string below = "light_source { <0, -1000, 0> rgb 1 parallel point_at 0 }";
    EXPECT_GT(lookDown(test::buildPov(scene(kSubsurface, "disc { 0, y, 4", 0.1, below)), 0.3, -0.2).x, 0.5);
    const Vec3 ball = lookDown(test::buildPov(scene(kSubsurface, "sphere { <0, -50, 0>, 50", 0.1)), 0, 0);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(ball[i], box[i], 0.02 * box[i]) << i;
}

TEST(PovSubsurface, MillimetresPerUnitScaleTheTranslucency) {
    // 2 mm at 10 mm a unit spreads as 20 mm at 100 mm a unit: the same picture.
    const Scene a = test::buildPov(scene(kSubsurface, kBox, 2));
    const Scene b = test::buildPov(scene(kSubsurface + " mm_per_unit 100", kBox, 20));
    EXPECT_DOUBLE_EQ(b.pov.subsurface.mmPerUnit, 100);
    EXPECT_DOUBLE_EQ(test::buildPov(scene(kSubsurface + " mm_per_unit 0", kBox, 2)).pov.subsurface.mmPerUnit, 10);
    for (double x : {2.95, 2.5, 0.0}) EXPECT_NEAR(lookDown(a, x, 0).x, lookDown(b, x, 0).x, 1e-9) << x;
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
