// POV-Ray 3.7's surface formulas (reference manual "Finish", "Interior", "Color Expressions"),
// with the details the manual leaves open settled by black-box measurements of povray 3.7
// (docs/povray-lighting.md; the scenes are in tests/data/povray/shading). Pure functions: the
// tracer (tracer_povray.cpp) finds the lights, rays and colours they combine.
#pragma once
#include <cmath>
#include <vector>

#include "rays/geometry/ray.h"
#include "rays/math/vec3.h"
#include "rays/scene/light.h"
#include "rays/scene/material.h"
#include "rays/scene/pov_surface.h"

namespace rays {

/// Whether the light shines on the surface, by light_group (Light::lightGroup).
inline bool povLightsSurface(const Light& light, const PovSurface& s) {
    return light.lightGroup == s.lightGroup || (light.lightGroup < 0 && s.globalLights);
}

/// The unit direction L from P towards the light (against a parallel light's direction); false
/// when P is at the light's position (no direction).
inline bool povDirectionToLight(const Light& light, Vec3 P, Vec3& L) {
    const Vec3 d = light.parallel ? -light.direction : light.position - P;
    const double dist = length(d);
    if (dist == 0) return false;
    L = d / dist;
    return true;
}

/// What one light adds at a surface point: diffuse (to be weighted by the surface's opacity) and
/// highlights (phong + specular, never weighted by it).
struct PovLightTerms {
    Vec3 diffuse;
    Vec3 highlight;
};

/// Light from one light of colour lightColor (already tinted and dimmed by what lies between) on a
/// surface of pigment C. N faces the viewer; L (towards the light) and V (towards the viewer) are
/// unit. Light in front (N·L > 0): diffuse·(N·L)^brilliance·C·Lc plus phong·(R·V)^phong_size·Lc
/// (R = L mirrored about N) and specular·(N·H)^(1/roughness)·Lc (H = normalize(L + V)), the
/// highlights tinted by metallic (povMetallicTint). Light from behind: with double_illuminate the
/// same with |N·L|; otherwise the second diffuse value, diffuseBack·|N·L|^brilliance·C·Lc, alone.
PovLightTerms povLightTerms(const PovSurface& s, Vec3 C, Vec3 N, Vec3 L, Vec3 V, Vec3 lightColor);

/// Ambient and emission of a surface of pigment C: (ambient·ambientLight + emission)·C.
Vec3 povAmbient(const PovFinish& f, Vec3 C, Vec3 ambientLight);

/// Share of the surface's own colour (ambient, emission, diffuse) for pigment C with filter and
/// transmit: 1 − filter − transmit; in legacy scenes (#version below 3.7) 1 − (filter·max(C) + transmit).
double povOpacity(Vec3 C, double filter, double transmit, double version);

/// Whether light can pass a surface at all: its pigment (or some colour of its pattern) filters
/// or transmits.
inline bool povLetsLightThrough(const Material& m, const PovSurface& s) {
    return m.filter != 0 || s.transmit != 0 || s.pigmentTransparent;
}

/// Whether shading gathers photons on the surface: it collects them (`collect`), and is not a
/// clear one that refracts them (photons are not kept where they refract: render/tracer_photons.cpp).
inline bool povGathersPhotons(const PovSurface& s, const Material& m) {
    return s.photons.collect && !(s.photons.refraction && povLetsLightThrough(m, s));
}

/// How a surface tints the light that passes through it: filter·C + transmit, per channel.
inline Vec3 povFilterTint(Vec3 C, double filter, double transmit) { return filter * C + Vec3(transmit); }

/// The empirical curve behind `metallic` (measured: docs/povray-lighting.md): 0 at normal incidence
/// rising to 1 at grazing angles, F(x) = 0.014567225/(x − 1.12)² − 0.011612903 clamped to [0, 1],
/// with x = acos(cosAngle)/(π/2).
double povMetallicCurve(double cosAngle);

/// Colour factor of metallic: 1 + amount·(1 − F)·(C − 1), F = povMetallicCurve(cosAngle) (1 when
/// amount is 0: the light's own colour).
Vec3 povMetallicTint(double amount, Vec3 C, double cosAngle);

/// Unpolarised Fresnel reflectance of a dielectric interface (exact, not Schlick) for the cosine
/// of the incidence angle and eta = n_incident / n_transmitted; 1 under total internal reflection.
double fresnelReflectance(double cosIncidence, double eta);

/// Reflectivity of a surface of pigment C seen at cosView = N·V (> 0): `reflection C` as given;
/// variable reflection min + (max − min)·(1 − cosView)^falloff; with fresnel min + (max − min)·F
/// (F from the interior's ior; eta as for fresnelReflectance); then tinted by the reflection's
/// metallic (povMetallicTint at cosView).
Vec3 povReflectivity(const PovSurface& s, Vec3 C, double cosView, double eta);

/// The mirror direction for a ray of direction d at a surface whose normal pattern tilts the normal
/// Nfacing (the shape's, facing the viewer) to N. POV-Ray 3.7 keeps the reflected ray on the viewer's
/// side: where the tilted normal faces away from the ray it mirrors about Nfacing; where the ray
/// mirrored about N would go into the surface it is mirrored back about the surface's plane
/// (measured: a mirror plane with `normal { gradient z }` seen at grazing angles, the reflected
/// direction read from a sky coloured by direction; docs/povray-lighting.md).
Vec3 povMirrorDirection(Vec3 d, Vec3 N, Vec3 Nfacing);

/// The reflected colour as the reflection's exponent shapes it: c^(1/exponent) per channel.
Vec3 povReflectionExponent(Vec3 reflected, double exponent);

/// Transmittance of a ray's path of length distance inside an interior: without fading
/// (fade_distance 0) 1; fade_power ≥ 1000: exp(−(1 − fade_color)·distance/fade_distance);
/// otherwise a + (1 − a)·fade_color with a = 1/(1 + (distance/fade_distance)^fade_power).
/// An infinite distance gives fade_color (or 0).
Vec3 povFade(const PovInterior& in, double distance);

/// True when the interior fades light at all (fade_distance > 0).
inline bool povFades(const PovInterior& in) { return in.fadeDistance > 0; }

/// Share of a spotlight's or cylindrical light's light that reaches a point at toPoint from the
/// light's position (1 for other lights). Spotlight, with c the cosine between direction and
/// toPoint: 1 within the radius cone, 0 beyond the falloff cone, 3s² − 2s³ between them with
/// s = (c − cos falloff)/(cos radius − cos falloff); times c^tightness. Cylinder, with r the
/// distance from the axis: 1 within radius, 0 beyond falloff, the same curve over (falloff − r)/
/// (falloff − radius) between; times (1 − r/falloff)^tightness. Measured with povray 3.7
/// (docs/povray-lighting.md).
double povSpotFactor(const Light& light, Vec3 toPoint);

/// Light fading at a distance from the light: 2/(1 + (distance/fade_distance)^fade_power), 1
/// without fade_distance (the manual, "Light Fading"; measured).
double povLightFade(const Light& light, double distance);

/// POV-Ray's iridescence (POV-Ray 3.7 reference, "Iridescence": thin-film interference, a
/// function of the angle between the light and the surface, `amount` its contribution, the
/// film's `thickness`, varied by `turbulence`): the factor a light's colour is multiplied by at
/// world point P for diffuse and highlights alike (ambient is not touched). Measured with povray
/// 3.7 on a lit plane: per channel 1 + amount·cos(2π·t·(N·L + N·V)/λ), λ the irid_wavelength
/// (N·L and N·V enter alike: turning the camera or the light gives the same colour), and the
/// turbulence scales the thickness, t = thickness·(1 + turbulence·Y), Y turbulence noise of mean 1.
Vec3 povIridTint(const PovFinish& f, Vec3 wavelength, Vec3 N, Vec3 L, Vec3 V, Vec3 P);

/// POV-Ray's fake caustics (POV-Ray 3.7 reference, "Faked Caustics": the light reaching a point
/// through a transparent object is brightened where the light ray runs nearly along the
/// object's surface normal, less as the angle grows): the light is multiplied by
/// 1 + |N·L|^(45·caustics) at each surface of the object the shadow ray crosses (measured with
/// povray 3.7 through a tilted pane: ×4 along the normal, ×(1 + cos^45) per face at caustics 1,
/// the exponent proportional to the power; filter and transmit as without caustics).
inline double povCausticGain(double caustics, double cosine) {
    return caustics > 0 ? 1 + std::pow(std::fabs(cosine), 45 * caustics) : 1.0;
}

/// The colour behind a ray segment from ray.origin to ray.at(t) (t may be infinite; ray.dir
/// unit) seen through the fogs: each keeps a·(1 − filter + filter·color) of it and adds
/// (1 − a)·color, a as PovFog says (measured: several fogs multiply their shares and add their
/// colours).
Vec3 povFog(const std::vector<PovFog>& fogs, Vec3 behind, const Ray& ray, double t);

/// What the fogs leave of a light with `media_attenuation on` along a shadow ray from ray.origin
/// to ray.at(t): each keeps a·(1 − filter + filter·color), a as for povFog (measured with POV-Ray
/// 3.7 on a lit plane: exp(−d/distance) of constant and ground fogs alike, transmit a floor
/// under it; the fog's colour adds no light).
Vec3 povFogLightTransmittance(const std::vector<PovFog>& fogs, const Ray& ray, double t);

}  // namespace rays
