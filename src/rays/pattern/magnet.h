// The magnet pattern (POV-Ray 3.7 reference, "Magnet"): fractint's magnet formulas in the x-y
// plane, iterated until the orbit escapes or settles at 1, coloured as mandel is (exterior and
// interior types, pattern.h's escapeColouring).
#pragma once
#include "rays/pattern/pattern.h"

namespace rays::pattern {

/// magnet 1: z → ((z² + c − 1) / (2z + c − 2))²;
/// magnet 2: z → ((z³ + 3(c − 1)z + (c − 1)(c − 2)) / (3z² + 3(c − 2)z + (c − 1)(c − 2) + 1))²
/// (fractint's formulas, as the manual names them). mandel type: z starts at 0, c = x + iy; julia
/// type: z starts at x + iy, c fixed. Measured with POV-Ray 3.7's pattern functions over 200
/// random points of each kind: the orbit stops when |z|² > 10000 or |z − 1|² < 0.0001 (both count
/// as escaped), and interior type 1's smallest |z| leaves out the mandel type's starting 0.
double magnetValue(const PatternParams& m, double x, double y);

}  // namespace rays::pattern
