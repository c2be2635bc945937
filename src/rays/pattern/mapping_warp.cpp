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
    }
    return oriented(w.orientation, c);
}

}  // namespace rays::pattern
