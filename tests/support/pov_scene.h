// POV-Ray text loaded into a Scene without the installed include folder, rays shot through it,
// and small renders checked against pixels measured from POV-Ray 3.7 (shared by the tests of
// POV-Ray's geometry).
#pragma once
#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rays/accel/bvh.h"
#include "rays/pov/load_pov.h"
#include "rays/render/renderer.h"

namespace rays::test {

/// A scene and the warnings its loading gave.
struct PovLoaded {
    Scene scene;
    std::vector<std::string> warnings;
};

/// The scene of head and text (head: `#version 3.7;` by default).
inline PovLoaded loadPov(const std::string& text, const std::string& head = "#version 3.7;\n") {
    PovLoaded l;
    ParseOptions o;
    o.warn = [&l](const std::string& w) { l.warnings.push_back(w); };
    o.language.installedIncludeDir.clear();
    l.scene = pov::parsePovText(head + text, "scene.pov", ".", o);
    return l;
}

/// The scene of `#version 3.7;` and text; warnings go to *warnings when given.
inline Scene buildPov(const std::string& text, std::vector<std::string>* warnings = nullptr) {
    PovLoaded l = loadPov(text);
    if (warnings) *warnings = std::move(l.warnings);
    return std::move(l.scene);
}

/// The nearest hit of the ray from `from` along `dir` (normalised).
inline Hit shootPov(const Scene& s, Vec3 from, Vec3 dir) {
    const Bvh bvh(s.objects);
    return bvh.closest(s.objects, Ray{from, normalize(dir)}, 1e-9, kInfinity);
}

/// The distances of the surfaces the ray crosses (at most 16), in order; each search starts
/// `step` past the last hit.
inline std::vector<double> allHitsPov(const Scene& s, Vec3 from, Vec3 dir, double step) {
    const Bvh bvh(s.objects);
    std::vector<double> ts;
    const Ray r{from, normalize(dir)};
    double t = 1e-9;
    for (int i = 0; i < 16; ++i) {
        const Hit h = bvh.closest(s.objects, r, t, kInfinity);
        if (!h.valid()) break;
        ts.push_back(h.t);
        t = h.t + step;
    }
    return ts;
}

/// The scene rendered at width × height (160×120 by default) on `threads` threads.
inline ImageF renderPov(const Scene& s, int width = 160, int height = 120, int threads = 2) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.threads = threads;
    const Bvh bvh(s.objects);
    TraceStats stats;
    return render(s, bvh, settings, stats);
}

/// A pixel of POV-Ray 3.7's render of the same scene (0–255) and what it shows.
struct PovPixel {
    int x, y;
    Vec3 povray;
    const char* what = "";
};

/// Every pixel within 3 levels of 255 (largest channel difference) of POV-Ray's.
inline void expectPovPixels(const ImageF& img, std::span<const PovPixel> pixels) {
    for (const PovPixel& p : pixels) {
        const Vec3 c = 255.0 * img.at(p.x, p.y);
        EXPECT_LE(std::max({std::fabs(c.x - p.povray.x), std::fabs(c.y - p.povray.y), std::fabs(c.z - p.povray.z)}), 3.0)
            << p.what << " at " << p.x << "," << p.y << ": " << c.x << " " << c.y << " " << c.z;
    }
}

}  // namespace rays::test
