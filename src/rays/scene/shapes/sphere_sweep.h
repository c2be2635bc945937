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
/// Nearest hit of the object-space ray with t in (tMin, tMax) on the surface of the union of
/// the segments: t and the outward normal.
bool hitSphereSweep(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is strictly inside a segment.
bool insideSphereSweep(const Object& o, Vec3 p);

}  // namespace rays
