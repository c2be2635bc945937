// POV-Ray's surface of revolution (reference 3.4.5.1.15, "sor"): points <r, h> with rising heights;
// between P(j) and P(j+1) (j = 1 … n − 3, 0-based) the radius² is the cubic in the height with the
// values r² at both ends and the slopes 2r·(r(j+1) − r(j−1))/(h(j+1) − h(j−1)) (and likewise at
// P(j+1)), as POV-Ray 3.7's trace() measures; rotated about the y axis, closed by flat caps at
// the first and last segments' ends unless Object::open. data->values holds per segment
// (h0, h1, a, b, c, d): r² = a + b·w + c·w² + d·w³ with w = y − h0; data->bounds the box.
#pragma once
#include <vector>

#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays {

/// The segments from the points (x = radius, y = height); false when there are fewer than four
/// points or the heights of the second to the last but one do not rise (or the outer ones fall).
bool makeSor(const std::vector<Vec3>& points, ShapeData& data);
/// Nearest hit of the object-space ray with t in (tMin, tMax): t and the outward normal.
bool hitSor(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is strictly inside (the closed solid, also when open).
bool insideSor(const Object& o, Vec3 p);

}  // namespace rays
