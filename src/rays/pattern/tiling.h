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

/// True for the tiling numbers drawn here: 1 to 12, 15 to 21, 23 and 24. Not drawn: 13 and 14
/// (tiles whose bevel lines do not follow the distance to their edges), 22 (3.12.12, whose
/// dodecagons' bevel near their triangles is not the distance to their edges either) and the
/// Penrose tilings 25 to 27.
bool tilingDrawn(int number);

/// The value of `tiling number` at p (y is ignored), in [0, 1]; 0 for a tiling not drawn.
double tilingValue(int number, Vec3 p);

}  // namespace rays::pattern
