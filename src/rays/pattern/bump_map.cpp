#include "rays/pattern/bump_map.h"

#include <cmath>

namespace rays::pattern {

namespace {

// The tangent directions (T1, T2) at unit normal n: the texture's y projected into the tangent
// plane, and n × T2 (measured, bump_map.h). A normal along y takes the texture's x instead.
void tangents(Vec3 n, Vec3& t1, Vec3& t2) {
    Vec3 y = Vec3{0, 1, 0} - n.y * n;
    if (length(y) < 1e-9) {
        const Vec3 x = Vec3{1, 0, 0} - n.x * n;
        t1 = x / length(x);
        t2 = cross(t1, n);
        return;
    }
    t2 = y / length(y);
    t1 = cross(n, t2);
}

}  // namespace

Vec3 bumpMapNormal(const ImageMap& m, Vec3 q, Vec3 n, double bumpSize) {
    if (!m.image || m.image->width <= 0 || m.image->height <= 0) return n;
    double u = 0, v = 0;
    if (!m.coordinates(q, u, v)) return n;
    const double du = 1.0 / m.image->width, dv = 1.0 / m.image->height;
    const double c = m.valueAt(u, v), l = m.valueAt(u - du, v - dv), r = m.valueAt(u + du, v - dv);
    const double tx = bumpSize * (l - r) / 2, ty = bumpSize * ((l + r) / 2 - c);
    if (tx == 0 && ty == 0) return n;
    Vec3 t1, t2;
    tangents(n, t1, t2);
    const Vec3 out = n + tx * t1 + ty * t2;
    const double len = length(out);
    return len > 0 ? out / len : n;
}

}  // namespace rays::pattern
