// POV-Ray's torus (reference 3.4.5.1.17): centred at the origin in the x-z plane around the y
// axis, major radius Object::r0 (centre of the hole to the middle of the rim), minor radius r1.
#pragma once
#include "rays/scene/object.h"

namespace rays {

/// Nearest hit of the object-space ray with t in (tMin, tMax): t and the outward normal.
bool hitTorus(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is strictly inside the tube.
bool insideTorus(const Object& o, Vec3 p);
/// Object-space bounds.
Bounds torusBounds(const Object& o);

}  // namespace rays
