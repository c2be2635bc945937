// POV-Ray's height_field (reference 3.4.5.1.5): a grid of heights over the unit square x, z in
// [0, 1], height y in [0, 1]; each cell of four neighbouring samples is two triangles. Hits walk
// the cells the ray crosses (2D DDA, Amanatides & Woo 1987) inside the bounding box, testing a
// cell's triangles only where the ray's height range meets the cell's. ShapeData::values holds
// nx, nz, water_level, then the nx·nz heights, row iz = 0 (z = 0) first; Object::smooth
// interpolates vertex normals.
#pragma once
#include <vector>

#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays {

/// Fills data for a height field of nx × nz samples (heights[iz·nx + ix] at x = ix/(nx−1),
/// z = iz/(nz−1)), parts below waterLevel left out; false (no shape) with fewer than 2×2 samples.
bool makeHeightField(int nx, int nz, const std::vector<double>& heights, double waterLevel, ShapeData& data);
/// Nearest hit of the object-space ray with t in (tMin, tMax): t and the upward-facing normal.
bool hitHeightField(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is below the surface, inside the unit square.
bool insideHeightField(const Object& o, Vec3 p);

}  // namespace rays
