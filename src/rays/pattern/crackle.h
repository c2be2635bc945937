// crackle (POV-Ray 3.7 reference, "Crackle Patterns"): a Voronoi pattern over seed points, its value
// form.x·d1 + form.y·d2 + form.z·d3 from the distances to the three nearest seeds, clamped to
// [0, 1]; `metric` picks the distance ((|dx|^m + |dy|^m + |dz|^m + offset^m)^(1/m), `offset` acting
// as a fourth coordinate), `solid` gives each cell one value instead.
// POV-Ray does not publish where its seeds are. Its values over 4,000 random points (povray
// 3.7.0.10, `function { pattern { crackle ... } }` printed with #debug) have the statistics of one
// seed placed uniformly at random in each unit cube: d1, d2, d3 means 0.52, 0.71, 0.84 (0.52,
// 0.71, 0.84 for such seeds), the default form 0.193 ± 0.154 (0.194 ± 0.159), metric 1, 3 and 4
// and offset alike, and solid cells 0.51 ± 0.12, about the spread of its noise (bozo 0.51 ± 0.13).
// Rays places its seeds so, from a hash of the cube (cell_hash.h): the look is POV-Ray's, the cells
// are not at the same places.
#pragma once
#include <cstdint>

#include "rays/math/vec3.h"

namespace rays::pattern {

/// crackle's modifiers (defaults as the reference gives them).
struct Crackle {
    Vec3 form{-1, 1, 0};
    double metric = 2;
    double offset = 0;
    bool solid = false;
};

/// The seed of the unit cube (i, j, k): a point uniform in the cube, from one hash of it.
Vec3 crackleSeed(int64_t i, int64_t j, int64_t k);
/// The pattern's value at p.
double crackleValue(Vec3 p, const Crackle& c);

}  // namespace rays::pattern
