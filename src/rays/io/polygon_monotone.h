// Triangulation of a simple polygon in O(n log n) time whatever its shape: a plane sweep splits it
// into y-monotone pieces with diagonals, and each piece is triangulated in linear time with a stack
// (de Berg, Cheong, van Kreveld, Overmars, "Computational Geometry", 3rd ed., ch. 3; Garey, Johnson,
// Preparata and Tarjan, "Triangulating a simple polygon", 1978). Used by polygon_triangulate for the
// polygons ear clipping finds hard (long thin spikes: a star of many corners).
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace rays {

/// A polygon corner projected into its plane.
struct PlanePoint {
    double x, y;
};

/// Triangulates the polygon `p` (counter-clockwise, finite coordinates, 3 or more corners) into
/// `out` (cleared first): p.size() − 2 counter-clockwise triangles of indices into p. Returns false,
/// with `out` unspecified, when the result does not check — the triangles must number n − 2 and
/// cover exactly the polygon's area — which happens for input that is not a simple polygon
/// (crossing edges, spikes, repeated corners); the time stays O(n log n) for any input. `work`
/// is increased by the steps taken (comparisons in the sort and the sweep's search tree, events,
/// steps around the pieces): the measure of the time that tests bound.
bool triangulateMonotone(std::span<const PlanePoint> p, std::vector<std::array<int, 3>>& out, uint64_t& work);

}  // namespace rays
