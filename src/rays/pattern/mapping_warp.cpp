#include "rays/pattern/mapping_warp.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rays::pattern {
namespace {

// The angle about y from +x towards +z in turns, in [0, 1).
double turns(double x, double z) {
    double u = std::atan2(z, x) / (2 * std::numbers::pi);
    if (u < 0) u += 1;
    return u >= 1 ? 0.0 : u;
}

// The cubic warp's (u, v) of p (mapping_warp.h): the first face of +x, +z, +y, −x, −y, −z whose
// coordinate, signed, reaches a = max(|x|, |y|, |z|) (measured on edges and corners).
Vec3 cubeMap(Vec3 p) {
    const double a = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    if (!(a > 0)) return {0, 0, 0};
    const double x = p.x / a, y = p.y / a, z = p.z / a;
    double u, v;
    if (p.x >= a) u = 0.625 - z / 8, v = 0.5 + y / 6;
    else if (p.z >= a) u = 0.375 + x / 8, v = 0.5 + y / 6;
    else if (p.y >= a) u = 0.375 + x / 8, v = 5.0 / 6 - z / 6;
    else if (-p.x >= a) u = 0.125 + z / 8, v = 0.5 + y / 6;
    else if (-p.y >= a) u = 0.375 + x / 8, v = 1.0 / 6 + z / 6;
    else u = 0.875 - x / 8, v = 0.5 + y / 6;
    return {u, v, a};
}

// M(o)·c (mapping_warp.h).
Vec3 oriented(Vec3 o, Vec3 c) {
    return {(o.y + o.z) * c.x + o.x * c.z, (o.x + o.z) * c.y - o.y * c.z, -o.x * c.x + o.y * c.y + o.z * c.z};
}

}  // namespace

Vec3 applyMappingWarp(const MappingWarp& w, Vec3 p) {
    Vec3 c;
    switch (w.kind) {
        case MappingKind::Planar: c = {p.x, p.y, w.distance}; break;
        case MappingKind::Cylindrical: {
            const double r = std::sqrt(p.x * p.x + p.z * p.z);
            const double scale = w.distExp != 0 ? std::pow(r, w.distExp) : 1.0;
            c = {turns(p.x, p.z) * scale, p.y, r};
            break;
        }
        case MappingKind::Spherical: {
            const double r = length(p);
            const double scale = w.distExp != 0 ? std::pow(r, w.distExp) : 1.0;
            const double v = r > 0 ? std::asin(std::clamp(p.y / r, -1.0, 1.0)) / std::numbers::pi + 0.5 : 0.5;
            c = {turns(p.x, p.z) * scale, v * scale, r};
            break;
        }
        case MappingKind::Toroidal: {
            const double across = std::sqrt(p.x * p.x + p.z * p.z) - w.majorRadius;
            const double r = std::sqrt(across * across + p.y * p.y);
            const double scale = w.distExp != 0 ? std::pow(r, w.distExp) : 1.0;
            double round = std::atan2(p.y, across) / (2 * std::numbers::pi) + 0.5;
            if (round >= 1) round -= 1;
            c = {turns(p.x, p.z) * scale, round * scale, r};
            break;
        }
        case MappingKind::Cubic: c = cubeMap(p); break;
    }
    return oriented(w.orientation, c);
}

}  // namespace rays::pattern
