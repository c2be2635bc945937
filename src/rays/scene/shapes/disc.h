// POV-Ray's disc (reference 3.4.5.2.2): centre Object::p0, unit normal p1, radius r0, hole radius
// r1 (0: none). Its inside (for CSG) is the half-space of its plane away from the normal, not
// bounded by the radius (reference: "the inside of a disc is the inside of the plane").
#pragma once
#include "rays/scene/object.h"

namespace rays {

/// Nearest hit of the ray (object space) with t in (tMin, tMax): t and the normal p1.
bool hitDisc(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Object-space bounds (exact: the circle's extent along each axis).
Bounds discBounds(const Object& o);

}  // namespace rays
