// Solid noise for the noise-based internal functions (f_noise3d, f_noise_generator, f_ridge,
// f_ridged_mf, f_hetero_mf). One small interface so that an exact reproduction of POV-Ray's
// noise can replace this one later: for now it is Perlin's improved gradient noise (Perlin,
// "Improving Noise", SIGGRAPH 2002), not POV-Ray's, so values differ from POV-Ray's.
#pragma once

namespace rays::fn {

/// Gradient noise at (x, y, z) mapped to [0, 1] (0.5 on the integer lattice); continuous,
/// deterministic. `generator` is POV-Ray's noise_generator (1, 2 or 3); all give this noise now.
double noise3d(double x, double y, double z, int generator = 2);

}  // namespace rays::fn
