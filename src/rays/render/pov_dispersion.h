// POV-Ray's dispersion (reference 3.4.8.1.3, "Dispersion"): a ray refracted into an interior with
// `dispersion D` is split into `dispersion_samples` N rays, each a band of the spectrum from red to
// violet with its own index of refraction and its own share of the colour. Measured with POV-Ray
// 3.7 (16-bit linear renders of a white/black edge seen through a tilted slab of ior 1.5, D 1.2,
// N = 2, 3, 4, 7, 24, 40 and 96: each sample's edge moves by its ior, and the colours across the
// edge add up band by band): sample i of N covers u ∈ [i/N, (i + 1)/N] (u = 0 red, 1 violet), its
// index is ior·D^((i + ½)/N − ½), and its colour is F((i + 1)/N) − F(i/N), F the cumulative
// spectrum measured at u = k/96 (the same at every N: N = 2's first half equals N = 4's first two
// quarters and N = 96's first 48 bands to the 16-bit step). F(1) is nearly white.
#pragma once
#include "rays/math/vec3.h"

namespace rays {

/// F(u) for u in [0, 1], linear between the measured points.
Vec3 povSpectrumUpTo(double u);
/// The colour share of dispersion sample i of n.
inline Vec3 povDispersionColor(int i, int n) { return povSpectrumUpTo(double(i + 1) / n) - povSpectrumUpTo(double(i) / n); }
/// The exponent of D in sample i of n's index: (i + ½)/n − ½.
inline double povDispersionExponent(int i, int n) { return (i + 0.5) / n - 0.5; }

}  // namespace rays
