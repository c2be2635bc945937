// POV-Ray's prism (reference 3.4.5.1.11) with linear_spline and linear_sweep: closed outlines in
// the x-z plane (sub-prisms closed by repeating their first point; where an even number overlap
// there is a hole) swept along y from Object::r0 to r1, with flat caps unless `open`.
// data->values the edges as (x0, z0, x1, z1, s) groups, s = ±1 the side of the outward normal
// (s·(z1 − z0, −(x1 − x0))); data->bounds the object-space box.
#pragma once
#include <vector>

#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays {

/// The prism's edges from its 2-D points (x, z); false when they enclose nothing.
bool makePrism(const std::vector<Vec3>& points, double y0, double y1, ShapeData& data);
/// Nearest hit of the object-space ray with t in (tMin, tMax): t and the outward normal.
bool hitPrism(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is strictly inside (the closed solid, also when open).
bool insidePrism(const Object& o, Vec3 p);

}  // namespace rays
