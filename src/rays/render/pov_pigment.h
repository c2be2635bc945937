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
/// there (for the slope and aoi patterns), D the direction of the ray that met it (aoi); s.pigment
/// must be ≥ 0. uv: the surface's (u, v, 0) when it has texture coordinates (uv-mapped pigments
/// are looked up there).
inline PovPigmentSample povPigmentAt(const Scene& scene, const PovSurface& s, Vec3 P, Vec3 N, const Vec3* uv = nullptr,
                                     Vec3 D = {}) {
    const pattern::Rgbft c = scene.pigments.atRoot(s.pigment, P, N, uv, D);
    return {c.rgb, std::clamp(c.filter, 0.0, 1.0), c.transmit};
}

/// The colour seen along a ray that meets nothing: the sky_sphere's pigments looked up at the
/// direction, the last written on top; without a sky_sphere the background. Measured with POV-Ray
/// 3.7 (one to three layers of rgbf, rgbt and rgbft colours over backgrounds, every 8-bit value
/// reproduced). A sky_sphere of #version 3.7 composes its layers as a layered texture's: each
/// layer L over what lies below it (B, the background under the bottom layer) gives
///   (1 − f − t)·L + f·L ⊙ B + t·B
/// (the changelog of POV-Ray 3.7.0 beta 37: filter in a layered sky_sphere "has the same effect as
/// in a large sphere with a multi-layered texture"). An older one (#version below 3.7) keeps
/// POV-Ray 3.6's way: a layer shows its own colour by 1 − f − t, seen through the layers above it
/// by the product of their filters plus the product of their transmits (the top layer fully; a
/// filter does not tint the layers below), and the background comes through by the product of
/// all the transmits plus the product of all the filters times their colours (one layer: t + f·L,
/// as through a surface, the same in both). Neither clamps 1 − f − t: a layer whose filter and
/// transmit add up to more than 1 takes its own colour away (measured):
///   C = Σᵢ (1 − fᵢ − tᵢ)·Lᵢ·(Πⱼ₍above i₎ fⱼ + Πⱼ₍above i₎ tⱼ) + B ⊙ (Πᵢ tᵢ + Πᵢ fᵢ·Lᵢ).
inline Vec3 povSky(const Scene& scene, Vec3 dir) {
    const PovGlobals& g = scene.pov;
    if (g.skyCount == 0) return g.background;
    const double len = length(dir);
    if (len == 0) return g.background;
    const Vec3 d = dir / len;
    if (g.skyLayersAsTexture) {
        Vec3 below = g.background;
        for (int i = 0; i < g.skyCount; ++i) {
            const pattern::Rgbft l = scene.pigments.atRoot(g.skyFirst + i, d);
            const double f = std::clamp(l.filter, 0.0, 1.0), t = std::clamp(l.transmit, 0.0, 1.0);
            below = (1 - f - t) * l.rgb + f * (l.rgb * below) + t * below;
        }
        return below * g.skyEmission;
    }
    Vec3 c{}, filteredColour{1, 1, 1};
    double filtered = 1, transmitted = 1;  // the products over the layers above
    for (int i = g.skyCount - 1; i >= 0; --i) {
        const pattern::Rgbft l = scene.pigments.atRoot(g.skyFirst + i, d);
        const double f = std::clamp(l.filter, 0.0, 1.0), t = std::clamp(l.transmit, 0.0, 1.0);
        const double seen = i == g.skyCount - 1 ? 1.0 : filtered + transmitted;
        c += seen * (1 - f - t) * l.rgb;
        filtered *= f;
        transmitted *= t;
        filteredColour = filteredColour * (f * l.rgb);
    }
    return (c + g.background * (Vec3(transmitted) + filteredColour)) * g.skyEmission;
}

}  // namespace rays
