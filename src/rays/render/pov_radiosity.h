// How POV-Ray 3.7's radiosity enters a surface's own colour, as measured with povray 3.7
// (docs/povray-lighting.md, "Radiosity"; tests/data/povray/shading/measure_radiosity.py). Pure
// functions; the tracer gathers the light (tracer_radiosity.cpp).
#pragma once
#include "rays/math/vec3.h"
#include "rays/scene/pov_surface.h"

namespace rays {

/// gray_threshold g: the gathered colour c becomes (1 − g)·c + g·grey(c), grey = .297 r + .589 g +
/// .114 b (measured with a coloured emitting sky at g = 0, .5 and 1).
inline Vec3 povGrayThreshold(Vec3 c, double g) {
    if (g == 0) return c;
    const double grey = 0.297 * c.x + 0.589 * c.y + 0.114 * c.z;
    return (1 - g) * c + Vec3(g * grey);
}

/// The ambient part of a surface's own colour with radiosity on: emission·C plus
/// diffuse·C·gathered (gathered: the light the radiosity brings, brightness and gray_threshold
/// applied). #version 3.7 scenes drop the finish's ambient (measured: ambient neither shows nor
/// lights other surfaces); older scenes keep ambient·ambient_light as without radiosity, and it
/// lights other surfaces as emission does (measured with #version 3.6).
inline Vec3 povRadiosityAmbient(const PovFinish& f, Vec3 C, Vec3 ambientLight, Vec3 gathered, double version) {
    const Vec3 own = version < 3.7 ? f.ambient * ambientLight + f.emission : f.emission;
    return (own + f.diffuse * gathered) * C;
}

}  // namespace rays
