// POV-Ray pigment patterns rendered (src/rays/pattern, pov/pigment_compile): pattern values, wave
// types, colour and pigment maps, block patterns and transformations. Expected values were printed
// by POV-Ray 3.7.0.10 itself: `#declare F = function { pigment { P } }` and
// `#debug str(F(x, y, z).red, 0, 6)` at the points below.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "rays/accel/bvh.h"
#include "rays/error.h"
#include "rays/render/renderer.h"
#include "rays/render/tracer.h"
#include "rays/pattern/black_hole.h"
#include "rays/pattern/wave.h"
#include "rays/pov/load_pov.h"
#include "support/pov_scene.h"

namespace rays {
namespace { namespace RAYS_TEST_UNIT {

using Built = test::PovLoaded;

Built build(const std::string& text) { return test::loadPov(text); }

// The pigment of the first object of a scene, evaluated at world points.
struct Probe {
    Built b;
    const PovSurface& surface() const {
        return b.scene.povSurfaces.at(size_t(b.scene.objects.at(0).material.pov));
    }
    pattern::Rgbft at(Vec3 p) const { return b.scene.pigments.atRoot(surface().pigment, p); }
};

Probe pigment(const std::string& body, const std::string& object = "sphere { 0, 1 ", const std::string& after = "") {
    return Probe{build(object + "pigment { " + body + " } " + after + "}")};
}

const char* kGrey = " color_map { [0 rgb 0] [1 rgb 1] }";

// Mean and standard deviation of the probe's value (red) at n points given one by one by `point`.
struct Spread {
    double mean, sd;
};
Spread spreadOf(const Probe& pr, int n, const std::function<Vec3()>& point) {
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
        const double v = pr.at(point()).rgb.x;
        sum += v;
        sum2 += v * v;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(sum2 / n - mean * mean)};
}

struct Sample {
    Vec3 p;
    double value;
};

void expectValues(const std::string& body, std::initializer_list<Sample> samples, double tol = 1e-6) {
    const Probe pr = pigment(body + kGrey);
    ASSERT_GE(pr.surface().pigment, 0) << body;
    for (const Sample& s : samples) EXPECT_NEAR(pr.at(s.p).rgb.x, s.value, tol) << body << " at " << s.p.x << " " << s.p.y << " " << s.p.z;
}

TEST(PovPattern, PatternPigmentsMadeOneAfterAnotherKeepTheirOwnColours) {
    // Each top-level object is built as soon as it is read and its items freed: a pigment made
    // later at a freed pigment's address must not be taken for it (gamma/gamma_showcase.pov's
    // striped spheres took each other's colours so).
    const Built b = build("#macro P(C) pigment { gradient x color_map { [0 rgb C] [1 rgb C] } } #end\n"
                          "#for (I, 0, 49) sphere { 0, 1 P(I / 50) } #end");
    ASSERT_EQ(b.scene.objects.size(), 50u);
    for (size_t i = 0; i < 50; ++i) {
        const PovSurface& s = b.scene.povSurfaces.at(size_t(b.scene.objects[i].material.pov));
        ASSERT_GE(s.pigment, 0) << i;
        EXPECT_NEAR(b.scene.pigments.atRoot(s.pigment, {0.5, 0, 0}).rgb.x, double(i) / 50, 1e-9) << i;
    }
}

TEST(PovPattern, ContinuousPatternsMatchPovRay) {
    expectValues("gradient x", {{{0.3, 0.2, 0.1}, 0.3}, {{-0.7, 0.25, 0.6}, 0.3}, {{2.5, 3.5, -1.2}, 0.5}, {{1, 0, 0}, 1}, {{2, 0, 0}, 0}});
    expectValues("gradient <1, 1, 0>", {{{0.3, 0.2, 0.1}, 0.353553}, {{1.3, 0.5, -0.4}, 0.272792}, {{-0.7, 0.25, 0.6}, 0.681802}});
    expectValues("radial", {{{0.3, 0.2, 0.1}, 0.948792}, {{1.3, 0.5, -0.4}, 0.047498}, {{-0.7, 0.25, 0.6}, 0.612781}, {{0.1, 0, -0.9}, 0.232378}});
    expectValues("onion", {{{0.3, 0.2, 0.1}, 0.374166}, {{1.3, 0.5, -0.4}, 0.449138}, {{2.5, 3.5, -1.2}, 0.465423}});
    expectValues("spherical", {{{0.3, 0.2, 0.1}, 0.625834}, {{-0.7, 0.25, 0.6}, 0.044751}, {{1.3, 0.5, -0.4}, 0}});
    expectValues("cylindrical", {{{0.3, 0.2, 0.1}, 0.683772}, {{-0.7, 0.25, 0.6}, 0.078046}, {{2.5, 3.5, -1.2}, 0}});
    expectValues("planar", {{{0.3, 0.2, 0.1}, 0.8}, {{-0.7, 0.25, 0.6}, 0.75}, {{2.5, 3.5, -1.2}, 0}});
    expectValues("boxed", {{{0.3, 0.2, 0.1}, 0.7}, {{-0.7, 0.25, 0.6}, 0.3}, {{0.1, 0, -0.9}, 0.1}});
    expectValues("leopard", {{{0.3, 0.2, 0.1}, 0.039207}, {{1.3, 0.5, -0.4}, 0.123333}, {{2.5, 3.5, -1.2}, 0.052037}});
    // wood without turbulence: rings round the z-axis, triangle wave by default.
    expectValues("wood", {{{0.3, 0.4, 0}, 1}, {{0.3, 0.4, 5}, 1}, {{0.1, 0, 0}, 0.2}, {{0.7, 0, 0}, 0.6}, {{1.2, 0, 0}, 0.39998}});
    expectValues("marble", {{{0.3, 0.4, 0}, 0.6}, {{0.7, 0, 0}, 0.6}, {{1.2, 0, 0}, 0.39998}});
}

TEST(PovPattern, FunctionPatternsRunTheUserFunction) {
    // Values printed by POV-Ray 3.7.
    expectValues("function { x * x + y }", {{{0.5, 0.1, 0}, 0.35}, {{0.9, 0.5, 0}, 0.31}, {{-0.3, -0.5, 0}, 0.59}});
    expectValues("function { 1.2 } triangle_wave", {{{0, 0, 0}, 0.4}});
    expectValues("function { 1 } phase 0.0001", {{{0, 0, 0}, 0.00009}});
    expectValues("function { 2 } phase 0.0001", {{{0, 0, 0}, 0.0001}});
    // A pattern function of a pattern Rays does not render gives 0: a function calling one is noted.
    const Built b = build("#declare P = function { pattern { tiling 26 } }\n"
                          "sphere { 0, 1 pigment { function { P(x, y, z) } } }");
    EXPECT_EQ(b.scene.povSurfaces.at(0).pigment, -1);
    ASSERT_EQ(b.warnings.size(), 1u);
    EXPECT_NE(b.warnings[0].find("pattern function calling a pattern or pigment function"), std::string::npos);
}

// The object pattern (values printed by POV-Ray 3.7 through pigment and pattern functions): the
// first list item outside the object, the second inside, a point on the surface outside; the
// object's own transformations and modifiers apply, the pattern's on top.
TEST(PovPattern, ObjectPatternIsTheFirstItemOutsideTheSecondInside) {
    const Probe two = pigment("object { sphere { 0, 1 } rgb <1, 0, 0>, rgb <0, 1, 0> }", "plane { y, -5 ");
    EXPECT_TRUE(two.b.warnings.empty());
    EXPECT_EQ(two.at({0, 0, 0}).rgb, (Vec3{0, 1, 0}));
    EXPECT_EQ(two.at({0.999, 0, 0}).rgb, (Vec3{0, 1, 0}));
    EXPECT_EQ(two.at({1, 0, 0}).rgb, (Vec3{1, 0, 0}));
    EXPECT_EQ(two.at({2, 0, 0}).rgb, (Vec3{1, 0, 0}));
    const Probe bare = pigment("object { sphere { 0, 1 } }", "plane { y, -5 ");  // blue outside, green inside
    EXPECT_EQ(bare.at({0, 0, 0}).rgb, (Vec3{0, 1, 0}));
    EXPECT_EQ(bare.at({2, 0, 0}).rgb, (Vec3{0, 0, 1}));
    // The object's translation, then the pattern's scale: a sphere of radius 2 round x = 4.
    const Probe moved = pigment("object { sphere { 0, 1 translate x*2 } rgb 0, rgb 1 } scale 2", "plane { y, -5 ");
    for (const auto& [x, v] : {std::pair{0.0, 0.0}, {2.0, 0.0}, {4.0, 1.0}, {5.9, 1.0}, {6.1, 0.0}})
        EXPECT_EQ(moved.at({x, 0, 0}).rgb.x, v) << x;
    // Modifiers written after the object inside the braces move the object.
    const Probe after = pigment("object { sphere { 0, 1 } translate x*2 rgb 0, rgb 1 }", "plane { y, -5 ");
    EXPECT_EQ(after.at({0, 0, 0}).rgb.x, 0);
    EXPECT_EQ(after.at({2, 0, 0}).rgb.x, 1);
    // CSG and planes have their inside; an object identifier; pigments as the list's items.
    const Probe csg = pigment("object { difference { box { -1, 1 } sphere { 0, 0.5 } } rgb 0, rgb 1 }", "plane { y, -5 ");
    EXPECT_EQ(csg.at({0, 0, 0}).rgb.x, 0);
    EXPECT_EQ(csg.at({0.8, 0, 0}).rgb.x, 1);
    EXPECT_EQ(csg.at({1.2, 0, 0}).rgb.x, 0);
    const Probe half = pigment("object { plane { y, 0 } rgb 0, rgb 1 } translate y", "sphere { 0, 1 ");
    EXPECT_EQ(half.at({0, 0.5, 0}).rgb.x, 1);
    EXPECT_EQ(half.at({0, 1.5, 0}).rgb.x, 0);
    const Built maps = build("#declare S = sphere { 0, 1 }\n"
                             "plane { y, -5 pigment { object { S pigment { gradient x }, pigment { rgb <0, 1, 0> } } } }");
    EXPECT_TRUE(maps.warnings.empty());
    const int root = maps.scene.povSurfaces.at(0).pigment;
    ASSERT_GE(root, 0);
    EXPECT_EQ(maps.scene.pigments.atRoot(root, {0.3, 0, 0}).rgb, (Vec3{0, 1, 0}));
    EXPECT_NEAR(maps.scene.pigments.atRoot(root, {1.3, 0, 0}).rgb.x, 0.3, 1e-9);
    EXPECT_NEAR(maps.scene.pigments.atRoot(root, {1.7, 0, 0}).rgb.y, 0.7, 1e-9);
    // As a pattern function: 1 inside, 0 outside and on the surface.
    const Built fn = build("#declare F = function { pattern { object { sphere { 0, 1 } } } }\n"
                           "plane { y, -5 pigment { function { F(x, y, z) * 0.5 + 0.25 }" + std::string(kGrey) + " } }");
    EXPECT_TRUE(fn.warnings.empty());
    const int f = fn.scene.povSurfaces.at(0).pigment;
    ASSERT_GE(f, 0);
    EXPECT_NEAR(fn.scene.pigments.atRoot(f, {0, 0, 0}).rgb.x, 0.75, 1e-9);
    EXPECT_NEAR(fn.scene.pigments.atRoot(f, {1, 0, 0}).rgb.x, 0.25, 1e-9);
    EXPECT_NEAR(fn.scene.pigments.atRoot(f, {2, 0, 0}).rgb.x, 0.25, 1e-9);
}

// A function pattern calling a pigment function whose pattern is a function calling a pigment
// function of an object pattern (benchmark.pov's XsinPigm): values printed by POV-Ray 3.7.
TEST(PovPattern, FunctionPatternsNestThroughPigmentFunctions) {
    const Built b = build(
        "#declare P = function { pigment { object { sphere { 0, 1 } rgb 1, rgb 0 } } }\n"
        "#declare Q = function { pigment { function { P(x*2, y, z).gray } } }\n"
        "plane { y, -5 pigment { function { Q(x, y, z).gray } color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } } }");
    EXPECT_TRUE(b.warnings.empty());
    const int r = b.scene.povSurfaces.at(0).pigment;
    ASSERT_GE(r, 0);
    // The grey of white is 0.297 + 0.589 + 0.114, 1 within rounding.
    const auto off = [&](Vec3 p, Vec3 want) { return length(b.scene.pigments.atRoot(r, p).rgb - want); };
    EXPECT_NEAR(off({0, 0, 0}, {1, 0, 0}), 0, 1e-12);
    EXPECT_NEAR(off({0.4, 0, 0}, {1, 0, 0}), 0, 1e-12);
    EXPECT_NEAR(off({0.6, 0, 0}, {0, 0, 1}), 0, 1e-12);
    EXPECT_NEAR(off({0.6, 0.9, 0}, {0, 0, 1}), 0, 1e-12);
    EXPECT_NEAR(off({0, 0.99, 0}, {1, 0, 0}), 0, 1e-12);
}

TEST(PovPattern, MandelMatchesPovRay) {
    // Values printed by POV-Ray 3.7.
    expectValues("mandel 25", {{{0, 0, 0}, 1}, {{1, 1, 0}, 0}, {{-2.5, 0, 0}, 0}, {{0.5, 0.5, 0}, 0.12},
                               {{0.3, 0.6, 0}, 0.52}, {{-0.75, 0.2, 0}, 0.56}, {{0.38, 0.3, 0}, 0.68}});
    expectValues("mandel 25 exterior 2, 0.5 interior 1, 2", {{{0.5, 0.5, 0}, 0.642568}, {{0.1, 0.1, 0}, 0.282843}});
    expectValues("mandel 25 exponent 3", {{{0.5, 0.5, 0}, 1}, {{0.3, 0.4, 0}, 1}});
    expectValues("mandel 25 exterior 7, 4", {{{0.5, 0.5, 0}, 0.75}, {{0.3, 0.6, 0}, 0.25}});
    // The built-in map: black outside, magenta to cyan, cyan inside.
    const Probe m = pigment("mandel 25");
    EXPECT_NEAR(length(m.at({0.5, 0.5, 0}).rgb - Vec3{0, 1, 1}), 0, 1e-6);
    EXPECT_NEAR(length(m.at({1, 1, 0}).rgb), 0, 1e-6);
}

TEST(PovPattern, MandelInteriorSixIsRealSquaredPlusFactorTimesImaginarySquared) {
    // Values printed by POV-Ray 3.7 (frequency 0.01 shows them unwrapped): zr² + factor·zi².
    expectValues("mandel 30 interior 6, 1 frequency 0.01", {{{0.1, 0.2, 0}, 0.000527864}, {{-0.5, 0.3, 0}, 0.00175993}}, 5e-9);
    expectValues("mandel 30 interior 6, 2 frequency 0.01", {{{0.1, 0.2, 0}, 0.001027864}, {{-0.5, 0.3, 0}, 0.00205112},
                                                           {{0.25, 0, 0}, 0.002232444}}, 5e-9);
}

TEST(PovPattern, MagnetMatchesPovRay) {
    // Values printed by POV-Ray 3.7 (single-precision colours): the orbit stops when |z|² > 10000
    // or |z − 1|² < 0.0001; mandel's colouring types; black to white by default.
    expectValues("magnet 1 mandel 30", {{{0, 0, 0}, 1}, {{-1, 0.5, 0}, 0.13333334}, {{1.5, 0.3, 0}, 0.600000024},
                                        {{0.2, -1.3, 0}, 0.266666681}, {{1.133, -0.796, 0}, 1}}, 2e-7);
    expectValues("magnet 2 mandel 30 exterior 2, 1", {{{0, 0, 0}, 0.992524087}, {{-1, 0.5, 0}, 0.999994934},
                                                      {{1.5, 0.3, 0}, 0.000001606}, {{0.2, -1.3, 0}, 0.000463304}}, 2e-7);
    expectValues("magnet 1 julia <0.4, -0.3>, 30 interior 1, 1",
                 {{{0, 0, 0}, 0}, {{-1, 0.5, 0}, 0.12527065}, {{1.5, 0.3, 0}, 0.256722569}, {{-0.15, 0.416, 0}, 0.191056967},
                  {{1.133, -0.796, 0}, 0.258017629}}, 2e-7);
    expectValues("magnet 2 julia <0.2, 0.6>, 25 exterior 6, 0.5 interior 3, 1",
                 {{{0, 0, 0}, 0.240695924}, {{1.5, 0.3, 0}, 0.500006557}, {{0.2, -1.3, 0}, 0.240695283}}, 2e-7);
    EXPECT_NEAR(pigment("magnet 1 mandel 30").at({-1, 0.5, 0}).rgb.y, 0.13333334, 2e-7);  // no built-in map
}

TEST(PovPattern, JuliaMatchesPovRay) {
    // Values printed by POV-Ray 3.7 (as the file's comment says; z starts at the point, c is fixed).
    expectValues("julia <0.353, 0.288>, 30", {{{0.1, 0.2, 0}, 1}, {{-0.5, 0.3, 0}, 0.2}, {{0.7, -0.2, 0}, 0.1},
                                               {{0.01, 0.01, 0}, 1}, {{1.5, 0.5, 0}, 0}});
    // The comma before the iterations is optional (textures/patterns/fractals1.pov leaves it out);
    // values printed by POV-Ray 3.7 for `julia <.3,.44> 30` with and without `interior 1,1`.
    expectValues("julia <.3,.44> 30", {{{-1, -0.2, 0}, 0.033333}, {{-0.34, 0, 0}, 0.433333}, {{0.32, 0.2, 0}, 1}});
    expectValues("julia <.3,.44> 30 interior 1,1", {{{-0.01, 0.1, 0}, 0.100499}, {{0.32, 0.2, 0}, 0.063851}});
    // The built-in map is mandel's: cyan inside.
    const Probe j = pigment("julia <0.353, 0.288>, 30");
    EXPECT_NEAR(length(j.at({0.1, 0.2, 0}).rgb - Vec3{0, 1, 1}), 0, 1e-6);
}

TEST(PovPattern, Spiral1MatchesPovRay) {
    // Values printed by POV-Ray 3.7: r + z + N·(turns about z from −y), triangle wave by default.
    expectValues("spiral1 3", {{{0.3, 0.2, 0}, 0.782591}, {{0.3, 0.2, 0.25}, 0.717409}, {{-0.5, 0.1, 0.1}, 0.468735},
                               {{0.1, -0.7, 0.6}, 0.749695}, {{1.3, 0.4, -0.2}, 0.1053}}, 2e-6);
    expectValues("spiral1 2 scale 0.5 frequency 2", {{{0.3, 0.2, 0}, 0.366931}, {{0.3, 0.2, 0.25}, 0.366951},
                                                     {{-0.5, 0.1, 0.1}, 0.627784}, {{0.1, -0.7, 0.6}, 0.637423},
                                                     {{1.3, 0.4, -0.2}, 0.338863}}, 2e-6);
    // As a pattern function (ramp wave): 0.391295690 printed by POV-Ray 3.7.
    const Built f = build("#declare S = function { pattern { spiral1 3 ramp_wave } }\n"
                          "#if (abs(S(0.3, 0.2, 0) - 0.3912957) < 1e-6) sphere { 0, 1 } #end");
    EXPECT_TRUE(f.warnings.empty());
    EXPECT_EQ(f.scene.objects.size(), 1u);
}

TEST(PovPattern, Spiral2MatchesPovRay) {
    // Values printed by POV-Ray 3.7: T(r + z + N·a) + T(r), T a unit triangle; triangle wave by default.
    expectValues("spiral2 1", {{{0.3, 0.2, 0}, 0.625645936}, {{0.1, 0.1, 0.1}, 0.099979997},
                               {{-0.5, 0.1, 0.1}, 0.725685894}});
    // Frequency 0.01 shows the value before the wave's wrap (in [0, 2]).
    expectValues("spiral2 2 ramp_wave frequency 0.01", {{{-0.882, 1.665, 1.063}, 0.00436128}, {{0.47, -1.493, -1.993}, 0.01530918},
                                                        {{1.93, 1.49, -0.843}, 0.01485491}}, 2e-8);
    expectValues("spiral2 3 ramp_wave frequency 0.01", {{{-1.181, 1.764, 0.763}, 0.00910628}, {{-1.739, -0.795, 0.412}, 0.00618114}}, 2e-8);
    expectValues("spiral2 -2 ramp_wave frequency 0.01", {{{-0.737, -0.075, 0.819}, 0.00573437}, {{1.151, -0.535, 0.314}, 0.00982044}}, 2e-8);
    // A fractional number of arms is cut to an integer (measured: 1.5 gives 1's values, −1.5 −1's).
    expectValues("spiral2 1.5 ramp_wave frequency 0.01", {{{0.492, 0.967, 1.181}, 0.00787814}, {{-1.884, -0.138, 1.773}, 0.01069274}}, 2e-8);
    expectValues("spiral2 -1.5 ramp_wave frequency 0.01", {{{0.3, 0.2, 0.1}, 0.009550534}, {{1.1, -0.4, 0.3}, 0.008928972}}, 2e-8);
    expectValues("spiral1 1.5 ramp_wave frequency 0.01", {{{0.3, 0.2, 0.1}, 0.008041386}, {{1.1, -0.4, 0.3}, 0.016649613}}, 2e-8);
}

TEST(PovPattern, QuiltedMatchesPovRay) {
    // Values printed by POV-Ray 3.7 at scattered points, with the default and other controls.
    expectValues("quilted", {{{0.1, 0.1, 0.1}, 0.448492497}, {{0.3, 0.2, 0.1}, 0.312364697}, {{0.5, 0.5, 0.5}, 0},
                             {{0, 0, 0}, 0.575961888}, {{-0.75, 0.5, 0.5}, 0.055630103},
                             {{-2.921, 2.025, -1.444}, 0.348924547}, {{2.019, -0.142, 0.834}, 0.437557369}});
    expectValues("quilted control0 0.5 control1 -0.2", {{{0.139, 1.448, 1.028}, 0.092576429},
                                                        {{-2.616, 1.549, 0.547}, 0.011758776},
                                                        {{1.805, -0.332, 2.614}, 0.049432285}});
    expectValues("quilted control0 2.5 control1 1.7", {{{0.76, -1.194, 0.043}, 0.655295193},
                                                       {{2.574, 2.138, 2.946}, 0.571510315}});
    // Negative curves give their magnitude; values above 1 are 1.
    expectValues("quilted control0 -1 control1 0.3", {{{2.788, 2.428, 0.415}, 0.060604423},
                                                      {{0.441, -1.29, -2.619}, 0.054346632}});
    expectValues("quilted control0 5 control1 5", {{{0, 0, 0}, 1}, {{0.2, 0.1, 0.3}, 1}});
    expectValues("quilted control0 -5 control1 -5", {{{0, 0, 0}, 0.629809499}, {{0.1, 0.1, 0.1}, 1}});
}

TEST(PovPattern, WaveTypesFrequencyAndPhaseMatchPovRay) {
    const Vec3 xs[] = {{0.1, 0, 0}, {0.3, 0, 0}, {0.5, 0, 0}, {0.75, 0, 0}, {0.95, 0, 0}, {1, 0, 0}, {-0.25, 0, 0}};
    struct Row {
        const char* mods;
        double v[7];
    };
    const Row rows[] = {
        {"triangle_wave", {0.2, 0.6, 1, 0.5, 0.1, 0, 0.5}},
        {"sine_wave", {0.793893, 0.975528, 0.5, 0, 0.345491, 0.5, 0}},
        {"scallop_wave", {0.309017, 0.809017, 1, 0.707107, 0.156434, 0, 0.707107}},
        {"cubic_wave", {0.028, 0.216, 0.5, 0.84375, 0.99275, 1, 0.84375}},
        {"poly_wave 2", {0.01, 0.09, 0.25, 0.5625, 0.9025, 1, 0.5625}},
        {"frequency 2", {0.2, 0.6, 1, 0.49999, 0.89999, 0.99999, 0.5}},
        {"phase 0.3", {0.4, 0.6, 0.8, 0.04999, 0.24999, 0.29999, 0.05}},
        {"frequency -1", {0.9, 0.7, 0.5, 0.25, 0.05, 0, 0.25}},
        {"frequency 2 triangle_wave", {0.4, 0.8, 0, 0.99998, 0.20002, 0.00002, 1}},
        {"frequency 1.5 phase 0.2 cubic_wave", {0.28175, 0.71825, 0.99275, 0.248206, 0.68358, 0.783987, 0.918844}},
    };
    for (const Row& r : rows) {
        const Probe pr = pigment(std::string("gradient x") + kGrey + " " + r.mods);
        for (int i = 0; i < 7; ++i) EXPECT_NEAR(pr.at(xs[i]).rgb.x, r.v[i], 2e-6) << r.mods << " at x=" << xs[i].x;
    }
}

TEST(PovPattern, ColorMapsInterpolateAllFiveComponents) {
    // Entries at 0.2, 0.6, 0.6 (the first of the two wins at 0.6) and 0.8.
    const Probe pr = pigment("gradient x color_map { [0.2 rgbft <1, 0, 0, 0.5, 0>] [0.6 rgbft <0, 0, 1, 0, 1>] "
                             "[0.6 rgb 1] [0.8 rgb 0.5] }");
    auto expectAt = [&](double x, Vec3 rgb, double f, double t) {
        const pattern::Rgbft c = pr.at({x, 0, 0});
        EXPECT_NEAR(length(c.rgb - rgb), 0, 1e-9) << x;
        EXPECT_NEAR(c.filter, f, 1e-9) << x;
        EXPECT_NEAR(c.transmit, t, 1e-9) << x;
    };
    expectAt(0.1, {1, 0, 0}, 0.5, 0);  // below the first entry
    expectAt(0.3, {0.75, 0, 0.25}, 0.375, 0.25);
    expectAt(0.59, {0.025, 0, 0.975}, 0.0125, 0.975);
    expectAt(0.6, {0, 0, 1}, 0, 1);
    expectAt(0.61, {0.975, 0.975, 0.975}, 0, 0);
    expectAt(0.9, {0.5, 0.5, 0.5}, 0, 0);  // above the last
    // The old form [a b colour c1 colour c2].
    const Probe old = pigment("gradient x color_map { [0.2 0.6 color rgb <1, 0, 0> color rgb <0, 0, 1>] "
                              "[0.6 1 color rgb 1 color rgb 0] }");
    EXPECT_NEAR(length(old.at({0.3, 0, 0}).rgb - Vec3{0.75, 0, 0.25}), 0, 1e-9);
    EXPECT_NEAR(length(old.at({0.65, 0, 0}).rgb - Vec3(0.875)), 0, 1e-9);
    // No map: black to white.
    EXPECT_NEAR(pigment("gradient x").at({0.7, 0, 0}).rgb.y, 0.7, 1e-9);
}

TEST(PovPattern, BuiltInMapsMatchPovRay) {
    const Probe wood = pigment("wood ramp_wave");
    EXPECT_NEAR(length(wood.at({0.3, 0, 0}).rgb - Vec3{0.666, 0.312, 0.2}), 0, 1e-9);
    EXPECT_NEAR(length(wood.at({0.7, 0, 0}).rgb - Vec3{0.4, 0.1333, 0.066}), 0, 1e-9);
    const Probe marble = pigment("marble ramp_wave");
    EXPECT_NEAR(length(marble.at({0.45, 0, 0}).rgb - Vec3{0.9, 0.44, 0.44}), 0, 1e-9);
    EXPECT_NEAR(length(marble.at({0.95, 0, 0}).rgb), 0, 1e-9);
    EXPECT_NEAR(length(pigment("brick").at({7.9, 2.9, 4.4}).rgb - Vec3(0.5)), 0, 1e-9);  // mortar
    // radial's colour wheel (cyan, yellow at 0.333, magenta at 0.666); gradient's black to white.
    const Probe radial = pigment("radial");
    EXPECT_NEAR(length(radial.at({1, 0, 0.3}).rgb - Vec3{0.138883, 0.861117, 1}), 0, 2e-6);
    EXPECT_NEAR(length(radial.at({-1, 0, 0.2}).rgb - Vec3{1, 0.404155, 0.595845}), 0, 2e-6);
    EXPECT_NEAR(length(pigment("gradient x").at({0.3, 0, 0}).rgb - Vec3(0.3)), 0, 1e-9);
    EXPECT_NEAR(length(pigment("brick").at({0.1, 0.1, 0.1}).rgb - Vec3{0.6, 0.15, 0.15}), 0, 1e-9);
}

TEST(PovPattern, BlockPatternsMatchPovRay) {
    const Probe checker = pigment("checker");  // blue and green by default
    EXPECT_EQ(checker.at({0.5, 0.5, 0.5}).rgb, (Vec3{0, 0, 1}));
    EXPECT_EQ(checker.at({1.5, 0.5, 0.5}).rgb, (Vec3{0, 1, 0}));
    EXPECT_EQ(checker.at({0.5, -0.5, 0}).rgb, (Vec3{0, 1, 0}));
    EXPECT_EQ(checker.at({-1e-9, 0.5, 0.5}).rgb, (Vec3{0, 1, 0}));
    EXPECT_EQ(checker.at({-1e-10, 0.5, 0.5}).rgb, (Vec3{0, 0, 1}));  // faces moved a hair (measured)
    const Probe hex = pigment("hexagon rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1>");
    // Rows of the map printed by POV-Ray: colour 1 round the origin, 2 in +z, 3 to the sides.
    EXPECT_EQ(hex.at({0, 0, 0}).rgb, (Vec3{1, 0, 0}));
    EXPECT_EQ(hex.at({0.9, 0, 0}).rgb, (Vec3{1, 0, 0}));
    EXPECT_EQ(hex.at({0, 0, 1.7}).rgb, (Vec3{0, 1, 0}));
    EXPECT_EQ(hex.at({0, 0, -1.7}).rgb, (Vec3{0, 0, 1}));
    EXPECT_EQ(hex.at({-1.5, 0, 0.9}).rgb, (Vec3{0, 0, 1}));
    EXPECT_EQ(hex.at({1.5, 0, -0.9}).rgb, (Vec3{0, 1, 0}));
    EXPECT_EQ(hex.at({0.8, 0, 0.4}).rgb, (Vec3{0, 0, 1}));
    // brick: mortar (colour 1) at the end of each brick; courses shift along x and z.
    const Probe brick = pigment("brick rgb 1, rgb 0");
    EXPECT_EQ(brick.at({2, 1, 2}).rgb, Vec3(1));     // course 0: z mortar at 1.75..2.25
    EXPECT_EQ(brick.at({2, 1, 3}).rgb, Vec3(0));
    EXPECT_EQ(brick.at({7.6, 1, 3}).rgb, Vec3(1));   // x mortar at 7.5..8
    EXPECT_EQ(brick.at({3.6, 4, 3}).rgb, Vec3(1));   // course 1: shifted half a brick along x
    EXPECT_EQ(brick.at({7.6, 4, 3}).rgb, Vec3(0));
    EXPECT_EQ(brick.at({2, 4, 4.2}).rgb, Vec3(1));   // and not along z
    EXPECT_EQ(brick.at({1, 2.7, 1}).rgb, Vec3(1));   // y mortar at 2.5..3
    // The mortar's faces move a hair as POV-Ray's do (its pattern function: 1e-10 below x = 7.5,
    // y = 2.5 or z = 1.75 is mortar, 1.2e-10 below is brick), so a box face on them is mortar.
    for (const Vec3 d : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}) {
        const Vec3 edge = d.x ? Vec3{7.5, 1, 1} : d.y ? Vec3{1, 2.5, 1} : Vec3{1, 1, 1.75};
        EXPECT_EQ(brick.at(edge).rgb, Vec3(1));
        EXPECT_EQ(brick.at(edge - 1e-10 * d).rgb, Vec3(1));
        EXPECT_EQ(brick.at(edge - 1.2e-10 * d).rgb, Vec3(0));
    }
}

// The list index a block pattern picks at p: entry i is rgb i/10.
void expectIndices(const std::string& pattern, int entries, std::initializer_list<std::pair<Vec3, int>> samples) {
    std::string body = pattern;
    for (int i = 0; i < entries; ++i) body += (i ? ", rgb " : " rgb ") + std::to_string(i / 10.0);
    const Probe pr = pigment(body);
    ASSERT_GE(pr.surface().pigment, 0) << pattern;
    EXPECT_TRUE(pr.b.warnings.empty()) << pattern;
    for (const auto& [p, i] : samples)
        EXPECT_NEAR(pr.at(p).rgb.x, i / 10.0, 1e-9) << pattern << " at " << p.x << " " << p.y << " " << p.z;
}

TEST(PovPattern, TilingBlockPatternsMatchPovRay) {
    // Indices printed by POV-Ray 3.7 (the layouts checked at 300 random points each).
    expectIndices("square", 4, {{{0.3, 0, 0.2}, 0}, {{1.7, 2, 0.4}, 3}, {{-0.6, 0, 0.3}, 3}, {{0.4, -1, -0.8}, 1},
                                {{-1.2, 0, -1.9}, 0}, {{3.3, 0, 2.1}, 3}, {{1.5, 0, 1.5}, 2}});
    expectIndices("triangular", 6, {{{0.5, 0, 0.2}, 0}, {{0.05, 0, 0.2}, 1}, {{0.95, 0, 0.2}, 3}, {{1.5, 0, 0.2}, 4},
                                    {{-0.5, 0, 0.2}, 2}, {{-0.95, 0, 0.2}, 5}, {{0.1, 0, 0.9}, 4}, {{0.5, 0, 1.2}, 5},
                                    {{-0.3, 1, -0.5}, 3}, {{2.2, 0, -2.4}, 0}, {{-3.7, 0, 3.1}, 3}, {{4.05, 0, -1}, 3}});
    expectIndices("cubic", 6, {{{0.9, 0.1, 0.1}, 0}, {{-0.9, 0.5, 0.1}, 3}, {{0.1, 0.9, -0.5}, 1}, {{0.1, -0.9, 0.3}, 4},
                               {{0.3, 0.1, 0.9}, 2}, {{-0.2, 0.1, -0.9}, 5}, {{5, -4, 2}, 0}});
    // Built-in colours (measured): square red, green, blue, yellow; triangular and cubic add cyan, magenta.
    EXPECT_EQ(pigment("square").at({1.5, 0, 0.5}).rgb, (Vec3{1, 1, 0}));
    EXPECT_EQ(pigment("square rgb 0.5").at({0.5, 0, 1.5}).rgb, (Vec3{0, 1, 0}));
    EXPECT_EQ(pigment("triangular").at({1.5, 0, 0.5}).rgb, (Vec3{0, 1, 1}));
    EXPECT_EQ(pigment("cubic").at({0, 0, -1}).rgb, (Vec3{1, 0, 1}));
    // Pigment lists.
    EXPECT_NEAR(pigment("square pigment { gradient x } rgb 1, rgb 1, rgb 1").at({0.25, 0, 0.5}).rgb.y, 0.25, 1e-9);
}

TEST(PovPattern, PigmentMapsAndAverageNestPigments) {
    const Probe pm = pigment("gradient x pigment_map { [0.2 checker] [0.6 gradient y color_map { [0 rgb <1, 0, 0>] "
                             "[1 rgb <0, 1, 0>] }] }");
    EXPECT_NEAR(length(pm.at({0.1, 0, 0}).rgb - Vec3{0, 0, 1}), 0, 1e-9);
    EXPECT_NEAR(length(pm.at({0.4, 0.5, 0}).rgb - Vec3{0.25, 0.25, 0.5}), 0, 1e-9);
    EXPECT_NEAR(length(pm.at({0.4, 0.5, 1}).rgb - Vec3{0.25, 0.75, 0}), 0, 1e-9);
    EXPECT_NEAR(length(pm.at({0.8, 0.25, 0}).rgb - Vec3{0.75, 0.25, 0}), 0, 1e-9);
    const Probe avg = pigment("average pigment_map { [1 rgb <1, 0, 0>] [3 checker rgb 1, rgb 0] [2 gradient x] }");
    EXPECT_NEAR(length(avg.at({0.5, 0.5, 0.5}).rgb - Vec3{0.833333, 0.666667, 0.666667}), 0, 1e-6);
    EXPECT_NEAR(length(avg.at({1.5, 0.5, 0.25}).rgb - Vec3{0.333333, 0.166667, 0.166667}), 0, 1e-6);
    // Pigments in a block pattern's list.
    const Probe list = pigment("checker pigment { gradient x } pigment { rgb <1, 0, 0> }");
    EXPECT_NEAR(list.at({0.25, 0.5, 0.5}).rgb.y, 0.25, 1e-9);
    EXPECT_EQ(list.at({1.25, 0.5, 0.5}).rgb, (Vec3{1, 0, 0}));
}

TEST(PovPattern, LayeredTexturesMixTheirPatternsPointByPoint) {
    // A gradient from clear to red over a white-and-black checker, the checker scaled on its own.
    const Built b = build("sphere { 0, 1 texture { pigment { checker rgb 1, rgb 0 } scale 2 }\n"
                          "  texture { pigment { gradient x color_map { [0 rgbt <1, 0, 0, 1>] [1 rgb <1, 0, 0>] } } } }");
    const pattern::PigmentTable& t = b.scene.pigments;
    const int root = b.scene.povSurfaces.at(0).pigment;
    ASSERT_GE(root, 0);
    // x = 0.25: the layer is red with transmit 0.75 over white; x = 2.25: over black (scaled checker).
    EXPECT_NEAR(length(t.atRoot(root, {0.25, 0.5, 0.5}).rgb - Vec3{1, 0.75, 0.75}), 0, 1e-9);
    EXPECT_NEAR(length(t.atRoot(root, {2.25, 0.5, 0.5}).rgb - Vec3{0.25, 0, 0}), 0, 1e-9);
}

TEST(PovPattern, PatternedTexturesDrawTheirTexturesPigments) {
    // The texture's transformations move the pattern and the textures in it.
    const Built b = build("sphere { 0, 1 texture { checker texture { pigment { rgb <1, 0, 0> } finish { ambient 0.7 } }\n"
                          "  texture { pigment { gradient x } } scale 2 } }\n"
                          "sphere { 0, 1 texture { gradient x texture_map { [0.25 pigment { rgb <0, 0, 1> }] "
                          "[0.75 pigment { rgb <1, 1, 0> }] } } }");
    ASSERT_EQ(b.scene.objects.size(), 2u);
    const pattern::PigmentTable& t = b.scene.pigments;
    const PovSurface& s0 = b.scene.povSurfaces.at(size_t(b.scene.objects[0].material.pov));
    ASSERT_GE(s0.pigment, 0);
    EXPECT_NEAR(length(t.atRoot(s0.pigment, {0.5, 0.5, 0.5}).rgb - Vec3{1, 0, 0}), 0, 1e-9);
    EXPECT_NEAR(length(t.atRoot(s0.pigment, {2.5, 0.5, 0.5}).rgb - Vec3(0.25)), 0, 1e-9);
    EXPECT_DOUBLE_EQ(s0.finish.ambient.x, 0.7);  // the first texture's finish
    const PovSurface& s1 = b.scene.povSurfaces.at(size_t(b.scene.objects[1].material.pov));
    ASSERT_GE(s1.pigment, 0);
    EXPECT_NEAR(length(t.atRoot(s1.pigment, {0.5, 0, 0}).rgb - Vec3{0.5, 0.5, 0.5}), 0, 1e-9);
    EXPECT_NEAR(length(t.atRoot(s1.pigment, {0.1, 0, 0}).rgb - Vec3{0, 0, 1}), 0, 1e-9);
}

TEST(PovPattern, ObjectTexturesChooseTheOutsideAndInsideTextures) {
    const Built b = build("plane { y, -5 texture { object { sphere { 0, 1 } texture { pigment { rgb <1, 0, 0> } },\n"
                          "  texture { pigment { rgb <0, 1, 0> } finish { ambient 0.7 } } } scale 2 } }");
    EXPECT_TRUE(b.warnings.empty());
    const PovSurface& s = b.scene.povSurfaces.at(size_t(b.scene.objects.at(0).material.pov));
    ASSERT_GE(s.pigment, 0);
    EXPECT_EQ(b.scene.pigments.atRoot(s.pigment, {1.5, 0, 0}).rgb, (Vec3{0, 1, 0}));
    EXPECT_EQ(b.scene.pigments.atRoot(s.pigment, {2.5, 0, 0}).rgb, (Vec3{1, 0, 0}));
}

TEST(PovPattern, TilesAreACheckerOfTwoTextures) {
    // POV-Ray's old `tiles { texture {A} tile2 texture {B} }`: `checker texture {B} texture {A}`
    // (measured with POV-Ray 3.7: B where a checker puts its first entry, on planes at y = −1.5 …
    // 1.5); the block's transformations move the checker, then the texture's.
    const Built b = build("sphere { 0, 1 texture { tiles { texture { pigment { rgb <1, 0, 0> } finish { ambient 0.7 } }\n"
                          "  tile2 texture { pigment { rgb <0, 0, 1> } } scale 2 } translate x } }");
    EXPECT_TRUE(b.warnings.empty()) << b.warnings[0];
    const pattern::PigmentTable& t = b.scene.pigments;
    const PovSurface& s = b.scene.povSurfaces.at(size_t(b.scene.objects[0].material.pov));
    ASSERT_GE(s.pigment, 0);
    EXPECT_NEAR(length(t.atRoot(s.pigment, {1.5, 0.5, 0.5}).rgb - Vec3{0, 0, 1}), 0, 1e-9);
    EXPECT_NEAR(length(t.atRoot(s.pigment, {3.5, 0.5, 0.5}).rgb - Vec3{1, 0, 0}), 0, 1e-9);
    EXPECT_NEAR(length(t.atRoot(s.pigment, {0.5, 0.5, 0.5}).rgb - Vec3{1, 0, 0}), 0, 1e-9);
    EXPECT_DOUBLE_EQ(s.finish.ambient.x, 0.7);  // the first texture's finish
    EXPECT_GE(s.texture, 0);  // each tile lit with its own texture
}

TEST(PovPattern, WarpsApplyInFileOrderWithTheTransformations) {
    // Values printed by POV-Ray 3.7.
    expectValues("gradient y warp { repeat 2*x offset <0, 0.25, 0> flip x }",
                 {{{0.5, 0.1, 0}, 0.1}, {{2.5, 0.1, 0}, 0.35}, {{4.5, 0.1, 0}, 0.6}, {{-1.5, 0.1, 0}, 0.85}});
    expectValues("gradient x warp { repeat 2*x offset <0, 0.25, 0> flip x }", {{{2.5, 0.1, 0}, 0.5}, {{3.2, 0, 0}, 0.8}});
    expectValues("gradient x scale 0.5 warp { repeat x } scale 3",
                 {{{0.5, 0, 0}, 0.333333}, {{2.9, 0, 0}, 0.933333}, {{3.5, 0, 0}, 0.333333}, {{4, 0, 0}, 0.666667}});
    // A turbulence warp moves the point.
    const Probe turb = pigment(std::string("gradient x warp { turbulence <0.3, 0, 0> }") + kGrey);
    int moved = 0;
    for (int i = 0; i < 20; ++i) moved += std::fabs(turb.at({0.5, 0.37 * i, 0.11 * i}).rgb.x - 0.5) > 1e-3;
    EXPECT_GT(moved, 15);
}

// The x, y, z of the point a warp hands its pattern, through `function { 0.5 + 0.01·v }`; values
// printed by POV-Ray 3.7 (pattern functions of the same pigments).
void expectWarped(const std::string& warp, Vec3 p, Vec3 want) {
    const char* axes[] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
        expectValues(std::string("function { 0.5 + 0.01*") + axes[i] + " } warp { " + warp + " }",
                     {{p, 0.5 + 0.01 * want[i]}}, 1e-7);
}

TEST(PovPattern, MappingWarpsMatchPovRay) {
    expectWarped("planar", {0.3, 0.2, 0.1}, {0.3, 0.2, 0});
    expectWarped("planar y, 2", {1.3, 0.5, -0.4}, {1.3, -2, 0.5});
    expectWarped("planar x, 0", {-0.7, 0.25, 0.6}, {0, 0.25, 0.7});
    expectWarped("planar <1,2,3>, 1", {0.3, 0.2, 0.1}, {0.66815, -0.32071, 0.82851});
    expectWarped("planar <1,1,0>, 0", {-0.7, 0.25, 0.6}, {-0.49497, 0.17678, 0.67175});
    expectWarped("cylindrical", {1.3, 0.5, -0.4}, {0.95249, 0.5, 1.36015});
    expectWarped("cylindrical", {0, 0, -2}, {0.75, 0, 2});
    expectWarped("cylindrical dist_exp 2", {-0.7, 0.25, 0.6}, {0.32914, 0.25, 0.92195});
    expectWarped("cylindrical orientation y", {0.3, 0.2, 0.1}, {0.05121, -0.31623, 0.2});
    expectWarped("cylindrical orientation <0,1,1>", {1.3, 0.5, -0.4}, {1.34703, -0.60822, 1.31532});
    expectWarped("cylindrical orientation -x", {-0.7, 0.25, 0.6}, {-0.92195, -0.25, 0.38722});
    expectWarped("spherical", {2, -1, 0.5}, {0.03899, 0.35624, 2.29129});
    expectWarped("spherical dist_exp 1", {1.3, 0.5, -0.4}, {1.38029, 0.88706, 1.44914});
}

TEST(PovPattern, ToroidalAndCubicWarpsMatchPovRay) {
    // Printed by POV-Ray 3.7 (function { 0.5 + 0.01·v } as above).
    expectWarped("toroidal", {2, 1, 0}, {0, 0.625, 1.41421});
    expectWarped("toroidal", {1.5, 0.5, 1.5}, {0.125, 0.56676, 1.22775});
    expectWarped("toroidal", {-2, 0.3, 0}, {0.5, 0.54639, 1.04403});
    expectWarped("toroidal", {0.5, 0, 0}, {0, 0, 0.5});  // half a turn round the tube wraps to 0
    expectWarped("toroidal major_radius 2", {-2, 0.3, 0}, {0.5, 0.75, 0.3});
    expectWarped("toroidal major_radius 2", {1.5, 0.5, 1.5}, {0.125, 0.71211, 0.51451});
    expectWarped("toroidal dist_exp 1", {1.5, 0.5, 1.5}, {0.15347, 0.69583, 1.22775});
    expectWarped("toroidal orientation y", {2, 1, 0}, {0, -1.41421, 0.625});
    // Each face of the cube, then edges and corners (the first face of +x, +z, +y, -x, -y, -z).
    expectWarped("cubic", {2, 1, 0}, {0.625, 0.58333, 2});
    expectWarped("cubic", {1, 2, 3}, {0.41667, 0.61111, 3});
    expectWarped("cubic", {-2, 0, 1}, {0.1875, 0.5, 2});
    expectWarped("cubic", {1, 0, -2}, {0.8125, 0.5, 2});
    expectWarped("cubic", {0, 2, 1}, {0.375, 0.75, 2});
    expectWarped("cubic", {0.2, -0.7, 0.4}, {0.41071, 0.26190, 0.7});
    expectWarped("cubic", {1, 1, 0}, {0.625, 0.66667, 1});
    expectWarped("cubic", {-1, 1, 0}, {0.25, 0.83333, 1});
    expectWarped("cubic", {0, 1, 1}, {0.375, 0.66667, 1});
    expectWarped("cubic", {0, 1, -1}, {0.375, 1, 1});
    expectWarped("cubic", {0, -1, -1}, {0.375, 0, 1});
    expectWarped("cubic", {-1, -1, -1}, {0, 0.33333, 1});
}

TEST(PovPattern, BlackHoleWarpMatchesPovRay) {
    // Values printed by POV-Ray 3.7: pushed out by min(1, strength·(1 − d/R)^falloff).
    expectWarped("black_hole <0,0,0>, 1", {0.3, 0.15, 0}, {0.432504, 0.216252, 0});
    expectWarped("black_hole <0,0,0>, 1", {0.9, 0.45, 0}, {0.9, 0.45, 0});  // outside the radius
    expectWarped("black_hole <0,0,0>, 1 inverse", {0.5, 0.25, 0}, {0.402767, 0.201383, 0});
    expectWarped("black_hole <0,0,0>, 1 falloff 3 strength 0.5", {0.4, 0.2, 0}, {0.433783, 0.216892, 0});
    expectWarped("black_hole <0.2,0,0>, 2 falloff 1 strength 2", {0.1, 0.05, 0}, {0, 0.1, 0});  // clamped at 1
    expectWarped("black_hole <0,0,0>, 1 falloff 2 strength 2 inverse", {0.3, 0.15, 0}, {0.034992, 0.017496, 0});
    // Repeated along x: the centres at R + 2n there (the location's x unused), its y kept.
    expectWarped("black_hole <0.3,0.1,0>, 0.7 repeat <2,0,0>", {-1.5, 0.05, 0.1}, {-1.590498, 0.027376, 0.145249});
    expectWarped("black_hole <0.3,0,0>, 0.4 repeat <2,0,0>", {2.3, 0.05, 0.1}, {2.260938, 0.069531, 0.139062});
}

TEST(PovPattern, BlackHoleTurbulenceMovesEachRepeatedHole) {
    // Measured with POV-Ray 3.7 (`repeat <2,2,0> turbulence <0.5,0.25,0>`, radius 0.5; each hole's
    // centre found from the displacements of a 0.1 grid over 100 cells): the centre moves from
    // cell·2 + R by u·t on each repeated axis, u in [0, 1): offsets mean <0.258, 0.134>, spread
    // <0.142, 0.072> (t/√12 is <0.144, 0.072>); without repeat the hole stays put.
    pattern::BlackHole h;
    h.radius = 0.5;
    h.repeat = {2, 2, 0};
    h.jitter = {0.5, 0.25, 0};
    double sum[2] = {0, 0}, sq[2] = {0, 0};
    const int n = 20;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec3 p{2.0 * i + 0.3, 2.0 * j - 40 + 1.7, 0.4};
            const Vec3 c = pattern::blackHoleCentre(h, p);
            EXPECT_EQ(c, pattern::blackHoleCentre(h, p + Vec3{1.2, -1.1, 3}));  // one centre per cell
            EXPECT_DOUBLE_EQ(c.z, 0);  // not repeated along z: the location's
            for (int a = 0; a < 2; ++a) {
                const double base = std::floor(p[a] / 2) * 2 + 0.5, off = c[a] - base;
                EXPECT_GE(off, 0);
                EXPECT_LT(off, h.jitter[a]);
                sum[a] += off;
                sq[a] += off * off;
            }
        }
    for (int a = 0; a < 2; ++a) {
        const double mean = sum[a] / (n * n), spread = std::sqrt(sq[a] / (n * n) - mean * mean);
        EXPECT_NEAR(mean, h.jitter[a] / 2, 0.1 * h.jitter[a]);
        EXPECT_NEAR(spread, h.jitter[a] / std::sqrt(12.0), 0.1 * h.jitter[a]);
    }
    pattern::BlackHole still = h;
    still.repeat = {};
    EXPECT_EQ(pattern::blackHoleCentre(still, {3.3, 1.2, 0}), still.center);
    // From the scene language, without a note and moving the holes off their lattice.
    const Probe jittered = pigment(std::string("function { 0.5 + 0.01*x } warp { black_hole <0,0,0>, 0.5 "
                                               "repeat <2,2,0> turbulence <0.5,0.25,0> }") + kGrey);
    EXPECT_TRUE(jittered.b.warnings.empty());
    const Probe lattice = pigment(std::string("function { 0.5 + 0.01*x } warp { black_hole <0,0,0>, 0.5 "
                                              "repeat <2,2,0> }") + kGrey);
    int differ = 0;
    for (int i = 0; i < 10; ++i) {
        const Vec3 p{2.0 * i + 0.6, 0.55, 0};
        differ += std::fabs(jittered.at(p).rgb.x - lattice.at(p).rgb.x) > 1e-6;
    }
    EXPECT_GE(differ, 5);
}

TEST(PovPattern, PigmentPatternIsThePigmentsGrey) {
    // Values printed by POV-Ray 3.7: 0.297·r + 0.589·g + 0.114·b, filter and transmit ignored.
    expectValues("pigment_pattern { rgb <1, 0, 0> }", {{{0, 0, 0}, 0.297}});
    expectValues("pigment_pattern { rgb <0, 1, 0> }", {{{0, 0, 0}, 0.589}});
    expectValues("pigment_pattern { rgb <0, 0, 1> }", {{{0, 0, 0}, 0.114}});
    expectValues("pigment_pattern { rgbft <0.5, 0.5, 0.5, 0.5, 0.3> }", {{{0, 0, 0}, 0.5}});
    expectValues("pigment_pattern { gradient x color_map { [0 rgb 0] [1 rgb 1] } }",
                 {{{0.3, 0, 0}, 0.3}, {{0.75, 2, 1}, 0.75}});
    expectValues("pigment_pattern { gradient x color_map { [0 rgb 0] [1 rgb 1] } scale 2 } scale 0.5",
                 {{{0.3, 0, 0}, 0.3}});
    // As a normal it tilts the surface by the grey's gradient.
    const test::PovLoaded n = test::loadPov(
        "sphere { 0, 1 normal { pigment_pattern { gradient x color_map { [0 rgb 0] [1 rgb 1] } } 1 } }");
    EXPECT_TRUE(n.warnings.empty());
    const PovSurface& s = n.scene.povSurfaces.at(size_t(n.scene.objects.at(0).material.pov));
    ASSERT_GE(s.normal, 0);
    const Vec3 tilted = n.scene.normals.atRoot(n.scene.pigments, s.normal, {0.3, 0.5, -0.8}, {0, 0, -1});
    EXPECT_GT(std::fabs(tilted.x), 0.05);
}

TEST(PovPattern, VturbulenceGivesTheTurbulenceDisplacement) {
    // vturbulence(lambda, omega, octaves, P): the vector Rays' turbulence moves P by at amount 1.
    pattern::Turbulence t;
    t.amount = {1, 1, 1};
    t.lambda = 2.5, t.omega = 0.4, t.octaves = 3;
    const Vec3 want = pattern::turbulenceVector({0.3, 0.2, 0.1}, t);
    ASSERT_GT(length(want), 1e-3);
    char check[256];
    std::snprintf(check, sizeof check, "#if (vlength(V - <%.17g, %.17g, %.17g>) > 1e-12) #error \"differs\" #end\n",
                  want.x, want.y, want.z);
    std::vector<std::string> warnings;
    EXPECT_NO_THROW(test::buildPov(std::string("#declare V = vturbulence(2.5, 0.4, 3, <0.3, 0.2, 0.1>);\n") + check +
                                       "sphere { 0, 1 }",
                                   &warnings));
    EXPECT_TRUE(warnings.empty());
}

TEST(PovPattern, TransformationsMoveThePatternInFileOrder) {
    // Inside the pigment (POV-Ray: scale 2 rotate y*45 translate x; values printed by POV-Ray).
    const Probe t = pigment("checker rgb 1, rgb 0 scale 2 rotate y*45 translate <1, 0, 0>");
    EXPECT_EQ(t.at({1, 0.5, 0.5}).rgb, Vec3(0));
    EXPECT_EQ(t.at({2.5, 0.5, 0.1}).rgb, Vec3(1));
    EXPECT_EQ(t.at({0, 0.5, 1.6}).rgb, Vec3(0));
    // The object's transformations after the pigment move it; those before do not.
    EXPECT_NEAR(pigment("gradient x", "sphere { 0, 1 translate x*10 ").at({10.3, 0, 0}).rgb.x, 0.3, 1e-9);
    EXPECT_NEAR(pigment("gradient x", "sphere { 0, 1 ", "translate x*0.5 scale 2").at({1.6, 0, 0}).rgb.x, 0.3, 1e-9);
    // A texture's own transformations, and a union's after its texture reach its members.
    const Built tex = build("sphere { 0, 1 texture { pigment { gradient x } scale 0.5 } }");
    EXPECT_NEAR(tex.scene.pigments.atRoot(tex.scene.povSurfaces[0].pigment, {0.7, 0, 0}).rgb.x, 0.4, 1e-9);
    const Built u = build("union { sphere { 0, 1 translate 5*y } pigment { gradient x } translate x*0.25 }");
    EXPECT_NEAR(u.scene.pigments.atRoot(u.scene.povSurfaces[0].pigment, {0.5, 5, 0}).rgb.x, 0.25, 1e-9);
}

TEST(PovPattern, RenderedPatternsAreNotNotedUnrenderedOnesAre) {
    const Probe flat = pigment("rgb <1, 0, 0>");
    EXPECT_EQ(flat.surface().pigment, -1);  // flat colours keep the flat path
    const Probe checker = pigment("checker rgb 1, rgb 0");
    EXPECT_TRUE(checker.b.warnings.empty());
    EXPECT_EQ(checker.b.scene.objects[0].material.color, Vec3(0.5));  // the mean stays the flat colour
    const Probe pavement = pigment("tiling 26");
    EXPECT_EQ(pavement.surface().pigment, -1);
    ASSERT_EQ(pavement.b.warnings.size(), 1u);
    EXPECT_NE(pavement.b.warnings[0].find("pigment pattern tiling 26 (drawn in its mean colour)"), std::string::npos);
}

TEST(PovPattern, NoisePatternsStayInRangeAndRepeat) {
    for (const char* p : {"bozo", "granite", "wrinkles", "agate", "crackle", "marble turbulence 0.5", "wood turbulence 0.3",
                          "spotted", "bozo turbulence <0.5, 0.2, 0>"}) {
        const Probe a = pigment(std::string(p) + kGrey);
        ASSERT_GE(a.surface().pigment, 0) << p;
        double lo = 1, hi = 0;
        for (int i = 0; i < 400; ++i) {
            const Vec3 q{0.137 * i, 0.071 * i, -0.053 * i};
            const double v = a.at(q).rgb.x;
            EXPECT_EQ(v, a.at(q).rgb.x);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        EXPECT_GE(lo, 0) << p;
        EXPECT_LE(hi, 1) << p;
        EXPECT_GT(hi - lo, 0.2) << p;  // varies
    }
}

// The colour (working space) the POV-Ray tracer sees along a ray.
Vec3 traceColor(const Scene& s, const Ray& ray) {
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    return Tracer(s, bvh, rs).tracePrimary(ray, ctx, nullptr, nullptr);
}

TEST(PovPatternRender, ACheckerPlaneShowsBothColoursWhereExpected) {
    const Built b = build("plane { y, 0 pigment { checker rgb <1, 0, 0>, rgb <0, 0, 1> scale 2 } "
                          "finish { ambient 1 diffuse 0 } translate <0.5, 0, 0> }");
    const Vec3 down{0, -1, 0};
    // Squares 2 units wide, moved 0.5 along x: [0.5, 2.5) is the first colour, [2.5, 4.5) the second.
    EXPECT_NEAR(length(traceColor(b.scene, Ray{{1, 5, 1}, down}) - Vec3{1, 0, 0}), 0, 1e-9);
    EXPECT_NEAR(length(traceColor(b.scene, Ray{{3, 5, 1}, down}) - Vec3{0, 0, 1}), 0, 1e-9);
    EXPECT_NEAR(length(traceColor(b.scene, Ray{{0, 5, 1}, down}) - Vec3{0, 0, 1}), 0, 1e-9);
    EXPECT_NEAR(length(traceColor(b.scene, Ray{{1, 5, -1}, down}) - Vec3{0, 0, 1}), 0, 1e-9);
    // A whole render: both colours appear, in about equal shares.
    const Built view = build("camera { location <0, 10, 0> look_at 0 angle 60 }\n"
                             "plane { y, 0 pigment { checker rgb <1, 0, 0>, rgb <0, 0, 1> } finish { ambient 1 diffuse 0 } }");
    RenderSettings rs;
    rs.width = 32;
    rs.height = 24;
    rs.threads = 1;
    const Bvh bvh(view.scene.objects);
    TraceStats stats;
    const ImageF img = render(view.scene, bvh, rs, stats);
    int red = 0, blue = 0;
    for (int y = 0; y < rs.height; ++y)
        for (int x = 0; x < rs.width; ++x) {
            const Vec3 c = img.at(x, y);
            red += c.x > 0.9 && c.z < 0.1;
            blue += c.z > 0.9 && c.x < 0.1;
        }
    EXPECT_GT(red, 200);
    EXPECT_GT(blue, 200);
}

TEST(PovPatternRender, SkySphereIsLookedUpByDirection) {
    const Built b = build("background { rgb <0, 1, 0> }\n"
                          "sky_sphere { pigment { gradient y color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } "
                          "scale 2 translate -1 } rotate z*90 }");
    EXPECT_TRUE(b.warnings.empty());
    // Turned 90° about z: +y of the pigment looks along −x.
    EXPECT_NEAR(length(traceColor(b.scene, Ray{{5, 5, 5}, {-1, 0, 0}}) - Vec3{0, 0, 1}), 0, 1e-9);
    EXPECT_NEAR(length(traceColor(b.scene, Ray{{5, 5, 5}, {1, 0, 0}}) - Vec3{1, 0, 0}), 0, 1e-9);
    EXPECT_NEAR(length(traceColor(b.scene, Ray{{5, 5, 5}, {0, 0, 2}}) - Vec3{0.5, 0, 0.5}), 0, 1e-9);
    // Layers: a transmitting upper layer lets the one below through; emission scales the sky.
    const Built l = build("sky_sphere { pigment { rgb <1, 0, 0> } pigment { rgbt <0, 0, 1, 0.25> } emission 2 }");
    EXPECT_NEAR(length(traceColor(l.scene, Ray{{0, 0, 0}, {0, 1, 0}}) - Vec3{0.5, 0, 1.5}), 0, 1e-9);
}

TEST(PovPatternRender, SkySphereLayersComposeAsPovRayDoes) {
    // POV-Ray 3.7's pixels (8-bit sRGB, assumed_gamma 1) looking at sky_spheres of rgbf, rgbt and
    // rgbft layers over a background, under #version 3.7 (the layers compose as a layered
    // texture's) and #version 3.6 (a filter lets the layers below through untinted, as a transmit
    // does, but tints the background); pov_pigment.h povSky. The last case's first layer has
    // filter + transmit above 1.
    auto linear = [](int v) {
        const double c = v / 255.0;
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    const struct {
        const char* scene;
        int now[3], legacy[3];
    } cases[] = {
        {"background { rgb <1, 0.3, 0.6> } sky_sphere { pigment { rgbt <0, 1, 1, 0.5> } pigment { rgbf <0, 0, 1, 0.5> } }",
         {0, 0, 243}, {0, 137, 225}},
        {"background { rgb <1, 0.3, 0.6> } sky_sphere { pigment { rgbt <0, 1, 1, 0.5> } pigment { rgbt <0, 0, 1, 0.5> } }",
         {137, 154, 243}, {137, 154, 243}},
        {"background { rgb <1, 0, 0> } sky_sphere { pigment { rgbft <1, 1, 0, 0.3, 0.2> } pigment { rgbft <1, 0, 1, 0.2, 0.5> } }",
         {255, 137, 149}, {232, 160, 149}},
        {"background { rgb <0.8, 0.5, 0.9> } sky_sphere { pigment { rgbft <0.7, 0.8, 0.4, 0.4, 0.3> } "
         "pigment { rgbft <0.6, 0.9, 0.5, 0.3, 0.3> } pigment { rgbft <0.9, 0.6, 0.8, 0.5, 0.2> } }",
         {209, 190, 188}, {190, 188, 175}},
        {"background { rgb <0.3, 0.9, 0.6> } sky_sphere { pigment { rgbft <0.2, 0.8, 0.4, 0.1, 0.6> } "
         "pigment { rgbft <0.6, 0.3, 0.5, 0.6, 0.1> } pigment { rgbft <0.9, 0.6, 0.1, 0.2, 0.2> } "
         "pigment { rgbft <0.5, 0.5, 0.9, 0.3, 0.4> } }",
         {189, 171, 162}, {197, 175, 158}},
        {"background { rgb <0.2, 0.4, 0.8> } sky_sphere { pigment { rgbft <0.9, 0.6, 0.1, 0.6, 0.6> } "
         "pigment { rgbft <1, 0.3, 0.5, 0.1, 0.8> } }",
         {106, 137, 184}, {60, 97, 173}},
    };
    for (const auto& c : cases) {
        for (const bool legacy : {false, true}) {
            SCOPED_TRACE(std::string(legacy ? "#version 3.6: " : "#version 3.7: ") + c.scene);
            const std::string head = std::string(legacy ? "#version 3.6;\n" : "#version 3.7;\n") +
                                     "global_settings { assumed_gamma 1 }\n";
            const Built b = test::loadPov(c.scene, head);
            const Vec3 got = traceColor(b.scene, Ray{{0, 0, 0}, {0, 0, 1}});
            const int* want = legacy ? c.legacy : c.now;
            EXPECT_NEAR(std::min(got.x, 1.0), linear(want[0]), 0.004);
            EXPECT_NEAR(std::min(got.y, 1.0), linear(want[1]), 0.004);
            EXPECT_NEAR(std::min(got.z, 1.0), linear(want[2]), 0.004);
        }
    }
}

// Rays' noise is not POV-Ray's, so noise patterns cannot match point for point; their mean and
// spread over space can. POV-Ray 3.7's figures over the same 400 points (printed as above).
TEST(PovPattern, RipplesAndWavesPigmentsArePovRaysPointForPoint) {
    // POV-Ray 3.7 with its default ten wave sources: a pigment function's values printed with
    // #debug (8 decimals) at three points; Rays' measured centres give them to 3·10⁻⁶.
    const Probe ripples = pigment(std::string("ripples") + kGrey), waves = pigment(std::string("waves") + kGrey);
    const struct {
        Vec3 p;
        double ripples, waves;
    } tenWaves[] = {{{3.63146305, 0.88373024, -2.66518291}, 0.40212169, 0.48064515},
                    {{-3.72106334, 1.91477262, -0.93619379}, 0.28949735, 0.40719935},
                    {{-0.14376441, 2.4137308, 2.60956798}, 0.45319936, 0.5101583}};
    for (const auto& c : tenWaves) {
        EXPECT_NEAR(ripples.at(c.p).rgb.x, c.ripples, 1e-5);
        EXPECT_NEAR(waves.at(c.p).rgb.x, c.waves, 1e-5);
    }
    // number_of_waves 1: POV-Ray's render of a plane z = 1 (16-bit, linear) at two pixels.
    const std::string oneWave = "global_settings { number_of_waves 1 } sphere { 0, 1 ";
    const Probe ripples1 = pigment(std::string("ripples") + kGrey, oneWave);
    const Probe waves1 = pigment(std::string("waves") + kGrey, oneWave);
    EXPECT_NEAR(ripples1.at({0.02, -0.02, 1}).rgb.x, 0.042374, 3e-5);
    EXPECT_NEAR(ripples1.at({2.02, 2.5, 1}).rgb.x, 0.043565, 3e-5);
    EXPECT_NEAR(waves1.at({0.02, -0.02, 1}).rgb.x, 0.309911, 3e-5);
    EXPECT_NEAR(waves1.at({2.02, 2.5, 1}).rgb.x, 0.643732, 3e-5);
}

TEST(PovPattern, RipplesWavesAndDentsPigmentsSpreadAsPovRaysDo) {
    // POV-Ray 3.7 over 400 random points in [−5, 5]³ (mean, standard deviation); here 400 points
    // of a fixed pseudo-random sequence in the same cube.
    struct Stat {
        const char* body;
        double mean, sd;
    };
    const Stat stats[] = {{"ripples", 0.500, 0.108}, {"waves", 0.476, 0.114}, {"dents", 0.157, 0.111},
                          {"ripples frequency 3", 0.515, 0.274}};
    for (const Stat& st : stats) {
        const Probe pr = pigment(std::string(st.body) + kGrey);
        ASSERT_GE(pr.surface().pigment, 0) << st.body;
        uint32_t seed = 12345;
        auto next = [&] {
            seed = seed * 1664525u + 1013904223u;
            return -5 + 10 * (seed >> 8) / double(1u << 24);
        };
        const auto [mean, sd] = spreadOf(pr, 400, [&] { return Vec3{next(), next(), next()}; });
        EXPECT_NEAR(mean, st.mean, 0.04) << st.body;
        EXPECT_NEAR(sd, st.sd, 0.02) << st.body;
    }
}

TEST(PovPattern, CellsGiveOneUniformValuePerUnitCube) {
    // POV-Ray 3.7: constant within a cube (0.711818933 at both <0.5, 0.5, 0.5> and <0.1, 0.9, 0.2>),
    // mean 0.505 and spread 0.286 over 400 random points; Rays' values are its own hash's.
    const Probe pr = pigment(std::string("cells") + kGrey);
    ASSERT_GE(pr.surface().pigment, 0);
    EXPECT_EQ(pr.at({0.5, 0.5, 0.5}).rgb.x, pr.at({0.1, 0.9, 0.2}).rgb.x);
    EXPECT_EQ(pr.at({2.5, 3.5, -4.5}).rgb.x, pr.at({2.1, 3.9, -4.1}).rgb.x);
    EXPECT_NE(pr.at({0.5, 0.5, 0.5}).rgb.x, pr.at({-0.5, 0.5, 0.5}).rgb.x);
    double sum = 0, sum2 = 0;
    const int n = 1000;
    for (int i = 0; i < n; ++i) {
        const double v = pr.at({i * 1.0 + 0.5, (i * 7) % 13 + 0.5, -(i % 5) + 0.5}).rgb.x;
        ASSERT_GE(v, 0);
        ASSERT_LT(v, 1);
        sum += v;
        sum2 += v * v;
    }
    const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
    EXPECT_NEAR(mean, 0.505, 0.03);
    EXPECT_NEAR(sd, 0.286, 0.02);
}

// Mean and spread of the noise patterns over 8,000 points, against POV-Ray 3.7's over 8,000 random
// points (its pattern functions, grey ramp). The points are on the planes and lines named, the free
// coordinates uniform in [−20, 20]: agate on z = 0.3 (its bands run along z, so that the turbulence
// alone spreads the values), marble turbulence 0.1 on x = 0 (0.1·T through the triangle wave: the
// turbulence's own spread), wood turbulence 0.1 on the line x = 0.3, y = 0.2 (how far the turbulence
// moves the rings).
TEST(PovPattern, NoisePatternsSpreadAsPovRaysDo) {
    enum class Where { Cube, AgatePlane, MarblePlane, WoodLine };
    struct Stat {
        const char* body;
        Where where;
        double mean, sd;
    };
    const Stat stats[] = {{"bozo", Where::Cube, 0.5059, 0.1267},
                          {"granite", Where::Cube, 0.3978, 0.1610},
                          {"wrinkles", Where::Cube, 0.5106, 0.1419},
                          {"agate", Where::AgatePlane, 0.5265, 0.3410},
                          {"marble turbulence 0.1", Where::MarblePlane, 0.2023, 0.0601},
                          {"wood turbulence 0.1", Where::WoodLine, 0.7032, 0.2054}};
    uint64_t seed = 99;
    auto next = [&] {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        return double(seed >> 11) * 0x1.0p-53 * 40 - 20;
    };
    for (const Stat& st : stats) {
        const Probe pr = pigment(std::string(st.body) + kGrey);
        const auto [mean, sd] = spreadOf(pr, 8000, [&] {
            const double a = next(), b = next(), c = next();
            return st.where == Where::Cube          ? Vec3{a, b, c}
                   : st.where == Where::AgatePlane  ? Vec3{a, b, 0.3}
                   : st.where == Where::MarblePlane ? Vec3{0, b, c}
                                                    : Vec3{0.3, 0.2, c};
        });
        EXPECT_NEAR(mean, st.mean, 0.04) << st.body;
        EXPECT_NEAR(sd, st.sd, 0.015) << st.body;
    }
}

// noise_generator (global or the pattern's own) changes bozo's spread as in POV-Ray 3.7 (8,000
// random points in [−20, 20]³: generator 1 0.4818 ± 0.2497, 2 0.5059 ± 0.1267, 3 0.4921 ± 0.1456).
TEST(PovPattern, NoiseGeneratorChangesBozosSpread) {
    struct Case {
        std::string scene;
        double mean, sd;
    };
    const std::string bozo = std::string("sphere { 0, 1 pigment { bozo") + kGrey;
    const Case cases[] = {{"global_settings { noise_generator 1 } " + bozo + " } }", 0.4818, 0.2497},
                          {bozo + " noise_generator 1 } }", 0.4818, 0.2497},
                          {"global_settings { noise_generator 3 } " + bozo + " } }", 0.4921, 0.1456},
                          {"global_settings { noise_generator 1 } " + bozo + " noise_generator 2 } }", 0.5059, 0.1267}};
    for (const Case& c : cases) {
        const Probe pr{build(c.scene)};
        uint64_t seed = 5;
        auto next = [&] {
            seed = seed * 6364136223846793005ull + 1442695040888963407ull;
            return double(seed >> 11) * 0x1.0p-53 * 40 - 20;
        };
        const auto [mean, sd] = spreadOf(pr, 8000, [&] { return Vec3{next(), next(), next()}; });
        EXPECT_NEAR(mean, c.mean, 0.02) << c.scene;
        EXPECT_NEAR(sd, c.sd, 0.012) << c.scene;
    }
}

// agate_turb 0 leaves agate deterministic: (½ + ½·sin(2π·1.1·z))^0.77, printed by POV-Ray 3.7's
// pattern functions along z.
TEST(PovPattern, AgateWithoutTurbulenceMatchesPovRay) {
    const Probe pr = pigment(std::string("agate agate_turb 0") + kGrey);
    const Sample samples[] = {{{0.3, 0.2, 0.0}, 0.58642},  {{1.7, -3.2, 0.15}, 0.94594}, {{0, 0, 0.5}, 0.44116},
                              {{0.3, 0.2, 0.7}, 0.01409},  {{0.3, 0.2, 1.25}, 0.88521}, {{0, 0, 1.6}, 0.00485},
                              {{0.3, 0.2, 1.95}, 0.91819}, {{5, 5, 2.0}, 0.98110}};
    for (const Sample& s : samples) EXPECT_NEAR(pr.at(s.p).rgb.x, s.value, 2e-5) << s.p.z;
}

// The noise sums as POV-Ray 3.7 makes them from the noise bozo shows (measured against its bozo at
// scaled points to 1e-7): granite Σ_{i<6} |c(4·2^i·p) − ½| / 2^i and wrinkles ½·Σ_{i<10} c(2^i·p) / 2^i,
// c(q) = clamp(2·bozo(q) − ½, 0, 1); marble's turbulence clamps only its first octave.
TEST(PovPattern, NoiseSumsAreMadeOfBozosNoiseAsInPovRay) {
    const Probe bozo = pigment(std::string("bozo") + kGrey);
    const Probe granite = pigment(std::string("granite") + kGrey);
    const Probe wrinkles = pigment(std::string("wrinkles") + kGrey);
    const Probe marble = pigment(std::string("marble turbulence 0.001 octaves 3 omega 0.7 lambda 3 ramp_wave") + kGrey);
    const auto b = [&](Vec3 q) { return bozo.at(q).rgb.x; };
    const auto c = [&](Vec3 q) { return std::clamp(2 * b(q) - 0.5, 0.0, 1.0); };
    for (int i = 0; i < 50; ++i) {
        const Vec3 p{-7.3 + 0.61 * i, 3.1 - 0.37 * i, 0.23 * i - 4.9};
        double g = 0, w = 0;
        for (int k = 0; k < 6; ++k) g += std::fabs(c(p * (4.0 * std::pow(2.0, k))) - 0.5) / std::pow(2.0, k);
        for (int k = 0; k < 10; ++k) w += 0.5 * c(p * std::pow(2.0, k)) / std::pow(2.0, k);
        EXPECT_NEAR(granite.at(p).rgb.x, g, 1e-6) << i;
        EXPECT_NEAR(wrinkles.at(p).rgb.x, w, 1e-6) << i;
        const Vec3 q{0, p.y, p.z};  // marble's value is x + 0.001·T
        const double T = c(q) + 0.7 * (2 * b(q * 3.0) - 0.5) + 0.49 * (2 * b(q * 9.0) - 0.5);
        EXPECT_NEAR(marble.at(q).rgb.x, 0.001 * T, 1e-9) << i;
    }
}

// wood with turbulence (measured with POV-Ray 3.7 at 300 random points, to 1e-4): x moves by
// sin(2π·amount.x·(x + D.x)), y by sin(2π·amount.y·(y + D.y)), D the turbulence displacement
// that gradient x and gradient y show at the same point.
TEST(PovPattern, TurbulentWoodMovesItsRingsAsPovRaysDoes) {
    const Probe wood = pigment(std::string("wood turbulence <0.3, 0.2, 0.5> octaves 2 ramp_wave") + kGrey);
    const Probe gx = pigment(std::string("gradient x turbulence 0.001 octaves 2 ramp_wave") + kGrey);
    const Probe gy = pigment(std::string("gradient y turbulence 0.001 octaves 2 ramp_wave") + kGrey);
    for (int i = 0; i < 50; ++i) {
        const Vec3 p{0.1 + 0.013 * i, 0.15 + 0.011 * i, 0.37 * i - 9};
        const double dx = (gx.at(p).rgb.x - p.x) / 0.001, dy = (gy.at(p).rgb.x - p.y) / 0.001;
        const double x = p.x + std::sin(2 * std::numbers::pi * 0.3 * (p.x + dx));
        const double y = p.y + std::sin(2 * std::numbers::pi * 0.2 * (p.y + dy));
        double r = std::sqrt(x * x + y * y);
        if (r > 1) r = std::fmod(r, 1.00001);
        EXPECT_NEAR(wood.at(p).rgb.x, r, 1e-5) << i;
    }
}

// spotted and bumps as pigments are bozo's noise on the grey ramp, not on bozo's built-in map
// (POV-Ray 3.7's pigment functions: 0.449 grey where bozo gives green).
TEST(PovPattern, SpottedAndBumpsWithoutAMapAreGrey) {
    const Probe grey = pigment(std::string("bozo") + kGrey);
    for (const char* body : {"spotted", "bumps"}) {
        const Probe pr = pigment(body);
        for (int i = 0; i < 20; ++i) {
            const Vec3 p{0.37 * i, 0.21 * i, 0.3};
            const pattern::Rgbft c = pr.at(p);
            EXPECT_NEAR(c.rgb.x, grey.at(p).rgb.x, 1e-12) << body;
            EXPECT_EQ(c.rgb.x, c.rgb.y) << body;
            EXPECT_EQ(c.rgb.y, c.rgb.z) << body;
        }
    }
}

// waves is ten rings of different frequencies, each with a height ∝ 1/frequency (measured with
// POV-Ray 3.7 along the line y = 0.3, z = 0.2 from x = 1000, 16,384 samples 0.05 apart: ten
// sinusoids between frequency 0.17 and 0.99, the strongest the slowest; ripples is one period 1).
// The same line's spectrum here: the strongest component below 0.5, little power about 1.
TEST(PovPattern, WavesAreRingsOfManyFrequencies) {
    const Probe waves = pigment(std::string("waves") + kGrey);
    const int n = 8192;
    std::vector<double> v(n);
    double mean = 0;
    for (int k = 0; k < n; ++k) mean += v[size_t(k)] = waves.at({1000 + 0.05 * k, 0.3, 0.2}).rgb.x;
    mean /= n;
    double best = 0, bestF = 0, nearOne = 0, total = 0;
    for (double f = 0.05; f < 1.3; f += 0.0025) {
        double re = 0, im = 0;
        for (int k = 0; k < n; ++k) {
            const double a = 2 * std::numbers::pi * f * 0.05 * k;
            re += (v[size_t(k)] - mean) * std::cos(a);
            im -= (v[size_t(k)] - mean) * std::sin(a);
        }
        const double power = re * re + im * im;
        total += power;
        if (f > 0.95 && f < 1.05) nearOne += power;
        if (power > best) best = power, bestF = f;
    }
    EXPECT_LT(bestF, 0.5);
    EXPECT_LT(nearOne, 0.3 * total);
}

}}  // namespace RAYS_TEST_UNIT, namespace
}  // namespace rays
