// POV-Ray 3.7's `tiling N` pattern (POV-Ray 3.7 reference, "Tiling Pattern"): 27 numbered tilings
// of the x-z plane. Each tile has a type t of the tiling's T types; its value runs from t/T where the
// point is at least the bevel width inside the tile to (t + 1)/T on its edges, linearly in the
// distance to the nearest edge. The bevel width is the inradius of the tiling's smallest tile (its
// smallest tiles come to a point). Shapes, placements, type orders and the bevel were measured with
// POV-Ray 3.7 (`function { pigment { tiling N color_map { [0 rgb 0] [1 rgb 1] } } }` sampled on
// grids; tests/pov_tiling_test.cpp).
#pragma once
#include "rays/math/vec3.h"

namespace rays::pattern {

/// True for the tiling numbers drawn here (the periodic ones); false for the others (the Penrose
/// tilings 25 to 27).
bool tilingDrawn(int number);

/// The value of `tiling number` at p (y is ignored), in [0, 1]; 0 for a tiling not drawn.
double tilingValue(int number, Vec3 p);

}  // namespace rays::pattern
