// ripples, waves and dents as pigment patterns (POV-Ray 3.7 reference, "Ripples", "Waves",
// "Dents"), and the wave centres the ripples and waves normals share. POV-Ray places its ten
// centres at random in the unit cube and dents on its own noise: these are look-alikes on Rays'
// centres and noise, their value spread matched to POV-Ray's (measured over 400 random points:
// ripples 0.50 ± 0.11, dents 0.16 ± 0.11; waves over 8,000: 0.50 ± 0.12), not POV-Ray's values
// point for point.
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
/// Each waves centre's own frequency. Measured with POV-Ray 3.7 (the waves pattern along a line far
/// from the centres, 16,384 samples): ten sinusoids of different frequencies between 0.17 and 0.99,
/// each with an amplitude ∝ 1/frequency. These are Rays' own (0.2 to 1, golden-ratio steps).
inline constexpr double kWaveFrequencies[10] = {0.575, 0.250, 0.776, 0.451, 0.976,
                                                0.652, 0.327, 0.852, 0.527, 0.203};
/// 0.5 + 0.02·Σ cos(2π·fᵢ·|p − cᵢ|)/fᵢ (POV-Ray: 0.02 ± 0.002 per 1/fᵢ; 0.501 ± 0.122 over 8,000
/// random points, here 0.50 ± 0.12).
double wavesValue(Vec3 p);
/// n³, n Rays' noise widened by 1.15 about 0.5 (measured: POV-Ray's dents pigment has median 0.13 and its 90th percentile 0.32, as the
/// cube of its noise).
double dentsValue(Vec3 p);

}  // namespace rays::pattern
