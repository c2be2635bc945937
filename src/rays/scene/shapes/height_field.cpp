#include "rays/scene/shapes/height_field.h"

#include <algorithm>
#include <cmath>

#include "rays/scene/shapes/box_clip.h"

namespace rays {

namespace {

constexpr size_t kHeader = 3;  // nx, nz, water level

struct Grid {
    int nx = 0, nz = 0;
    double water = 0;
    const double* h = nullptr;
    double at(int ix, int iz) const { return h[size_t(iz) * size_t(nx) + size_t(ix)]; }
    // Object-space corner (ix, iz).
    Vec3 point(int ix, int iz) const { return {double(ix) / (nx - 1), at(ix, iz), double(iz) / (nz - 1)}; }
    // Vertex normal by central differences of the heights (smooth).
    Vec3 vertexNormal(int ix, int iz) const {
        const int x0 = std::max(ix - 1, 0), x1 = std::min(ix + 1, nx - 1);
        const int z0 = std::max(iz - 1, 0), z1 = std::min(iz + 1, nz - 1);
        const double dx = (at(x1, iz) - at(x0, iz)) * (nx - 1) / std::max(1, x1 - x0);
        const double dz = (at(ix, z1) - at(ix, z0)) * (nz - 1) / std::max(1, z1 - z0);
        return normalize(Vec3{-dx, 1, -dz});
    }
};

Grid gridOf(const Object& o) {
    const std::vector<double>& v = o.data->values;
    return {int(v[0]), int(v[1]), v[2], v.data() + kHeader};
}

// Möller–Trumbore: t and barycentrics (b1 toward b, b2 toward c) of the ray's hit with abc.
bool triangleT(const Ray& r, Vec3 a, Vec3 b, Vec3 c, double& t, double& b1, double& b2) {
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 pv = cross(r.dir, e2);
    const double det = dot(e1, pv);
    if (std::fabs(det) < 1e-300) return false;
    const double inv = 1 / det;
    const Vec3 tv = r.origin - a;
    b1 = dot(tv, pv) * inv;
    if (b1 < 0 || b1 > 1) return false;
    const Vec3 qv = cross(tv, e1);
    b2 = dot(r.dir, qv) * inv;
    if (b2 < 0 || b1 + b2 > 1) return false;
    t = dot(e2, qv) * inv;
    return true;
}

// The cell (ix, iz)'s two triangles, split along the diagonal from (ix+1, iz) to (ix, iz+1) as
// POV-Ray 3.7 splits them (measured with trace() on a 2×2 image): the nearest hit in (tMin, tMax)
// above the water level.
bool hitCell(const Grid& g, const Object& o, const Ray& r, int ix, int iz, double tMin, double tMax, ShapeHit& h) {
    const int corners[2][3][2] = {{{ix, iz}, {ix + 1, iz}, {ix, iz + 1}}, {{ix + 1, iz}, {ix + 1, iz + 1}, {ix, iz + 1}}};
    bool found = false;
    for (const auto& tri : corners) {
        const Vec3 a = g.point(tri[0][0], tri[0][1]), b = g.point(tri[1][0], tri[1][1]), c = g.point(tri[2][0], tri[2][1]);
        double t = 0, b1 = 0, b2 = 0;
        if (!triangleT(r, a, b, c, t, b1, b2) || t <= tMin || t >= tMax) continue;
        if (g.water > 0 && r.at(t).y < g.water) continue;
        tMax = t;
        found = true;
        h.t = t;
        Vec3 n = normalize(cross(c - a, b - a));  // up for a ccw-from-above triangle
        if (n.y < 0) n = -n;
        h.geomNormal = n;
        if (o.smooth) {
            const Vec3 s = (1 - b1 - b2) * g.vertexNormal(tri[0][0], tri[0][1]) +
                           b1 * g.vertexNormal(tri[1][0], tri[1][1]) + b2 * g.vertexNormal(tri[2][0], tri[2][1]);
            h.normal = length(s) > 0 ? normalize(s) : n;
        } else {
            h.normal = n;
        }
    }
    return found;
}

}  // namespace

bool makeHeightField(int nx, int nz, const std::vector<double>& heights, double waterLevel, ShapeData& data) {
    if (nx < 2 || nz < 2 || heights.size() != size_t(nx) * size_t(nz)) return false;
    data.values.clear();
    data.values.reserve(kHeader + heights.size());
    data.values.push_back(nx);
    data.values.push_back(nz);
    data.values.push_back(waterLevel);
    data.values.insert(data.values.end(), heights.begin(), heights.end());
    double lo = std::max(waterLevel, 0.0), hi = 0;
    for (double v : heights) hi = std::max(hi, v);
    lo = std::min(lo, hi);
    for (double v : heights) lo = std::min(lo, std::max(v, waterLevel));
    data.bounds = Bounds{Vec3{0, lo, 0}, Vec3{1, hi, 1}};
    return true;
}

bool hitHeightField(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const Grid g = gridOf(o);
    double t0 = tMin, t1 = tMax;
    if (!clipRayToBox(o.data->bounds, r, t0, t1)) return false;
    // Grid coordinates: X = x·(nx−1), Z = z·(nz−1); cell (ix, iz) spans [ix, ix+1] × [iz, iz+1].
    const double sx = g.nx - 1, sz = g.nz - 1;
    const Vec3 start = r.at(t0);
    int ix = std::clamp(int(std::floor(start.x * sx)), 0, g.nx - 2);
    int iz = std::clamp(int(std::floor(start.z * sz)), 0, g.nz - 2);
    const double dX = r.dir.x * sx, dZ = r.dir.z * sz;
    const int stepX = dX > 0 ? 1 : -1, stepZ = dZ > 0 ? 1 : -1;
    // t at which the ray crosses the next cell boundary in X and Z, and the t per cell.
    const double inf = kInfinity;
    auto next = [&](double origin, double d, int i, int step) {
        if (d == 0) return inf;
        const double boundary = step > 0 ? i + 1 : i;
        return (boundary - origin) / d;
    };
    const double oX = r.origin.x * sx, oZ = r.origin.z * sz;
    double tX = next(oX, dX, ix, stepX), tZ = next(oZ, dZ, iz, stepZ);
    const double dtX = dX == 0 ? inf : std::fabs(1 / dX), dtZ = dZ == 0 ? inf : std::fabs(1 / dZ);
    double tEnter = t0;
    for (;;) {
        const double tExit = std::min({tX, tZ, t1});
        // The ray's height over [tEnter, tExit] against the cell's.
        const double y0 = r.origin.y + r.dir.y * tEnter, y1 = r.origin.y + r.dir.y * tExit;
        const double c00 = g.at(ix, iz), c10 = g.at(ix + 1, iz), c01 = g.at(ix, iz + 1), c11 = g.at(ix + 1, iz + 1);
        const double cellLo = std::min({c00, c10, c01, c11}), cellHi = std::max({c00, c10, c01, c11});
        const double pad = 1e-9;
        if (std::min(y0, y1) <= cellHi + pad && std::max(y0, y1) >= cellLo - pad &&
            hitCell(g, o, r, ix, iz, tMin, tMax, h))
            return true;
        if (tExit >= t1) return false;
        if (tX < tZ) {
            ix += stepX;
            tEnter = tX;
            tX += dtX;
            if (ix < 0 || ix > g.nx - 2) return false;
        } else {
            iz += stepZ;
            tEnter = tZ;
            tZ += dtZ;
            if (iz < 0 || iz > g.nz - 2) return false;
        }
    }
}

bool insideHeightField(const Object& o, Vec3 p) {
    const Grid g = gridOf(o);
    if (p.x < 0 || p.x > 1 || p.z < 0 || p.z > 1 || p.y < o.data->bounds.lo.y) return false;
    const double X = p.x * (g.nx - 1), Z = p.z * (g.nz - 1);
    const int ix = std::clamp(int(X), 0, g.nx - 2), iz = std::clamp(int(Z), 0, g.nz - 2);
    const double fx = X - ix, fz = Z - iz;
    // The triangle of the cell holding p (split along fx + fz = 1), interpolated linearly.
    const double c00 = g.at(ix, iz), c10 = g.at(ix + 1, iz), c01 = g.at(ix, iz + 1), c11 = g.at(ix + 1, iz + 1);
    const double y = fx + fz <= 1 ? c00 + fx * (c10 - c00) + fz * (c01 - c00)
                                  : c11 + (1 - fx) * (c01 - c11) + (1 - fz) * (c10 - c11);
    return p.y < y;
}

}  // namespace rays
