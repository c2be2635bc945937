// The quilted pattern (POV-Ray 3.7 reference, "Quilted"): unit cubes whose value and normal rise
// from each cube's centre towards its faces along a cubic curve shaped by control0 and control1.
// The curve is the one the example scene animations/quilted/plotqlt.pov plots,
// t³ + 3t(1 − t)²·c0 + 3t²(1 − t)·c1; how it is applied in 3D was measured with POV-Ray 3.7.
#pragma once
#include "rays/math/vec3.h"

namespace rays::pattern {

struct Quilt {
    double control0 = 1, control1 = 1;
};

/// The pigment value at p (measured with POV-Ray 3.7's pattern functions, to 1e-8 at scattered
/// points and controls): with d = p − the centre of p's unit cube and B the curve at t = |d|,
/// min(1, |B(|d|)·(|dx| + |dy| + |dz|)·2/(3√3)|).
double quiltedValue(const Quilt& q, Vec3 p);

/// The normal's tilt at p, added to the unit normal in pattern space (times the amount) before it
/// is normalised: B(|d|)·d·2/√3 (measured with POV-Ray 3.7 on a lit plane: the tilt points along d,
/// grows linearly with the amount, and d's part along the normal counts).
Vec3 quiltedTilt(const Quilt& q, Vec3 p);

}  // namespace rays::pattern
