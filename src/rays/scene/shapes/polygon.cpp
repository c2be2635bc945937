#include "rays/scene/shapes/polygon.h"

#include <cmath>

namespace rays {

bool makePolygon(const std::vector<Vec3>& pts, Object& o, ShapeData& data) {
    if (pts.size() < 3) return false;
    // Newell's method (Sutherland et al. 1974): the normal of a planar polygon from all its points.
    Vec3 n;
    for (size_t i = 0; i < pts.size(); ++i) {
        const Vec3 a = pts[i], b = pts[(i + 1) % pts.size()];
        n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    }
    if (length(n) == 0) {  // e.g. sub-polygons cancelling out: take any two independent edges
        for (size_t i = 2; i < pts.size() && length(n) == 0; ++i) n = cross(pts[1] - pts[0], pts[i] - pts[0]);
        if (length(n) == 0) return false;
    }
    n = normalize(n);
    o.p0 = n;
    o.r0 = dot(n, pts[0]);
    const Vec3 helper = std::fabs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    o.p1 = normalize(cross(helper, n));
    o.p2 = cross(n, o.p1);
    auto add = [&](Vec3 a, Vec3 b) {
        data.values.insert(data.values.end(), {dot(a, o.p1), dot(a, o.p2), dot(b, o.p1), dot(b, o.p2)});
    };
    // Sub-polygons: a point equal to the current sub-polygon's first point closes it; an
    // unclosed last one is closed.
    size_t start = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        data.bounds.extend(pts[i]);
        if (i > start && pts[i] == pts[start]) {
            for (size_t k = start; k < i; ++k) add(pts[k], pts[k + 1]);
            start = i + 1;
        }
    }
    if (pts.size() - start >= 2) {
        for (size_t k = start; k + 1 < pts.size(); ++k) add(pts[k], pts[k + 1]);
        add(pts.back(), pts[start]);
    }
    return !data.values.empty();
}

bool hitPolygon(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const double denom = dot(o.p0, r.dir);
    if (denom == 0) return false;
    const double t = (o.r0 - dot(o.p0, r.origin)) / denom;
    if (!(t > tMin && t < tMax)) return false;
    const Vec3 p = r.at(t);
    const double px = dot(p, o.p1), py = dot(p, o.p2);
    // Even-odd rule by crossings of the ray from p along +x (Shimrat 1962, Haines 1994).
    bool in = false;
    const std::vector<double>& e = o.data->values;
    for (size_t i = 0; i + 3 < e.size(); i += 4) {
        const double x0 = e[i], y0 = e[i + 1], x1 = e[i + 2], y1 = e[i + 3];
        if ((y0 > py) != (y1 > py) && px < x0 + (py - y0) * (x1 - x0) / (y1 - y0)) in = !in;
    }
    if (!in) return false;
    h.t = t;
    h.normal = o.p0;
    return true;
}

}  // namespace rays
