// POV-Ray 3.7's subsurface light transport (the reference manual's "Subsurface Light Transport":
// global_settings { mm_per_unit F subsurface { samples N, M radiosity B } } and a finish's
// subsurface { translucency C }). How Rays renders it: render/pov_subsurface.h.
#pragma once

namespace rays {

/// The most samples one point's subsurface light takes (samples' first number is clamped to it).
inline constexpr int kMaxSubsurfaceSamples = 10000;

/// global_settings' subsurface block and mm_per_unit.
struct PovSubsurfaceSettings {
    /// A subsurface block was given: finishes with a subsurface block then light by it (without
    /// the block POV-Ray 3.7 lights them as plain finishes: measured).
    bool enabled = false;
    double mmPerUnit = 10;    ///< millimetres per scene unit (translucency is in millimetres)
    int samples = 50;         ///< samples of the diffuse (multiple) scattering per shaded point
    int singleSamples = 50;   ///< samples of single scattering (read; not rendered: docs/povray-lighting.md)
    bool radiosity = false;   ///< radiosity's light scattered below the surface too (read; not rendered)
};

}  // namespace rays
