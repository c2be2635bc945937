// POV-Ray 3.7's pavement pattern (POV-Ray 3.7 reference, "Pavement Pattern"): the x-z plane paved
// with one polyform tile of number_of_tiles triangles, squares or hexagons (number_of_sides 3, 4,
// 6), its corners shaped by exterior, interior and form. Its value runs from 0 where the point is at
// least the bevel width inside its tile to 1 on the tile's edge, linearly in the distance; the bevel
// width is the unit triangle's inradius √3/6 for triangles and hexagons, 1/2 for squares. Measured
// with POV-Ray 3.7 (`function { pigment { pavement ... color_map { [0 rgb 0] [1 rgb 1] } } }` sampled
// on grids; tests/pov_tiling_test.cpp).
#pragma once
#include "rays/math/vec3.h"

namespace rays::pattern {

struct Pavement {
    int sides = 3, tiles = 1, pattern = 1;  ///< number_of_sides, number_of_tiles, pattern
    int exterior = 0, interior = 0, form = 0;
};

/// True for the pavements drawn here: single tiles, pairs of triangles or squares (one pattern
/// each), three triangles (trapezoids) and three squares in a row (pattern 1), with the corners
/// whose shape makes a difference there left sharp (exterior 0 for triangles and squares, form 0
/// or 3 for hexagons and several triangles, interior 0 for trapezoids).
bool pavementDrawn(const Pavement& m);

/// The value of the pavement at p (y is ignored), in [0, 1]; 0 for a pavement not drawn.
double pavementValue(const Pavement& m, Vec3 p);

}  // namespace rays::pattern
