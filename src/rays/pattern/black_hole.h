// The black_hole warp (POV-Ray 3.7 reference, "Black Hole Warp"): points within Radius of the
// hole's centre are pushed away from it (pulled towards it with `inverse`), more near the centre.
// Measured with POV-Ray 3.7's pattern functions: a point at distance d < R from the centre C moves
// to C + (p − C)·(1 ± min(1, strength·(1 − d/R)^falloff)) (falloff 2 and strength 1 by default);
// with `repeat <v>` the holes repeat along each axis with a non-zero component, the centre in the
// cell floor(p/v) at cell·v + R on that axis (the location's component there is not used:
// measured with several locations and radii). POV-Ray's per-hole random displacement
// (`turbulence`) is not reproduced.
#pragma once
#include "rays/math/vec3.h"

namespace rays::pattern {

struct BlackHole {
    Vec3 center;
    double radius = 1;
    double falloff = 2, strength = 1;
    bool inverse = false;
    Vec3 repeat;  ///< zero components: no repeat along that axis
};

/// p (the space enclosing the warp) moved into the space inside it.
Vec3 applyBlackHole(const BlackHole& h, Vec3 p);

}  // namespace rays::pattern
