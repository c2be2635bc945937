// POV-Ray's sphere_sweep (reference 3.4.5.1.13) with linear_spline: the space a sphere takes
// moving in straight lines from one listed sphere to the next, its radius changing linearly; each
// segment is the convex hull of its two spheres (the spheres and the cone tangent to both).
// data->values holds kSweepStride numbers per segment (see sphere_sweep.cpp); data->bounds the box.
#pragma once
#include <vector>

#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays {

/// The segments from the spheres (centres and radii); false when none has a positive radius.
bool makeSphereSweep(const std::vector<Vec3>& centres, const std::vector<double>& radii, ShapeData& data);
/// A sweep along a b_spline (uniform cubic B-spline: segment i from (P(i) + 4P(i+1) + P(i+2))/6 to
/// (P(i+1) + 4P(i+2) + P(i+3))/6) or a cubic_spline (Catmull-Rom from P(i+1) to P(i+2)), the radii
/// interpolated the same way (as measured with POV-Ray 3.7's trace()). Drawn as a linear sweep
/// through kSplineSweepSamples spheres per segment: the hulls of neighbouring samples approximate the
/// moving sphere's envelope (hits within 2e-4 of POV-Ray's exact envelope on radii of 0.1 to 0.4). False when
/// fewer than 4 spheres are given or none has a positive radius.
bool makeSplineSphereSweep(const std::vector<Vec3>& centres, const std::vector<double>& radii, bool bSpline,
                           ShapeData& data);
constexpr int kSplineSweepSamples = 64;
/// Nearest hit of the object-space ray with t in (tMin, tMax) on the surface of the union of
/// the segments: t and the outward normal.
bool hitSphereSweep(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is strictly inside a segment.
bool insideSphereSweep(const Object& o, Vec3 p);

}  // namespace rays
