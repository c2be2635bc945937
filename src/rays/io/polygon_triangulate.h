// Triangulation of one OBJ polygon (a face of more than three corners) in time linear in its
// corners for ordinary shapes: ear clipping over a linked ring, with the test "does a reflex
// corner lie in this ear?" answered by a uniform grid of the reflex corners (Eberly, "Triangulation
// by Ear Clipping", 2002, for the method; the grid replaces its linear scan).
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
/// picks, walking on from each ear cut. A polygon with
/// no ear left (self-intersecting, degenerate) has its remaining corners fanned. O(n) expected for
/// ordinary polygons; the grid keeps the reflex-corner test near constant.
/// `work`, when given, receives the steps taken (ear candidates tried, grid cells visited and
/// corners looked at in them): the measure of the time, which tests bound by a multiple of the corner count.
std::vector<std::array<int, 3>> triangulatePolygon(std::span<const Vec3> corners, uint64_t* work = nullptr);

}  // namespace rays
