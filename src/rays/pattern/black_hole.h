// The black_hole warp (POV-Ray 3.7 reference, "Black Hole Warp"): points within Radius of the
// hole's centre are pushed away from it (pulled towards it with `inverse`), more near the centre.
// Measured with POV-Ray 3.7's pattern functions: a point at distance d < R from the centre C moves
// to C + (p − C)·(1 ± min(1, strength·(1 − d/R)^falloff)) (falloff 2 and strength 1 by default);
// with `repeat <v>` the holes repeat along each axis with a non-zero component, the centre in the
// cell floor(p/v) at cell·v + R on that axis (the location's component there is not used:
// measured with several locations and radii). With `turbulence <t>` and `repeat`, each hole moves
// from there by u·t on each repeated axis, u uniform in [0, 1) and drawn per cell (measured over
// 100 holes: offsets between 0 and t, mean t/2, spread t/√12; without `repeat` it does nothing).
// Rays' random numbers are its own (pattern/cell_hash.h), so the holes sit alike, not where
// POV-Ray's do.
#pragma once
#include "rays/math/vec3.h"

namespace rays::pattern {

struct BlackHole {
    Vec3 center;
    double radius = 1;
    double falloff = 2, strength = 1;
    bool inverse = false;
    Vec3 repeat;  ///< zero components: no repeat along that axis
    Vec3 jitter;  ///< `turbulence`: the most each repeated hole moves along each axis
};

/// The centre of the hole that acts on p (with `repeat`, the one of p's cell).
Vec3 blackHoleCentre(const BlackHole& h, Vec3 p);

/// p (the space enclosing the warp) moved into the space inside it.
Vec3 applyBlackHole(const BlackHole& h, Vec3 p);

}  // namespace rays::pattern
