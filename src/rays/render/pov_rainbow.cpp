#include "rays/render/pov_rainbow.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rays/pattern/color.h"

namespace rays {
namespace {

constexpr double kDegrees = 180 / std::numbers::pi;

// The arc's weight for a ray direction d: 1 within falloff_angle/2 of up (about the direction),
// falling linearly to 0 at arc_angle/2 (measured: half way at the middle of the fade).
double arcWeight(const PovRainbow& r, Vec3 d) {
    if (r.arcAngle >= 360) return 1;
    const Vec3 across = d - dot(d, r.direction) * r.direction;
    const Vec3 up = r.up - dot(r.up, r.direction) * r.direction;
    const double la = length(across), lu = length(up);
    if (la == 0 || lu == 0) return 1;
    const double phi = std::acos(std::clamp(dot(across, up) / (la * lu), -1.0, 1.0)) * kDegrees;
    const double arc = r.arcAngle / 2, fall = std::min(r.falloffAngle, r.arcAngle) / 2;
    if (phi <= fall) return 1;
    if (phi >= arc) return 0;
    return (arc - phi) / (arc - fall);
}

}  // namespace

Vec3 povRainbows(const std::vector<PovRainbow>& rainbows, Vec3 behind, const Ray& ray, double t, double u) {
    for (const PovRainbow& r : rainbows) {
        if (r.map.empty() || r.width <= 0) continue;
        const double theta = std::acos(std::clamp(dot(ray.dir, r.direction), -1.0, 1.0)) * kDegrees;
        double index = (theta - (r.angle - r.width / 2)) / r.width;
        if (index < 0 || index > 1) continue;
        index = std::clamp(index + r.jitter * (u - 0.5), 0.0, 1.0);
        const double w = arcWeight(r, ray.dir);
        if (w == 0) continue;
        const pattern::MapPlace at = pattern::placeInMap(r.map, index);
        const pattern::Rgbft c = at.lo == at.hi ? r.map[size_t(at.lo)].color
                                                : pattern::mix(r.map[size_t(at.lo)].color, r.map[size_t(at.hi)].color, at.t);
        // As a fog: keep a·(1 − filter + filter·colour) of what is behind and add (1 − a)·colour,
        // the arc's weight scaling the rainbow's share.
        const double a = 1 - w * (1 - std::max(std::exp(-t / r.distance), c.transmit));
        behind = behind * (a * (Vec3(1.0 - c.filter) + c.filter * c.rgb)) + (1 - a) * c.rgb;
    }
    return behind;
}

}  // namespace rays
