// Sample positions of area lights (scene/light.h: an n1 × n2 grid over a rectangle or disc, with
// jitter and orient), shared by the course's light loop and POV-Ray's (tracer_povray.cpp).
#pragma once
#include <algorithm>

#include "rays/math/sampling.h"
#include "rays/render/sampler.h"
#include "rays/scene/light.h"

namespace rays {

/// The grid of one area light as seen from one shaded point: sample counts and the two axes.
struct AreaGrid {
    int n1 = 1, n2 = 1;
    Vec3 a1, a2;
};

/// Offset of sample i of n along one area-light axis, in [−½, ½] (POV-Ray: i/(n−1) − ½; the
/// centre when n = 1). With jitter the sample moves randomly within its cell.
inline double areaOffset(int i, int n, bool jitter, SampleRng& rng) {
    if (n == 1) return jitter ? rng.next() - 0.5 : 0.0;
    double s = double(i) / (n - 1) - 0.5;
    if (jitter) s += (rng.next() - 0.5) / (n - 1);
    return std::clamp(s, -0.5, 0.5);
}

/// The light's grid for shading P: its own sample counts unless samplesOverride > 0 (both axes);
/// with orient the light's plane turns to face P, keeping the axis lengths.
inline AreaGrid areaGrid(const Light& light, int samplesOverride, Vec3 P) {
    AreaGrid g;
    g.n1 = samplesOverride > 0 ? samplesOverride : light.n1;
    g.n2 = samplesOverride > 0 ? samplesOverride : light.n2;
    g.a1 = light.axis1;
    g.a2 = light.axis2;
    if (light.orient) {
        const Vec3 toP = P - light.position;
        if (length(toP) > 0) {
            Vec3 t, b;
            orthonormalBasis(normalize(toP), t, b);
            g.a1 = length(light.axis1) * t;
            g.a2 = length(light.axis2) * b;
        }
    }
    return g;
}

/// Position of sample (u, v) of the grid; jitter draws two numbers from rng (u's first). Circular
/// lights map the grid onto the disc (ellipse) inscribed in the rectangle.
inline Vec3 areaSample(const Light& light, const AreaGrid& g, int u, int v, SampleRng& rng) {
    double s1 = areaOffset(u, g.n1, light.jitter, rng), s2 = areaOffset(v, g.n2, light.jitter, rng);
    if (light.circular) {
        double x, y;
        concentricDisc(s1 + 0.5, s2 + 0.5, x, y);
        s1 = 0.5 * x;
        s2 = 0.5 * y;
    }
    return light.position + s1 * g.a1 + s2 * g.a2;
}

}  // namespace rays
