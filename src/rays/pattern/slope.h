// The slope pattern (POV-Ray 3.7 reference, "Slope"): a value from the angle between the surface
// normal and a direction, optionally mixed with the altitude of the point along a second vector.
// The only pattern that reads the surface normal; without a surface (a zero normal) the slope part
// is that of a normal perpendicular to the direction (0.5).
#pragma once
#include "rays/math/vec3.h"

namespace rays::pattern {

/// slope { <Direction> [, Lo_slope, Hi_slope] [altitude <Altitude> [, Lo_alt, Hi_alt]] }
struct Slope {
    Vec3 direction{0, 1, 0};  ///< unit
    double lo = 0, hi = 1;    ///< the slope values that give 0 and 1
    Vec3 altitude{0, 0, 0};   ///< unit; zero: no altitude part
    double loAlt = 0, hiAlt = 1;  ///< the altitudes that give 0 and 1
    double slopeWeight = 1;  ///< |Direction| / (|Direction| + |Altitude|); 1 without altitude
};

/// The documented rule, as measured with POV-Ray 3.7 on probe scenes: the slope is
/// 1 − angle(N, Direction)/π (1 along the direction, 0.5 across it, 0 against it), rescaled by
/// (s − Lo_slope)/(Hi_slope − Lo_slope); the altitude is p·Altitude/|Altitude| rescaled by
/// (a − Lo_alt)/(Hi_alt − Lo_alt); the two are weighed by their vectors' lengths. Nothing is
/// clamped: the wave wraps values outside [0, 1]. N is the (perturbed) world normal facing the
/// viewer, p the point in pattern space.
double slopeValue(const Slope& s, Vec3 p, Vec3 N);

/// Reads the lengths and ranges into a Slope (zero-length direction: straight up).
Slope makeSlope(Vec3 direction, double lo, double hi, Vec3 altitude, double loAlt, double hiAlt);

}  // namespace rays::pattern
