// Light sources: point lights (the course), POV-Ray's area lights (a rectangle or disc sampled by an
// n1 × n2 grid of point lights), parallel (directional) lights, spotlights, cylindrical lights,
// shadowless lights and light fading (POV-Ray 3.7 reference, "Light Source").
#pragma once
#include "rays/math/vec3.h"

namespace rays {

struct Light {
    Vec3 position;
    Vec3 color{1, 1, 1};

    // Area light: a rectangle spanned by axis1 and axis2 (full lengths) centred on position,
    // sampled by an n1 × n2 grid: sample (u, v) at position + axis1·(u/(n1−1) − ½) + axis2·(v/(n2−1) − ½).
    bool area = false;
    Vec3 axis1, axis2;
    int n1 = 1, n2 = 1;
    bool jitter = false;    ///< move each sample randomly within its cell
    int adaptive = -1;      ///< ≥ 0: test the four corner samples first; all agreeing decides visibility
    bool circular = false;  ///< the grid is mapped onto the disc (ellipse) inscribed in the rectangle
    bool orient = false;    ///< the light's plane turns to face the shaded point
    bool areaIllumination = false;  ///< POV-Ray's area_illumination: each sample lights from its own place

    // Parallel light: every light ray has direction `direction` (from the light toward point_at).
    bool parallel = false;
    Vec3 pointAt{0, 0, 0};
    Vec3 direction{0, 0, -1};  ///< unit; set by the parser from point_at − position

    // POV-Ray only (render/pov_lighting.h, povSpotFactor and povLightFade):
    enum class Spot : unsigned char { None, Cone, Cylinder };
    /// Cone: a spotlight from position along direction, radius and falloff as cosines of their
    /// half angles. Cylinder: light along direction (parallel is then true) within the distances
    /// radius and falloff of the axis through position. Both sharpened by tightness.
    Spot spot = Spot::None;
    double spotRadius = 0, spotFalloff = 0, tightness = 0;
    bool shadowless = false;  ///< no shadow rays (nothing blocks it) and no highlights
    /// projected_through: Scene::projectors[projectorBegin, + projectorCount); the light reaches
    /// only points whose way to it crosses one of them (none: everywhere).
    int projectorBegin = 0, projectorCount = 0;
    double fadeDistance = 0;  ///< > 0: light fading 2/(1 + (d/fadeDistance)^fadePower)
    double fadePower = 0;
    bool mediaInteraction = true;   ///< lights scattering media (media_interaction)
    bool mediaAttenuation = false;  ///< dimmed by atmospheric media on its way (media_attenuation)
    /// Its photons block (render/tracer_photons.cpp). Without one the light shoots at the targets
    /// that refract or reflect photons, and they do (measured with POV-Ray 3.7); with one, what it
    /// turns on (off by default, the manual's table) and at every target.
    bool photonBlock = false;
    bool photonRefraction = true, photonReflection = true;
    /// The light_group it is in (an index, as PovSurface::lightGroup): it lights that group's
    /// objects only. -1: a light of the scene, lighting every object outside groups and those of
    /// groups with global_lights.
    int lightGroup = -1;
};

}  // namespace rays
