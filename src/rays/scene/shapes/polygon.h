// POV-Ray's polygon (reference 3.4.5.2.5): one or more sub-polygons in one plane, each closed by
// repeating its first point; a point is on the polygon when it is inside an odd number of them
// (even-odd rule). Object::p0 the plane's unit normal, r0 its distance (n·x = d), p1 and p2 an
// orthonormal in-plane basis; data->values the edges in that basis as (x0, y0, x1, y1) groups,
// data->bounds the object-space box of the points. A flat patch: no inside.
#pragma once
#include <vector>

#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays {

/// The polygon's data from its points (as written; 2-D points have z = 0) and the plane fields
/// of o; false when the points span no plane (fewer than three, or all on one line).
bool makePolygon(const std::vector<Vec3>& points, Object& o, ShapeData& data);
/// Nearest hit of the ray (object space) with t in (tMin, tMax): t and the normal p0.
bool hitPolygon(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);

}  // namespace rays
