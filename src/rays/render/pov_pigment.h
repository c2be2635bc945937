// The colour of a POV-Ray surface at a point: its pigment pattern evaluated at the world point
// (PovSurface::pigment ≥ 0), else the flat colour of the material.
#pragma once
#include <algorithm>

#include "rays/scene/scene.h"

namespace rays {

struct PovPigmentSample {
    Vec3 color;
    double filter = 0, transmit = 0;
};

/// The pattern colour of surface s at world point P, N the (perturbed) normal facing the viewer
/// there (for the slope pattern); s.pigment must be ≥ 0. uv: the surface's (u, v, 0) when it has
/// texture coordinates (uv-mapped pigments are looked up there).
inline PovPigmentSample povPigmentAt(const Scene& scene, const PovSurface& s, Vec3 P, Vec3 N, const Vec3* uv = nullptr) {
    const pattern::Rgbft c = scene.pigments.atRoot(s.pigment, P, N, uv);
    return {c.rgb, std::clamp(c.filter, 0.0, 1.0), c.transmit};
}

/// The colour seen along a ray that meets nothing: the sky_sphere's pigments looked up at the
/// direction, each layer over the ones below (its filter and transmit let them through, as a
/// layered texture does), the lowest over the background; without a sky_sphere the background.
inline Vec3 povSky(const Scene& scene, Vec3 dir) {
    const PovGlobals& g = scene.pov;
    if (g.skyCount == 0) return g.background;
    const double len = length(dir);
    if (len == 0) return g.background;
    const Vec3 d = dir / len;
    Vec3 c = g.background;
    for (int i = 0; i < g.skyCount; ++i) {
        const pattern::Rgbft l = scene.pigments.atRoot(g.skyFirst + i, d);
        const double f = std::clamp(l.filter, 0.0, 1.0), t = std::clamp(l.transmit, 0.0, 1.0);
        c = l.rgb * std::max(0.0, 1 - f - t) + c * (Vec3(t) + f * l.rgb);
    }
    return c * g.skyEmission;
}

}  // namespace rays
