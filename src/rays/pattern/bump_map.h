// POV-Ray's bump_map normal (POV-Ray 3.7 reference, "Bump Map"): an image's brightness (or palette
// index with use_index) as heights over the image map's unit square, tilting the normal. The
// scheme, measured with POV-Ray 3.7 on a lit plane with 5 × 5 images holding one bright texel
// (tests/pov_normal_test.cpp, BumpMap*): three heights, at the point c and one texel down the image
// and one to either side, l = h(u − 1/W, v − 1/H) and r = h(u + 1/W, v − 1/H), each interpolated as
// the image map's texels are; the tilt is bump_size·(l − r)/2 along the texture's x and
// bump_size·((l + r)/2 − c) along its y, in texel steps (the image's size and the normal's scale
// do not change it). The two directions are the tangent plane's: T2 the texture's y projected
// into the plane, T1 = n × T2 (measured on planes tilted about x, y and both).
#pragma once
#include "rays/math/vec3.h"
#include "rays/pattern/image_map.h"

namespace rays::pattern {

/// The unit normal of the bump map `m` at q (its pattern space) for the unit surface normal n there
/// (facing the viewer). Outside a `once` image the normal is n.
Vec3 bumpMapNormal(const ImageMap& m, Vec3 q, Vec3 n, double bumpSize);

}  // namespace rays::pattern
