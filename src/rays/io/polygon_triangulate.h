// Triangulation of one OBJ polygon (a face of more than three corners) in O(n log n) time for any
// input, linear for ordinary shapes: ear clipping over a linked ring, with the test "does a reflex
// corner lie in this ear?" answered by a uniform grid of the reflex corners (Eberly, "Triangulation
// by Ear Clipping", 2002, for the method; the grid replaces its linear scan), and for the polygons it
// finds hard the sweep into monotone pieces of polygon_monotone.h.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "rays/math/vec3.h"

namespace rays {

/// Triangles covering the polygon `corners` (in order, as written in the file), each a triple of
/// indices into `corners` in the polygon's own winding; corners.size() − 2 triangles for 3 or more
/// corners, none for fewer. Triangles stay triangles; quads are split along the shorter diagonal
/// (as tinyobjloader splits them); a larger convex polygon becomes the fan from corner 0 (as
/// tinyobjloader's ear walk gives it); any other is ear-clipped in the plane its Newell normal
/// picks, walking on from each ear cut, for at most 32 steps a corner (O(n) for ordinary polygons:
/// the grid keeps the reflex-corner test near constant). Past that budget the sweep of
/// triangulateMonotone triangulates it afresh in O(n log n). A polygon with no ear left
/// (self-intersecting, degenerate), or one past the budget that the sweep cannot triangulate either,
/// has its remaining corners fanned; so does one with non-finite or huge (≥ 1e100) coordinates.
/// `work`, when given, receives the steps taken (ear candidates tried, grid cells visited and
/// corners looked at in them; the sweep's comparisons and steps): the measure of the time, which
/// tests bound.
std::vector<std::array<int, 3>> triangulatePolygon(std::span<const Vec3> corners, uint64_t* work = nullptr);

}  // namespace rays
