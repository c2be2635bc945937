// Stencil taps decided from the pixel records around them instead of by tracing a ray, where the
// local geometry is simple enough to be sure: the four records around a tap lie on one surface
// and differ only by a crease (two facets) or only by the number of lights blocked (one facet).
// Each facet is taken as the tangent plane of a record (its hit point and facing normal); for
// flat facets this is exact, on curved surfaces the planes are those of the nearest samples, a
// fraction of a pixel from the tap. Rays that graze a plane are left to the tracer.
#pragma once
#include <cmath>

#include "rays/geometry/ray.h"
#include "rays/npr/edge_classify.h"

namespace rays {

/// Distance along r to the tangent plane of record e, or a negative value when r grazes the
/// plane (|cos| below 0.05) or meets it behind its origin.
inline double tangentPlaneT(const Ray& r, const EdgeRecord& e) {
    const Vec3 n = e.normal();
    const double cosine = dot(r.dir, n);
    if (std::fabs(cosine) < 0.05 * length(r.dir)) return -1;
    return dot(e.point() - r.origin, n) / cosine;
}

/// Which of two facets meeting at a crease the ray r sees: 0 for the facet of record a, 1 for
/// that of b, −1 when the planes do not decide it (grazing, nearly coplanar, behind the eye).
/// Seen from the front, a convex crease (b behind a's plane) shows the farther of the two plane
/// hits, a concave one the nearer.
inline int creaseSide(const Ray& r, const EdgeRecord& a, const EdgeRecord& b) {
    const double ta = tangentPlaneT(r, a), tb = tangentPlaneT(r, b);
    if (ta <= 0 || tb <= 0) return -1;
    const Vec3 na = a.normal();
    const Vec3 ab{b.p[0] - a.p[0], b.p[1] - a.p[1], b.p[2] - a.p[2]};
    const double side = dot(ab, na);
    if (std::fabs(side) <= 1e-3 * length(ab)) return -1;
    const bool convex = side < 0;
    return (convex ? tb > ta : tb < ta) ? 1 : 0;
}

}  // namespace rays
