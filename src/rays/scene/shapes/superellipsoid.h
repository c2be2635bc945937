// POV-Ray's superellipsoid (reference 3.4.5.1.14, "Superquadric Ellipsoid"): Barr's superquadric
// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1 in the box <-1,-1,-1>–<1,1,1>, with the east-west
// exponent e in Object::r0 and the north-south one n in r1 (inside where the left side is < 1).
#pragma once
#include "rays/scene/object.h"

namespace rays {

/// Nearest hit of the object-space ray with t in (tMin, tMax): t and the outward normal.
bool hitSuperellipsoid(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is strictly inside.
bool insideSuperellipsoid(const Object& o, Vec3 p);

}  // namespace rays
