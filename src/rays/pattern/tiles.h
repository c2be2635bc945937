// POV-Ray 3.7's block patterns square, triangular and cubic (POV-Ray 3.7 reference, "Square",
// "Triangular", "Cubic"): the index of the list entry (colour, pigment, normal or texture) at a
// point. The layouts and colour orders were measured with POV-Ray 3.7's pattern functions
// (tests/pov_pattern_test.cpp, TilingBlockPatternsMatchPovRay).
#pragma once
#include "rays/math/vec3.h"

namespace rays::pattern {

/// square: unit squares in the x-z plane, four entries in 2×2 blocks: 0 where floor(x) and floor(z)
/// are both even, 3 for odd x, 1 for odd z, 2 for both odd.
int squareIndex(Vec3 p);

/// triangular: equilateral triangles of side 1 in the x-z plane, rows √3/2 deep, a base on the
/// x-axis from 0 to 1 (entry 0); six entries, each row's run of triangles repeating every three
/// units, odd rows shifted half a unit.
int triangularIndex(Vec3 p);

/// cubic: the six pyramids about the origin by the largest coordinate: +x 0, +y 1, +z 2, −x 3,
/// −y 4, −z 5 (not repeated).
int cubicIndex(Vec3 p);

}  // namespace rays::pattern
