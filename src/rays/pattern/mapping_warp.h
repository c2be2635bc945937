// The mapping warps planar, cylindrical, spherical, toroidal and cubic (POV-Ray 3.7 reference,
// "Mapping using warps"): they wrap the x-y plane of a pattern onto a plane, a cylinder, a sphere,
// a torus or a cube. Each computes map coordinates c of the point and hands out M(o)·c, o the warp's orientation (default
// z) or the planar warp's normal. All measured with POV-Ray 3.7's pattern functions
// (`function { pattern { function { x } warp { ... } } }` at scattered points):
//   planar <n>, d:   c = (x, y, d)                         (default n = z, d = 0)
//   cylindrical:     c = (u·r^e, y, r)                     r = √(x² + z²)
//   spherical:       c = (u·r^e, v·r^e, r)                 r = |p|
//   toroidal:        c = (u·r^e, w·r^e, r)                 r = √((ρ − R)² + y²), ρ = √(x² + z²)
//   cubic:           c = (face u, face v, max(|x|, |y|, |z|))
// with u = atan2(z, x)/2π wrapped into [0, 1), v = asin(y/r)/π + 1/2, w = atan2(y, ρ − R)/2π + 1/2
// wrapped into [0, 1) (the angle round the tube of major_radius R, default 1) and e the dist_exp
// (default 0). The cubic warp unfolds the cube as a cross: with a = max(|x|, |y|, |z|), the faces
// −x, +z, +x, −z side by side in u (quarters centred at 1/8, 3/8, 5/8, 7/8, half width 1/8) and the
// middle third in v (v = 1/2 + y/6a), +y above and −y below the +z face; a point on an edge or
// corner takes the first face of +x, +z, +y, −x, −y, −z that it lies on (all measured; cubeMap in
// mapping_warp.cpp has each face's formula); it has no orientation in POV-Ray's grammar.
// M(o), o normalised, is the measured orientation matrix
//   [[oy + oz, 0, ox], [0, ox + oz, −oy], [−ox, oy, oz]]
// (the identity for z; for y it takes (c0, c1, c2) to (c0, −c2, c1), for x to (c2, c1, −c0); it is
// not a rotation for other directions, as POV-Ray's results show).
#pragma once
#include "rays/math/vec3.h"

namespace rays::pattern {

enum class MappingKind : unsigned char { Planar, Cylindrical, Spherical, Toroidal, Cubic };

struct MappingWarp {
    MappingKind kind = MappingKind::Planar;
    Vec3 orientation{0, 0, 1};  ///< unit: the planar warp's normal, the others' orientation
    double distance = 0;        ///< planar: the plane's distance
    double distExp = 0;         ///< cylindrical, spherical and toroidal: dist_exp
    double majorRadius = 1;     ///< toroidal: major_radius
};

/// p (the space enclosing the warp) moved into the space inside it.
Vec3 applyMappingWarp(const MappingWarp& w, Vec3 p);

}  // namespace rays::pattern
