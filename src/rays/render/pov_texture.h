// Layered and patterned textures at a point (POV-Ray 3.7 reference, "Layered Textures",
// "Patterned Textures", "Texture Maps"): which runs of layers a texture shows there and with what
// weight, each layer's pigment, and what the texture lets through to shadow rays.
#pragma once
#include "rays/render/pov_pigment.h"
#include "rays/scene/scene.h"

namespace rays {

/// A run of layers (Scene::povTextures.layers[begin, begin + count), the top first) shown with a weight.
struct PovTextureChoice {
    double weight = 0;
    int begin = 0, count = 0;
};

/// The texture node a ray meets on surface s from outside (entering) or inside: the interior
/// texture inside when there is one, else the texture; -1: the plain texture.
inline int povTextureSeen(const PovSurface& s, bool entering) {
    return !entering && s.interiorTexture >= 0 ? s.interiorTexture : s.texture;
}

/// At most this many textures are blended at one point (more are left out).
constexpr int kMaxTextureChoices = 8;

/// The runs of layers texture node `node` shows at world point P (N: the normal facing the viewer,
/// for the slope and aoi patterns; D: the direction of the ray, for aoi), with weights summing to 1: one
/// for layers, the pattern's map entry or block entry, two between map entries (linearly: the
/// manual blends the whole textures' colours), all of an average by the map's weights. Returns
/// how many were written to out.
/// uv: the surface's (u, v, 0) when it has texture coordinates (for uv-mapped patterns).
int povTextureChoices(const Scene& scene, int node, Vec3 P, Vec3 N, PovTextureChoice (&out)[kMaxTextureChoices],
                      const Vec3* uv = nullptr, Vec3 D = {});

/// A layer's pigment at world point P, N the layer's normal facing the viewer, D the ray's
/// direction (its pattern, or its flat colour).
inline PovPigmentSample povLayerPigment(const Scene& scene, const PovLayer& l, Vec3 P, Vec3 N, const Vec3* uv = nullptr,
                                        Vec3 D = {}) {
    if (l.surface.pigment >= 0) return povPigmentAt(scene, l.surface, P, N, uv, D);
    return {l.color, l.filter, l.surface.transmit};
}

/// What texture node `node` lets through at P, per channel: the product over each run's layers of
/// filter·C + transmit, the runs blended by their weights (measured: a shadow through a layered
/// pane is tinted by both layers).
Vec3 povTextureTint(const Scene& scene, int node, Vec3 P, Vec3 N, const Vec3* uv = nullptr, Vec3 D = {});

}  // namespace rays
