// Local reflection models evaluated for one light: the course's Blinn-Phong and Cook-Torrance.
#pragma once
#include <cmath>

#include "rays/math/vec3.h"
#include "rays/scene/material.h"

namespace rays {

/// Diffuse and specular radiance from one unoccluded light.
struct LightTerms {
    Vec3 diffuse;
    Vec3 specular;
};

/// Course Blinn-Phong: diffuse = Lc·kd·C·max(0, N·L); specular = Lc·ks·C·(N·H)^(2/roughness² − 2).
/// N faces the viewer; L and V are unit vectors from the surface to the light and viewer.
/// Diffuse is zero when N·L ≤ 0; the specular lobe is not gated by N·L (the course reference
/// renderer's behaviour, visible on its pbr_grid image).
LightTerms blinnPhong(const Material& m, Vec3 N, Vec3 L, Vec3 V, Vec3 lightColor);

/// Course Cook-Torrance: Lambert diffuse plus ks·C·Lc·D·G·F / (4·max(1/16, |N·V|)) with GGX D
/// (α = roughness²), Smith-GGX G and Schlick F on V·H from the finish ior (blended toward 1 by
/// metallic, which also removes the diffuse term). Zero when N·L ≤ 0.
LightTerms cookTorrance(const Material& m, Vec3 N, Vec3 L, Vec3 V, Vec3 lightColor);

/// Lambert: diffuse only, Lc·kd·C·max(0, N·L).
LightTerms lambert(const Material& m, Vec3 N, Vec3 L, Vec3 lightColor);

/// Oren-Nayar rough diffuse (roughness σ = material.sigma in degrees); equals Lambert at σ = 0.
LightTerms orenNayar(const Material& m, Vec3 N, Vec3 L, Vec3 V, Vec3 lightColor);

/// True when the model gives nothing at all from a light with N·L ≤ 0, whether the light is
/// visible or not (every model but Blinn-Phong with a specular term): its shadow ray can be skipped.
inline bool darkFacingAway(const Material& m, ShadingModel model) {
    return model == ShadingModel::CookTorrance || model == ShadingModel::OrenNayar ||
           model == ShadingModel::Lambert || m.specular == 0;
}

/// True when dot(toLight / |toLight|, N) is certainly below zero, decided without the square root
/// and division that normalise toLight: dot(toLight, N) is negative by far more than the rounding
/// of either dot product (~1e-16 of the sum of the products' sizes), so both have the same sign.
/// Near zero it answers false and the normalised test decides, as before.
inline bool clearlyFacingAway(Vec3 toLight, Vec3 N) {
    const double d = dot(toLight, N);
    const double size = std::fabs(toLight.x * N.x) + std::fabs(toLight.y * N.y) + std::fabs(toLight.z * N.z);
    return d < -1e-12 * size;
}

/// Schlick's approximation with F0 = ((ior − 1)/(ior + 1))², cosTheta = |N·V|.
double schlickFresnel(double ior, double cosTheta);

}  // namespace rays
