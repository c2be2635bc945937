// ripples, waves and dents as pigment patterns (POV-Ray 3.7 reference, "Ripples", "Waves",
// "Dents"), and the wave centres the ripples and waves normals share. POV-Ray places its ten
// centres at random in the unit cube and dents on its own noise: these are look-alikes on Rays'
// centres and noise, their value spread matched to POV-Ray's (measured over 400 random points:
// ripples 0.50 ± 0.11, waves 0.48 ± 0.11, dents 0.16 ± 0.11), not POV-Ray's values point for point.
#pragma once
#include "rays/math/vec3.h"

namespace rays::pattern {

/// Ten wave centres in the unit cube for ripples and waves.
inline constexpr Vec3 kWaveCentres[10] = {{0.12, 0.84, 0.37}, {0.71, 0.22, 0.91}, {0.45, 0.58, 0.06},
                                          {0.93, 0.67, 0.49}, {0.28, 0.11, 0.62}, {0.59, 0.95, 0.73},
                                          {0.04, 0.39, 0.18}, {0.81, 0.03, 0.27}, {0.36, 0.76, 0.88},
                                          {0.67, 0.48, 0.55}};

/// 0.5 + 0.0885·Σ sin(2π·|p − cᵢ|): rings of period 1 about each centre (measured: along a line far
/// from the centres POV-Ray's ripples is a sine of period 1 about 0.5; frequency and phase act
/// through the wave, as for other patterns).
double ripplesValue(Vec3 p);
/// 0.476 + 0.107·Σ c·|c|, c = cos(2π·|p − cᵢ|): rounder crests, as the waves normal's heights.
double wavesValue(Vec3 p);
/// n³, n Rays' noise widened by 1.15 about 0.5 (measured: POV-Ray's dents pigment has median 0.13 and its 90th percentile 0.32, as the
/// cube of its noise).
double dentsValue(Vec3 p);

}  // namespace rays::pattern
