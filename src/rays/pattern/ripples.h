// ripples, waves and dents as pigment patterns (POV-Ray 3.7 reference, "Ripples", "Waves",
// "Dents", "Number_Of_Waves"), and the wave sources the ripples and waves normals share.
// POV-Ray places its wave sources at random; their centres and frequencies here were measured
// from POV-Ray 3.7's renders (below). Dents is a look-alike on Rays' noise.
#pragma once
#include "rays/math/vec3.h"

namespace rays::pattern {

/// The most wave sources Rays has (global_settings' number_of_waves, POV-Ray's default 10; more
/// are taken as this many).
inline constexpr int kMaxWaves = 10;

/// POV-Ray 3.7's first ten wave centres, all on the unit sphere. Measured: with number_of_waves N
/// (1 to 10) a plane z = 0 and a plane z = 1 coloured by `ripples` (16-bit, linear) over
/// [−4, 4]², each N fitted with the N − 1 centres before it fixed: every fit leaves a residual of
/// 4·10⁻⁶ (the file's 16-bit step), so the formulas below are POV-Ray's values to that step.
inline constexpr Vec3 kWaveCentres[kMaxWaves] = {
    {-0.604378, 0.492048, -0.626590}, {-0.552573, -0.246075, -0.796310}, {-0.444551, 0.623329, 0.643300},
    {0.496586, 0.668948, 0.553092},   {-0.064371, -0.805951, -0.588471}, {0.246191, -0.914557, -0.320899},
    {-0.666089, -0.591878, -0.453878}, {-0.520489, -0.386027, -0.761625}, {0.137949, -0.704642, -0.696023},
    {0.564897, 0.722040, -0.399436}};
/// Each source's frequency in `waves` (ripples runs every source at frequency 1), measured the same
/// way with the centres above.
inline constexpr double kWaveFrequencies[kMaxWaves] = {0.919116, 0.960041, 0.433170, 0.709301, 0.689189,
                                                       0.991445, 0.782973, 0.400667, 0.229672, 0.168513};

/// The sources a pattern sums: its number_of_waves, or 10 where none was filled in.
inline int waveCount(int setting) { return setting > 0 ? setting : kMaxWaves; }

/// 0.5 + (0.5/n)·Σᵢ sin(2π·|p − cᵢ|) over the first n sources (n: number_of_waves, 1 to 10).
double ripplesValue(Vec3 p, int n);
/// 0.5 + (0.2/n)·Σᵢ sin(2π·fᵢ·|p − cᵢ|)/fᵢ over the first n sources.
double wavesValue(Vec3 p, int n);
/// n³, n Rays' noise widened by 1.15 about 0.5 (measured: POV-Ray's dents pigment has median 0.13 and its 90th percentile 0.32, as the
/// cube of its noise).
double dentsValue(Vec3 p);

}  // namespace rays::pattern
