#include "rays/pattern/quilted.h"

#include <algorithm>
#include <cmath>

namespace rays::pattern {
namespace {

// p less the centre of its unit cube: each component in [−0.5, 0.5).
Vec3 fromCubeCentre(Vec3 p) {
    return {p.x - std::floor(p.x) - 0.5, p.y - std::floor(p.y) - 0.5, p.z - std::floor(p.z) - 0.5};
}

// The quilt's curve: the cubic Bézier through 0, control0, control1, 1.
double quiltCurve(const Quilt& q, double t) {
    const double s = 1 - t;
    return t * t * t + 3 * t * s * s * q.control0 + 3 * t * t * s * q.control1;
}

constexpr double kInvSqrt3 = 0.57735026918962576;

}  // namespace

double quiltedValue(const Quilt& q, Vec3 p) {
    const Vec3 d = fromCubeCentre(p);
    const double sum = std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
    const double v = quiltCurve(q, length(d)) * sum * (2.0 / 3.0) * kInvSqrt3;
    return std::min(1.0, std::fabs(v));
}

Vec3 quiltedTilt(const Quilt& q, Vec3 p) {
    const Vec3 d = fromCubeCentre(p);
    return (quiltCurve(q, length(d)) * 2 * kInvSqrt3) * d;
}

}  // namespace rays::pattern
