// POV-Ray's ovus (reference 3.4.5.1.10 "Ovus"): an egg from a bottom sphere (centre the origin,
// radius Object::r0) and a top sphere (centre <0, r0, 0>, radius r1) joined by a spindle torus's
// inner part (a "lemon"). The reference leaves the join's size open; measured with POV-Ray
// 3.7.0.10's trace() and min/max_extent: the torus's tube radius is ρ = 2·max(r0, r1), its tube
// circle (in the profile half-plane, centre (−a, yc)) touches both spheres from outside them, and
// each sphere is the surface beyond its touching point; with r1 ≥ 2·r0 the top sphere holds the
// bottom one and the ovus is that sphere. data->values: a, yc, ρ, the touching heights yb and yt,
// and 1 when only the top sphere is left; data->bounds the box.
#pragma once
#include "rays/scene/object.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays {

/// Fills data from the radii (o.r0, o.r1); false when a radius is not above 0.
bool makeOvus(const Object& o, ShapeData& data);
/// Nearest hit of the object-space ray with t in (tMin, tMax): t and the outward normal.
bool hitOvus(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h);
/// Whether object-space point p is strictly inside.
bool insideOvus(const Object& o, Vec3 p);

}  // namespace rays
