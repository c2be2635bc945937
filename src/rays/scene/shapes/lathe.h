// POV-Ray's lathe (reference 3.4.5.1.8): a curve of 2-D points <x, y> rotated about the y axis.
// Segments, from the spline type: linear_spline P(i) → P(i+1); quadratic_spline the parabola
// through P(i), P(i+1), P(i+2) at parameters −1, 0, 1, drawn from P(i+1) to P(i+2);
// cubic_spline Catmull-Rom from P(i+1) to P(i+2) (slopes (P(i+2) − P(i))/2 and
// (P(i+3) − P(i+1))/2); bezier_spline four points per segment. (The quadratic and cubic forms
// as measured with POV-Ray 3.7's trace().) data->values holds per segment x(s) and y(s) as
// cubics in s ∈ [0, 1] (x0..x3, y0..y3); Object::r0 is +1 when the curve, closed through the axis,
// turns counter-clockwise in the x-y plane (its outward side is then to the right of its
// direction), −1 otherwise; data->bounds the box.
#pragma once
#include <vector>

#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays {

/// Lathe spline types.
enum class LatheSpline { Linear, Quadratic, Cubic, Bezier };

/// The segments from the points (x, y); false when there are too few points for the spline.
bool makeLathe(const std::vector<Vec3>& points, LatheSpline spline, Object& o, ShapeData& data);
/// Nearest hit of the object-space ray with t in (tMin, tMax): t and the outward normal.
bool hitLathe(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is strictly inside the curve rotated (even-odd rule).
bool insideLathe(const Object& o, Vec3 p);

}  // namespace rays
