// POV-Ray's prism (reference 3.4.5.1.11): closed outlines in the x-z plane (sub-prisms; where an
// even number overlap there is a hole) swept along y from Object::r0 to r1, with flat caps unless
// `open`.
//   linear_spline, linear_sweep: data->values the edges as (x0, z0, x1, z1, s) groups, s = ±1 the
//   side of the outward normal (s·(z1 − z0, −(x1 − x0))).
//   Other splines or conic_sweep (data->conic): data->values the segments as groups of 13: x(u)
//   and z(u) as cubics in u ∈ [0, 1] (x0..x3, z0..z3), s = ±1 the outward side of (z'(u), −x'(u)),
//   and the segment's box xlo, xhi, zlo, zhi. A conic sweep's outline at height y is the outline
//   scaled by y (a point at y = 0, the points as written at y = 1).
// data->bounds the object-space box.
#pragma once
#include <vector>

#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays {

/// How a prism's points are read (the reference's spline types).
enum class PrismSpline { Linear, Quadratic, Cubic, Bezier };

/// The prism's edges from its 2-D points (x, z); false when they enclose nothing.
bool makePrism(const std::vector<Vec3>& points, double y0, double y1, ShapeData& data);
/// A prism of any spline and sweep (linear_spline with linear_sweep is makePrism's) from its 2-D
/// points (x, z), read into closed sub-prisms as the reference says: quadratic — a control point,
/// then the curve's points up to a repeat of the second point; cubic — the same plus one more
/// control point after the repeat; bezier — four points a segment, closed when a segment ends at
/// the sub-prism's first point; linear — as makePrism. An unclosed sub-prism (other than linear's)
/// is left out. False when no segment is left or the heights are empty.
bool makeSplinePrism(const std::vector<Vec3>& points, PrismSpline spline, bool conic, double y0, double y1,
                     ShapeData& data);
/// Nearest hit of the object-space ray with t in (tMin, tMax): t and the outward normal.
bool hitPrism(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is strictly inside (the closed solid, also when open).
bool insidePrism(const Object& o, Vec3 p);

}  // namespace rays
