// POV-Ray 3.7's lighting model in the tracer (render/tracer_povray.cpp, pov_lighting, pov_output):
// scenes built in code, single rays or tiny renders, values worked out by hand from the formulas
// of docs/povray-lighting.md. Where a number was measured from povray 3.7, the comment gives the
// measurement (the scenes are in tests/data/povray/shading; these tests do not need POV-Ray).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "rays/accel/bvh.h"
#include "rays/image/image.h"
#include "rays/render/pov_lighting.h"
#include "rays/render/pov_output.h"
#include "rays/render/renderer.h"
#include "rays/render/tracer.h"
#include "support/objects.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

constexpr double kPi = std::numbers::pi;
const Vec3 kPigment{0.5, 0.6, 0.7};
const Vec3 kBackground{0.2, 0.5, 0.9};

double deg(double d) { return d * kPi / 180; }

// A POV-Ray scene with no objects yet: a camera at −3z looking at the origin, a black background.
Scene povScene() {
    Scene s;
    s.pov.enabled = true;
    Camera c;
    c.location = {0, 0, -3};
    c.lookAt = {0, 0, 0};
    c.right = {1, 0, 0};
    c.up = {0, 1, 0};
    s.cameras.push_back(c);
    return s;
}

// A surface with ambient 0 and diffuse 0 (the defaults are 0.1 and 0.6), to be set up by the test.
PovSurface darkSurface() {
    PovSurface p;
    p.finish.ambient = Vec3{};
    p.finish.diffuse = 0;
    return p;
}

// Adds an object with pigment C (filter f) and POV-Ray surface p to the scene.
void add(Scene& s, Object o, Vec3 C, const PovSurface& p, double filter = 0) {
    o.material.color = C;
    o.material.filter = filter;
    o.material.pov = int(s.povSurfaces.size());
    s.povSurfaces.push_back(p);
    s.objects.push_back(o);
}

// The plane through the origin facing −z (POV-Ray's plane { -z, 0 }: the camera side is outside),
// turned by `tilt` degrees about y.
Object facingPlane(double tilt = 0) {
    const Vec3 n{-std::sin(deg(tilt)), 0, -std::cos(deg(tilt))};
    return test::makeObject(ShapeType::Plane, n, {}, {}, 0, 0);
}

Object box(Vec3 lo, Vec3 hi) { return test::makeObject(ShapeType::Box, lo, hi, {}, 0, 0); }

// A parallel light whose light arrives from unit direction `toLight` (from the surface to the light).
Light parallelLight(Vec3 toLight, Vec3 color = Vec3(1.0)) {
    Light l;
    l.parallel = true;
    l.position = 100.0 * toLight;
    l.pointAt = {0, 0, 0};
    l.direction = -toLight;
    l.color = color;
    return l;
}

// Light from `angle` degrees off the −z normal, in the x-z plane, on the camera's side.
Vec3 frontAt(double angle) { return {std::sin(deg(angle)), 0, -std::cos(deg(angle))}; }

// The colour (working space) seen along one ray, as a primary ray.
Vec3 trace(const Scene& s, const Ray& ray, PathInfo* info = nullptr) {
    const Bvh bvh(s.objects);
    const RenderSettings rs;
    TraceContext ctx;
    return Tracer(s, bvh, rs).tracePrimary(ray, ctx, nullptr, info);
}

// The ray of an orthographic camera looking along +z at the origin.
const Ray kView{{0.1, -0.1, -3}, {0, 0, 1}};

void expectColor(Vec3 got, Vec3 want, double tol = 1e-9) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

// Measured: ambient <.3,.2,.1> on rgb <.5,.6,.7> under ambient_light <1,2,.5> gives
// <.15,.24,.035>; emission is not multiplied by ambient_light.
TEST(PovShading, AmbientTimesAmbientLightPlusEmission) {
    Scene s = povScene();
    s.pov.ambientLight = {1, 2, 0.5};
    PovSurface p = darkSurface();
    p.finish.ambient = {0.3, 0.2, 0.1};
    p.finish.emission = {0.05, 0.1, 0.2};
    add(s, facingPlane(), kPigment, p);
    expectColor(trace(s, kView), Vec3{0.3 * 1 + 0.05, 0.2 * 2 + 0.1, 0.1 * 0.5 + 0.2} * kPigment);
}

TEST(PovShading, MissedRaysSeeTheBackground) {
    Scene s = povScene();
    s.pov.background = kBackground;
    expectColor(trace(s, kView), kBackground);
}

// diffuse·(N·L)^brilliance·C·Lc, light colours above 1 included (measured: 60°, diffuse 0.8,
// brilliance 2.5 on <.5,.6,.7> gives <.07071,.08485,.09900> under white light).
TEST(PovShading, DiffuseWithBrilliance) {
    Scene s = povScene();
    const Vec3 Lc{3, 2, 0.5};
    s.lights.push_back(parallelLight(frontAt(60), Lc));
    PovSurface p = darkSurface();
    p.finish.diffuse = 0.8;
    p.finish.brilliance = 2.5;
    add(s, facingPlane(), kPigment, p);
    expectColor(trace(s, kView), 0.8 * std::pow(0.5, 2.5) * kPigment * Lc);
}

// Light from behind: nothing, unless the second diffuse value (|N·L|^brilliance) or
// double_illuminate (then the front value) lets it in.
TEST(PovShading, DiffuseBackAndDoubleIlluminate) {
    const Vec3 behind{std::sin(deg(60)), 0, std::cos(deg(60))};  // 120° from the facing normal
    auto shade = [&](double back, bool twoSided) {
        Scene s = povScene();
        s.lights.push_back(parallelLight(behind));
        PovSurface p = darkSurface();
        p.finish.diffuse = 0.8;
        p.finish.diffuseBack = back;
        p.finish.brilliance = 2;
        p.doubleIlluminate = twoSided;
        add(s, facingPlane(), kPigment, p);
        return trace(s, kView);
    };
    expectColor(shade(0, false), Vec3{});
    expectColor(shade(0.3, false), 0.3 * 0.25 * kPigment);
    expectColor(shade(0.3, true), 0.8 * 0.25 * kPigment);
}

// Highlights from behind: only with double_illuminate, computed with the normal that faces the
// viewer (measured, light 150° off it: specular 1 roughness 1 gives 0.25881 = N·H, phong 0; with
// only a second diffuse value the specular adds nothing: 0.5·0.866·C).
TEST(PovShading, HighlightsFromBehind) {
    const Vec3 behind{0.5, 0, std::sqrt(0.75)};
    auto shade = [&](bool twoSided, double phong, double specular, double back) {
        Scene s = povScene();
        s.lights.push_back(parallelLight(behind));
        PovSurface p = darkSurface();
        p.finish.phong = phong;
        p.finish.phongSize = 1;
        p.finish.specular = specular;
        p.finish.roughness = 1;
        p.finish.diffuseBack = back;
        p.doubleIlluminate = twoSided;
        add(s, facingPlane(), kPigment, p);
        return trace(s, kView);
    };
    expectColor(shade(true, 0, 1, 0), Vec3(0.25881), 2e-5);
    expectColor(shade(true, 1, 0, 0), Vec3{});
    expectColor(shade(false, 0, 1, 0), Vec3{});
    expectColor(shade(false, 0, 1, 0.5), 0.5 * std::sqrt(0.75) * kPigment);
}

// phong·(R·V)^phong_size in the light's colour, not the pigment's (measured: phong 0.7, size 20,
// 10° off the mirror direction: 0.51539 in every channel).
TEST(PovShading, PhongHighlight) {
    for (double angle : {0.0, 10.0}) {
        Scene s = povScene();
        s.lights.push_back(parallelLight(frontAt(angle)));
        PovSurface p = darkSurface();
        p.finish.phong = 0.7;
        p.finish.phongSize = 20;
        add(s, facingPlane(), kPigment, p);
        expectColor(trace(s, kView), Vec3(0.7 * std::pow(std::cos(deg(angle)), 20)));
    }
    EXPECT_NEAR(0.7 * std::pow(std::cos(deg(10)), 20), 0.51539, 2e-5);
}

// specular·(N·H)^(1/roughness) (measured: specular 0.7, roughness 0.02, light 20° off: 0.32559,
// N·H = cos 10°).
TEST(PovShading, SpecularHighlight) {
    for (double angle : {0.0, 20.0}) {
        Scene s = povScene();
        s.lights.push_back(parallelLight(frontAt(angle)));
        PovSurface p = darkSurface();
        p.finish.specular = 0.7;
        p.finish.roughness = 0.02;
        add(s, facingPlane(), kPigment, p);
        expectColor(trace(s, kView), Vec3(0.7 * std::pow(std::cos(deg(angle / 2)), 50)));
    }
}

// metallic tints the highlight by 1 + m·(1 − F)·(C − 1), F from the angle of incidence (measured:
// light at 60°, phong 1 size 1, metallic 1 on <.5,.6,.7>: <.26482,.31186,.35890>).
TEST(PovShading, MetallicHighlight) {
    Scene s = povScene();
    s.lights.push_back(parallelLight(frontAt(60)));
    PovSurface p = darkSurface();
    p.finish.phong = 1;
    p.finish.phongSize = 1;
    p.finish.metallic = 1;
    add(s, facingPlane(), kPigment, p);
    expectColor(trace(s, kView), {0.26482, 0.31186, 0.35890}, 2e-5);
    // The curve itself at the measured angles (tests/data/povray/shading/measure_metallic.py).
    EXPECT_NEAR(povMetallicCurve(std::cos(deg(0))), 0.0, 1e-4);
    EXPECT_NEAR(povMetallicCurve(std::cos(deg(30))), 0.01192, 2e-5);
    EXPECT_NEAR(povMetallicCurve(std::cos(deg(80))), 0.26117, 2e-4);
    EXPECT_NEAR(povMetallicCurve(std::cos(deg(88))), 0.70865, 2e-4);
}

// Filter vs transmit on a pane (ior 1, ambient 1) over a coloured background: the pane keeps
// 1 − filter − transmit of its own colour and lets through (filter·C + transmit)·background
// (measured: rgbf <.5,.6,.7,.5> → <.3,.45,.665>; rgbt ... 0.5 → <.35,.55,.8>).
TEST(PovShading, FilterVersusTransmitThroughAPane) {
    auto pane = [](double filter, double transmit) {
        Scene s = povScene();
        s.pov.background = kBackground;
        PovSurface p = darkSurface();
        p.finish.ambient = Vec3(1.0);
        p.transmit = transmit;
        add(s, facingPlane(), kPigment, p, filter);
        return trace(s, kView);
    };
    expectColor(pane(0.5, 0), {0.3, 0.45, 0.665});
    expectColor(pane(0, 0.5), {0.35, 0.55, 0.8});
    expectColor(pane(0.3, 0.4), 0.3 * kPigment + (0.3 * kPigment + Vec3(0.4)) * kBackground);
}

// Legacy scenes (#version below 3.7): the own colour keeps 1 − (filter·max(C) + transmit)
// (measured: rgbft <.2,.6,.9,.5,.1>, ambient 1: 3.7 gives .4·C, 3.6 gives .45·C).
TEST(PovShading, LegacyOpacity) {
    for (double version : {3.7, 3.6}) {
        Scene s = povScene();
        s.pov.version = version;
        PovSurface p = darkSurface();
        p.finish.ambient = Vec3(1.0);
        p.transmit = 0.1;
        const Vec3 C{0.2, 0.6, 0.9};
        add(s, facingPlane(), C, p, 0.5);
        expectColor(trace(s, kView), (version < 3.7 ? 0.45 : 0.4) * C);
    }
}

// Highlights are not weighted by the opacity (measured: phong 1 on rgbft <.5,.6,.7,.3,.4> gives
// the opaque surface's 0.5 at 60°), diffuse is (0.3 of it).
TEST(PovShading, HighlightsIgnoreTransparency) {
    Scene s = povScene();
    s.lights.push_back(parallelLight(frontAt(60)));
    PovSurface p = darkSurface();
    p.finish.diffuse = 0.8;
    p.finish.phong = 1;
    p.finish.phongSize = 1;
    p.transmit = 0.4;
    add(s, facingPlane(), kPigment, p, 0.3);
    expectColor(trace(s, kView), 0.3 * 0.8 * 0.5 * kPigment + Vec3(0.5));
}

// reflection C adds C·(reflected colour) without taking anything from the surface's own colour.
TEST(PovShading, ReflectionOfAColouredBackground) {
    Scene s = povScene();
    s.pov.background = kBackground;
    PovSurface p = darkSurface();
    p.finish.ambient = Vec3(1.0);
    p.finish.reflectionMin = p.finish.reflectionMax = {0.4, 0.2, 0.1};
    add(s, facingPlane(), kPigment, p);
    expectColor(trace(s, kView), kPigment + Vec3{0.4, 0.2, 0.1} * kBackground);
}

// Variable reflection min + (max − min)·(1 − cos)^falloff (measured {0.1, 0.9}: 0.5 at 60°,
// falloff 2: 0.3); fresnel on: min + (max − min)·F with the exact Fresnel F of the interior's ior
// (measured 0.04000, 0.08919 and 0.38771 at 0°, 60°, 80° for ior 1.5).
TEST(PovShading, VariableAndFresnelReflection) {
    auto reflectivity = [](double tilt, const PovSurface& p) {
        Scene s = povScene();
        s.pov.background = Vec3(1.0);
        add(s, facingPlane(tilt), Vec3{}, p);
        return trace(s, kView).x;
    };
    PovSurface p = darkSurface();
    p.finish.reflectionMin = Vec3(0.1);
    p.finish.reflectionMax = Vec3(0.9);
    EXPECT_NEAR(reflectivity(60, p), 0.5, 1e-9);
    p.finish.reflectionFalloff = 2;
    EXPECT_NEAR(reflectivity(60, p), 0.3, 1e-9);
    PovSurface f = darkSurface();
    f.finish.reflectionMin = Vec3(0.0);
    f.finish.reflectionMax = Vec3(1.0);
    f.finish.reflectionFresnel = true;
    f.interior.ior = 1.5;
    EXPECT_NEAR(reflectivity(0, f), 0.04, 1e-9);
    EXPECT_NEAR(reflectivity(60, f), 0.08919, 1e-5);
    EXPECT_NEAR(reflectivity(80, f), 0.38771, 1e-5);
}

// exponent shapes the reflected colour, c^(1/exponent); metallic tints the reflection by the
// pigment (measured: reflection { .4 exponent .5 } over <.2,.5,.9> → <.016,.1,.324>;
// reflection { .4 metallic 1 } at normal incidence → .4·C·background).
TEST(PovShading, ReflectionExponentAndMetallic) {
    auto shade = [](double exponent, double metallic) {
        Scene s = povScene();
        s.pov.background = kBackground;
        PovSurface p = darkSurface();
        p.finish.reflectionMin = p.finish.reflectionMax = Vec3(0.4);
        p.finish.reflectionExponent = exponent;
        p.finish.reflectionMetallic = metallic;
        add(s, facingPlane(), kPigment, p);
        return trace(s, kView);
    };
    expectColor(shade(0.5, 0), {0.016, 0.1, 0.324});
    expectColor(shade(1, 1), 0.4 * kPigment * kBackground, 1e-4);
}

// conserve_energy multiplies filter and transmit by 1 − reflection, per channel (measured:
// reflection <.4,.2,.1> on rgbft <.5,.6,.7,.3,.4> → transmitted part .6, .8, .9 of its value).
TEST(PovShading, ConserveEnergy) {
    Scene s = povScene();
    s.pov.background = kBackground;
    PovSurface p = darkSurface();
    p.finish.reflectionMin = p.finish.reflectionMax = {0.4, 0.2, 0.1};
    p.finish.conserveEnergy = true;
    p.transmit = 0.4;
    add(s, facingPlane(), kPigment, p, 0.3);
    const Vec3 through = (0.3 * kPigment + Vec3(0.4)) * kBackground;
    expectColor(trace(s, kView), Vec3{0.4, 0.2, 0.1} * kBackground + Vec3{0.6, 0.8, 0.9} * through);
}

// Inside glass (ior 1.5) beyond the critical angle: one reflected ray with the whole weight takes
// the place of reflection and transmission (measured: rgbf <.5,.6,.7,.5>, reflection .3, seen from
// inside at 60°: exactly the background); below it the ray refracts out, tinted filter·C.
TEST(PovShading, RefractionAndTotalInternalReflection) {
    auto inside = [](double tilt) {
        Scene s = povScene();
        s.pov.background = kBackground;
        PovSurface p = darkSurface();
        p.finish.reflectionMin = p.finish.reflectionMax = Vec3(0.3);
        p.interior.ior = 1.5;
        Object plane = facingPlane(tilt);
        plane.p0 = -plane.p0;  // the camera is inside
        plane.r0 = -plane.r0;
        prepareObject(plane, Transform{});
        add(s, plane, kPigment, p, 0.5);
        return trace(s, kView);
    };
    expectColor(inside(60), kBackground);
    expectColor(inside(0), 0.5 * kPigment * kBackground + 0.3 * kBackground);
}

// fade: a + (1 − a)·fade_color with a = 1/(1 + (d/fade_distance)^fade_power), or with power
// 1000 and more exp(−(1 − fade_color)·d/fade_distance) (measured on a slab of depth 1, white
// behind, fade_distance 2, fade_color <.5,.2,0>: power 1 → <.83333,.73333,.66667>, power 1000 →
// <.77879,.67032,.60653>).
TEST(PovShading, InteriorFade) {
    auto slab = [](double power) {
        Scene s = povScene();
        s.pov.background = Vec3(1.0);
        PovSurface p = darkSurface();
        p.transmit = 1;
        p.interior.fadeDistance = 2;
        p.interior.fadePower = power;
        p.interior.fadeColor = {0.5, 0.2, 0};
        add(s, box({-5, -5, 0}, {5, 5, 1}), Vec3(1.0), p);
        return trace(s, kView);
    };
    // The ray inside starts kSurfaceOffset past the entry: it is 0.999 long.
    const double a = 1 / (1 + 0.999 / 2);
    expectColor(slab(1), Vec3(a) + (1 - a) * Vec3{0.5, 0.2, 0});
    expectColor(slab(1000), {std::exp(-0.5 * 0.999 / 2), std::exp(-0.8 * 0.999 / 2), std::exp(-0.999 / 2)});
    // The measured values, at depth 1 and 2 (power 2: <.9,.84,.8> and <.75,.6,.5>).
    expectColor(povFade(PovInterior{1, 2, 1, {0.5, 0.2, 0}}, 1), {0.83333, 0.73333, 0.66667}, 2e-5);
    expectColor(povFade(PovInterior{1, 2, 1000, {0.5, 0.2, 0}}, 1), {0.77879, 0.67032, 0.60653}, 2e-5);
    expectColor(povFade(PovInterior{1, 2, 2, {0.5, 0.2, 0}}, 1), {0.9, 0.84, 0.8});
    expectColor(povFade(PovInterior{1, 2, 2, {0.5, 0.2, 0}}, 2), {0.75, 0.6, 0.5});
    expectColor(povFade(PovInterior{1, 0, 2, {0.5, 0.2, 0}}, 2), Vec3(1.0));  // fade_distance 0: none
}

// Only transmitted rays fade inside an interior; rays reflected inside it do not (measured: a clear
// slab of depth 1 with reflection 0.4, fade_distance 1, fade_power 1001, over background 0.3,
// max_trace_level 3: 0.27451 = 0.4·0.3 + e⁻¹·(0.3 + 0.4·0.3); fading the reflected ray too would
// give 0.24660).
TEST(PovShading, ReflectedRaysInsideDoNotFade) {
    Scene s = povScene();
    s.pov.background = Vec3(0.3);
    s.pov.maxTraceLevel = 3;
    s.pov.adcBailout = 0;
    PovSurface p = darkSurface();
    p.transmit = 1;
    p.finish.reflectionMin = p.finish.reflectionMax = Vec3(0.4);
    p.interior.fadeDistance = 1;
    p.interior.fadePower = 1001;
    add(s, box({-5, -5, 0}, {5, 5, 1}), Vec3(1.0), p);
    const double inside = 1 - Tracer::kSurfaceOffset;  // the transmitted ray's length
    const double want = 0.4 * 0.3 + std::exp(-inside) * (0.3 + 0.4 * 0.3);
    EXPECT_NEAR(trace(s, kView).x, want, 1e-9);
    EXPECT_NEAR(want, 0.27451, 2e-4);
}

// The light at a point inside a fading interior, seen through it over V: POV-Ray 3.7 fades it
// over the shadow ray's path inside (S, to where it leaves) and divides it by the viewing ray's
// fade over V, so that only the shadow path counts in the end (measured on a floor inside a clear
// box whose front is 2 in front of it, fade_distance 1: power 2, light 37° off: factor 0.68766 =
// fade(2.504)/fade(2), not fade(2.504 − 2); a light inside the box: 1/fade(2) = 5; light 80° off
// through a side 0.875 away, power 1001: e^+1.11, brighter than no box at all).
TEST(PovShading, LightInsideAFadingInteriorIsDividedByTheViewingRaysFade) {
    struct Case {
        double angle, side, power;
    };
    for (const Case c : {Case{37, 50, 2}, Case{60, 50, 1001}, Case{80, 1, 1001}}) {
        Scene s = povScene();
        s.lights.push_back(parallelLight(frontAt(c.angle)));
        PovSurface clear = darkSurface();
        clear.transmit = 1;
        clear.interior.fadeDistance = 1;
        clear.interior.fadePower = c.power;
        add(s, box({-50, -50, -2}, {c.side, 50, 2}), Vec3(1.0), clear);
        PovSurface floor = darkSurface();
        floor.finish.diffuse = 1;
        add(s, facingPlane(), Vec3(0.2), floor);
        const double a = deg(c.angle), off = Tracer::kSurfaceOffset;
        // The shadow ray leaves the floor `off` above it, at x = 0.1.
        const double shadow = std::min((c.side - 0.1) / std::sin(a), (2 - off) / std::cos(a));
        auto fade = [&](double d) {
            return c.power >= 1000 ? std::exp(-d) : 1 / (1 + std::pow(d, c.power));
        };
        const double want = 0.2 * std::cos(a) * fade(shadow);  // the view's fade cancels out
        EXPECT_NEAR(trace(s, kView).x, want, 1e-9) << c.angle;
    }
    // A point light inside the box: nothing to leave, the light is divided by the view's fade.
    Scene s = povScene();
    Light light;
    light.position = {0, 0, -1};
    s.lights.push_back(light);
    PovSurface clear = darkSurface();
    clear.transmit = 1;
    clear.interior.fadeDistance = 1;
    clear.interior.fadePower = 2;
    add(s, box({-50, -50, -2}, {50, 50, 2}), Vec3(1.0), clear);
    PovSurface floor = darkSurface();
    floor.finish.diffuse = 1;
    add(s, facingPlane(), Vec3(0.2), floor);
    const Vec3 toLight = light.position - Vec3{0.1, -0.1, 0};
    EXPECT_NEAR(trace(s, kView).x, 0.2 * -toLight.z / length(toLight), 1e-9);
}

// A shadow ray passes transparent objects, tinted by filter·C + transmit at each surface it
// crosses (measured: a thin box of rgbf <.5,.6,.7,.5> between a parallel light at 60° and a white
// floor, diffuse 1: <.03125,.045,.06125> = 0.5·(0.5·C)²); an opaque one blocks.
TEST(PovShading, ColouredShadowThroughAFilterPane) {
    auto floorLit = [](double filter, double transmit) {
        Scene s = povScene();
        s.lights.push_back(parallelLight(frontAt(60)));
        PovSurface floor = darkSurface();
        floor.finish.diffuse = 1;
        add(s, facingPlane(), Vec3(1.0), floor);
        PovSurface pane = darkSurface();
        pane.transmit = transmit;
        add(s, box({1, -5, -1.01}, {5, 5, -1}), kPigment, pane, filter);
        return trace(s, kView);
    };
    expectColor(floorLit(0.5, 0), {0.03125, 0.045, 0.06125});
    expectColor(floorLit(0, 0.5), Vec3(0.125));
    expectColor(floorLit(0, 0), Vec3{});
}

// The same for a point reached by a ray reflected inside the interior: its light is divided by what
// the rays faded on the way in (measured: a clear fading box holding a 45° mirror that sends the
// view to a wall inside the box: 0.01152 = 0.2·0.6·e^−2.344, the shadow path's fade alone).
TEST(PovShading, LightAfterAReflectionInsideAFadingInterior) {
    Scene s = povScene();
    s.lights.push_back(parallelLight({0.6, 0, -0.8}));
    PovSurface clear = darkSurface();
    clear.transmit = 1;
    clear.interior.fadeDistance = 1;
    clear.interior.fadePower = 1001;
    add(s, box({-50, -50, -2}, {50, 50, 4}), Vec3(1.0), clear);
    PovSurface mirror = darkSurface();
    mirror.finish.reflectionMin = mirror.finish.reflectionMax = Vec3(1.0);
    const Vec3 n = normalize(Vec3{-1, 0, -1});  // faces the camera, turned 45° about y
    add(s, test::makeObject(ShapeType::Plane, n, {}, {}, 0, 0), Vec3{}, mirror);
    PovSurface wall = darkSurface();
    wall.finish.diffuse = 1;
    add(s, test::makeObject(ShapeType::Plane, {1, 0, 0}, {}, {}, -2, 0), Vec3(0.2), wall);
    // The view meets the mirror at z = −0.1 and the wall at (−2, −0.1, −0.1); its shadow ray
    // leaves the box through z = −2.
    const double shadow = (2 - 0.1) / 0.8;
    EXPECT_NEAR(trace(s, kView).x, 0.2 * 0.6 * std::exp(-shadow), 1e-5);
}

// Along a shadow ray, an interior fades the light over the length between entry and exit
// (measured: a clear box 2 deep beside the view, fade_distance 2, fade_color <.5,.2,0>, crossed
// over 3.629 by the shadow ray of povray's centre pixel: <.33882,.24211,.17765> with power 1).
TEST(PovShading, ShadowFadesThroughAThickBox) {
    for (double power : {1.0, 1001.0}) {
        Scene s = povScene();
        s.lights.push_back(parallelLight(frontAt(60)));
        PovSurface floor = darkSurface();
        floor.finish.diffuse = 1;
        add(s, facingPlane(), Vec3(1.0), floor);
        PovSurface clear = darkSurface();
        clear.transmit = 1;
        clear.interior = PovInterior{1, 2, power, {0.5, 0.2, 0}};
        add(s, box({1, -5, -3}, {5, 5, -1}), Vec3(1.0), clear);
        // The shadow ray leaves (0.1, −0.1, −off) along (sin 60°, 0, −cos 60°): in through the top
        // (z = −1), out through the side x = 5.
        const double off = Tracer::kSurfaceOffset, sn = std::sin(deg(60)), cs = std::cos(deg(60));
        const double inside = (5 - 0.1) / sn - (1 - off) / cs;
        expectColor(trace(s, kView), 0.5 * povFade(clear.interior, inside));
        if (power == 1) expectColor(0.5 * povFade(clear.interior, 3.629), {0.33882, 0.24211, 0.17765}, 1e-4);
    }
}

// A parallel light's shadow rays end at the plane through its position (measured: an occluder 6
// units along the shadow ray shadows a light placed 100 away, not one placed 4 away).
TEST(PovShading, ParallelLightShadowsEndAtItsPlane) {
    for (double distance : {4.0, 100.0}) {
        Scene s = povScene();
        Light light = parallelLight(frontAt(60));
        light.position = distance * frontAt(60);
        s.lights.push_back(light);
        PovSurface floor = darkSurface();
        floor.finish.diffuse = 1;
        add(s, facingPlane(), Vec3(1.0), floor);
        add(s, box({1, -5, -3.01}, {8, 5, -3}), Vec3{}, darkSurface());
        expectColor(trace(s, kView), Vec3(distance < 6 ? 0.5 : 0.0));
    }
}

// An area light is shaded from its centre; its samples only decide how much arrives (measured: a
// 2×1 light with samples at ±4 two units above the floor gives the centre's cosine, 0.99612).
TEST(PovShading, AreaLightShadesFromItsCentre) {
    Scene s = povScene();
    Light light;
    light.position = {0, 0, -2};
    light.area = true;
    light.axis1 = {8, 0, 0};
    light.axis2 = {0, 1, 0};
    light.n1 = 2;
    light.n2 = 1;
    s.lights.push_back(light);
    PovSurface floor = darkSurface();
    floor.finish.diffuse = 1;
    add(s, facingPlane(), Vec3(1.0), floor);
    const Vec3 toCentre = light.position - Vec3{0.1, -0.1, 0};
    expectColor(trace(s, kView), Vec3(-toCentre.z / length(toCentre)));
    // Half the samples blocked (an opaque wall over x > 1): half the light.
    add(s, box({1, -5, -1.1}, {9, 5, -1}), Vec3{}, darkSurface());
    expectColor(trace(s, kView), Vec3(0.5 * -toCentre.z / length(toCentre)));
}

// max_trace_level: the camera ray is level 1; a mirror at the last level reflects nothing
// (measured between two mirrors, ambient 0.1, reflection 0.5: 0.1, 0.15, 0.175 for levels 1-3).
// adc_bailout: a ray whose weight falls below it is not traced (0.2: weights 1, .5, .25 traced).
TEST(PovShading, MaxTraceLevelAndAdcBailoutBetweenTwoMirrors) {
    auto mirrors = [](int maxLevel, double bailout) {
        Scene s = povScene();
        s.pov.maxTraceLevel = maxLevel;
        s.pov.adcBailout = bailout;
        s.pov.background = Vec3(1.0);
        PovSurface p = darkSurface();
        p.finish.ambient = Vec3(0.1);
        p.finish.reflectionMin = p.finish.reflectionMax = Vec3(0.5);
        add(s, facingPlane(), Vec3(1.0), p);
        add(s, test::makeObject(ShapeType::Plane, {0, 0, 1}, {}, {}, -2, 0), Vec3(1.0), p);
        return trace(s, Ray{{0, 0, -1}, {0, 0, 1}}).x;
    };
    EXPECT_NEAR(mirrors(1, 0), 0.1, 1e-12);
    EXPECT_NEAR(mirrors(2, 0), 0.15, 1e-12);
    EXPECT_NEAR(mirrors(3, 0), 0.175, 1e-12);
    EXPECT_NEAR(mirrors(20, 0.2), 0.175, 1e-12);
    EXPECT_NEAR(mirrors(20, 0.1), 0.1875, 1e-12);
}

// Transmitted rays carry a weight too, times max(filter·C + transmit) (measured: three thin boxes of
// rgbt .5 with ambient .2 before a white background: 0.175 with adc_bailout 0.2, 0.1875 with 0.1).
TEST(PovShading, AdcBailoutOnTransmittedRays) {
    auto stack = [](double bailout) {
        Scene s = povScene();
        s.pov.background = Vec3(1.0);
        s.pov.adcBailout = bailout;
        s.pov.maxTraceLevel = 20;
        PovSurface p = darkSurface();
        p.finish.ambient = Vec3(0.2);
        p.transmit = 0.5;
        for (int k = 0; k < 3; ++k) add(s, box({-5, -5, 0.1 * k}, {5, 5, 0.1 * k + 0.01}), Vec3(1.0), p);
        return trace(s, kView).x;
    };
    EXPECT_NEAR(stack(0.2), 0.175, 1e-12);
    EXPECT_NEAR(stack(0.1), 0.1875, 1e-12);
    EXPECT_NEAR(stack(0), 0.1 * (1 + 0.5 + 0.25 + 0.125 + 0.0625 + 0.03125) + 0.015625, 1e-12);
}

// Passing straight through a surface (ior 1) keeps the trace level, refracting adds one (measured:
// four clear thin boxes need max_trace_level 2 with ior 1, 9 with ior 1.5).
TEST(PovShading, StraightThroughKeepsTheTraceLevel) {
    auto boxes = [](int maxLevel, double ior) {
        Scene s = povScene();
        s.pov.maxTraceLevel = maxLevel;
        s.pov.background = Vec3(1.0);
        PovSurface p = darkSurface();
        p.transmit = 1;
        p.interior.ior = ior;
        for (int k = 0; k < 4; ++k) add(s, box({-5, -5, 0.1 * k}, {5, 5, 0.1 * k + 0.01}), Vec3(1.0), p);
        return trace(s, kView).x;
    };
    EXPECT_EQ(boxes(1, 1.0), 0.0);
    EXPECT_NEAR(boxes(2, 1.0), 1.0, 1e-12);
    EXPECT_EQ(boxes(8, 1.5), 0.0);
    EXPECT_NEAR(boxes(9, 1.5), 1.0, 1e-12);
}

// Output: sRGB(c^assumed_gamma) (measured: rgb 0.5 with ambient 1 is written as 188 with
// assumed_gamma 1, 128 with 2.2; <.2,.5,.9> as 124 188 243 and 48 128 230; legacy scenes without
// assumed_gamma write the colour as it is, 51 128 230).
TEST(PovShading, OutputEncoding) {
    const Vec3 c{0.2, 0.5, 0.9};
    auto bytes = [&](double gamma) {
        const Vec3 o = povOutputColor(c, gamma);
        return std::array<int, 3>{toByte(o.x), toByte(o.y), toByte(o.z)};
    };
    EXPECT_EQ(bytes(1.0), (std::array<int, 3>{124, 188, 243}));
    EXPECT_EQ(bytes(2.2), (std::array<int, 3>{48, 128, 230}));
    EXPECT_EQ(bytes(0.0), (std::array<int, 3>{51, 128, 230}));
    EXPECT_NEAR(srgbEncode(0.5), 0.735357, 1e-6);
    EXPECT_NEAR(srgbEncode(0.002), 0.02584, 1e-6);  // the linear toe
    expectColor(povOutputColor({2, -1, 1}, 1.0), {1, 0, 1});
}

// File_Gamma g: (c^assumed_gamma)^(1/g) instead of sRGB; nothing for legacy scenes (measured:
// rgb 0.2 with ambient 1 is written as 51 with File_Gamma 1.0, 123 with 2.2, 104 with 1.8 under
// assumed_gamma 1; 7, 51 and 36 under assumed_gamma 2.2; 51 whatever File_Gamma in a 3.6 scene).
TEST(PovShading, FileGammaEncodesWithItsPower) {
    auto byte = [](double assumed, double file) { return int(toByte(povOutputColor({0.2, 0.2, 0.2}, assumed, file).x)); };
    EXPECT_EQ(byte(1.0, 1.0), 51);
    EXPECT_EQ(byte(1.0, 2.2), 123);
    EXPECT_EQ(byte(1.0, 1.8), 104);
    EXPECT_EQ(byte(2.2, 1.0), 7);
    EXPECT_EQ(byte(2.2, 2.2), 51);
    EXPECT_EQ(byte(2.2, 1.8), 36);
    EXPECT_EQ(byte(0.0, 1.8), 51);
    EXPECT_EQ(byte(1.0, 0.0), 124);  // 0: sRGB
}

// render() writes POV-Ray scenes' pixels encoded; course scenes are left alone.
TEST(PovShading, RenderEncodesPovRayScenesOnly) {
    Scene s = povScene();
    PovSurface p = darkSurface();
    p.finish.ambient = Vec3(1.0);
    add(s, facingPlane(), Vec3(0.5), p);
    RenderSettings rs;
    rs.width = 4;
    rs.height = 3;
    rs.threads = 1;
    for (double gamma : {1.0, 2.2}) {
        s.pov.assumedGamma = gamma;
        const Bvh bvh(s.objects);
        TraceStats stats;
        const Image8 img = toImage8(render(s, bvh, rs, stats));
        for (uint8_t b : img.pixels) EXPECT_EQ(b, gamma == 1.0 ? 188 : 128);
    }
    // The same objects in a course scene: the course's shading, written as traced.
    s.pov.enabled = false;
    s.objects[0].material.ambient = 0.5;
    const Bvh bvh(s.objects);
    TraceStats stats;
    const Image8 img = toImage8(render(s, bvh, rs, stats));
    for (uint8_t b : img.pixels) EXPECT_EQ(b, toByte(0.25));
}

// The feature lines' records: ids along the ray tree and the lights blocked at the primary hit.
TEST(PovShading, PathInfoOfPovRayScenes) {
    Scene s = povScene();
    s.pov.background = kBackground;
    s.lights.push_back(parallelLight(frontAt(60)));
    PovSurface p = darkSurface();
    p.finish.diffuse = 1;
    p.finish.reflectionMin = p.finish.reflectionMax = Vec3(0.5);
    add(s, facingPlane(), Vec3(1.0), p);
    add(s, box({1, -5, -1.01}, {5, 5, -1}), Vec3{}, darkSurface());  // blocks the light
    PathInfo info;
    trace(s, kView, &info);
    ASSERT_EQ(info.count, 2);
    EXPECT_EQ(info.ids[0], 0);
    EXPECT_EQ(info.ids[1], -1);  // the reflection sees the background
    EXPECT_EQ(info.blockedLights, 1);
    EXPECT_NEAR(info.t, 3.0, 1e-6);
}

}}  // namespace RAYS_TEST_UNIT, namespace
