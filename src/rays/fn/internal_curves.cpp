// Internal functions built from a plane curve g(X, Y) = 0 (reference 3.4.9.1.7.5-7, "SOR"
// parameters): with the SOR switch off (≤ 0) the curve is extruded along z, X = x and Y = y;
// with it on (> 0) it is swept around the y axis: X = sqrt(x² + z²) − offset, then (X, Y) is
// rotated by the SOR angle (degrees) about z. The value is the field strength times g, clamped
// (internal_field.h). The curves were recovered by fitting POV-Ray 3.7's values.
#include <cmath>

#include "rays/fn/internal_field.h"
#include "rays/fn/internal_impl.h"
#include "rays/fn/ops.h"

namespace rays::fn::internal {
namespace {

struct Plane {
    double x, y;
};

// The curve coordinates of point p; the SOR switch, offset and angle are p[sor], p[sor+1], p[sor+2].
Plane curvePoint(const double* p, int sor) {
    if (!(p[sor] > 0)) return {p[0], p[1]};
    const double x = std::sqrt(p[0] * p[0] + p[2] * p[2]) - p[sor + 1];
    const double a = p[sor + 2] * ops::kRadiansPerDegree;
    const double c = std::cos(a), s = std::sin(a);
    return {x * c - p[1] * s, x * s + p[1] * c};
}

}  // namespace

// Figure-of-eight: |X|³ − X² + Y²; P1 is the field limit, P2-P4 the SOR parameters.
double f_algbr_cyl1(const double* p) {
    const Plane q = curvePoint(p, 5);
    const double x2 = q.x * q.x;
    return field(p[3], std::fabs(q.x) * x2 - x2 + q.y * q.y, p[4]);
}

// 3X²Y + 2Y³ − 2X⁴ − Y⁴ − Y²; P1 field limit, P2-P4 SOR.
double f_algbr_cyl2(const double* p) {
    const Plane q = curvePoint(p, 5);
    const double x2 = q.x * q.x, y2 = q.y * q.y;
    return field(p[3], 3 * x2 * q.y + 2 * y2 * q.y - 2 * x2 * x2 - y2 * y2 - y2, p[4]);
}

// XY² + 2X²Y − X²Y² − X⁴ − Y²; P1 field limit, P2-P4 SOR.
double f_algbr_cyl3(const double* p) {
    const Plane q = curvePoint(p, 5);
    const double x2 = q.x * q.x, y2 = q.y * q.y;
    return field(p[3], q.x * y2 + 2 * x2 * q.y - x2 * y2 - x2 * x2 - y2, p[4]);
}

// Y³ − 3X²Y − (X² + Y²)²; P1 field limit, P2-P4 SOR.
double f_algbr_cyl4(const double* p) {
    const Plane q = curvePoint(p, 5);
    const double x2 = q.x * q.x, y2 = q.y * q.y;
    return field(p[3], y2 * q.y - 3 * x2 * q.y - sq(x2 + y2), p[4]);
}

// Devil's curve: Y⁴ − X⁴ + a²X² − b²Y², a = P1, b = P2; P3-P5 SOR.
double f_devils_curve_2d(const double* p) {
    const Plane q = curvePoint(p, 6);
    const double x2 = q.x * q.x, y2 = q.y * q.y, a = p[4], b = p[5];
    return field(p[3], y2 * y2 - x2 * x2 + a * a * x2 - b * b * y2);
}

// Folium (the 3-D surface's curve, negated): −(Y²(1 + (b − 4a)X) + (b + 1)X²), a = P1, b = P2; P3-P5 SOR.
double f_folium_surface_2d(const double* p) {
    const Plane q = curvePoint(p, 6);
    const double a = p[4], b = p[5];
    return field(p[3], -(q.y * q.y * (1 + (b - 4 * a) * q.x) + (b + 1) * q.x * q.x));
}

// Kampyle of Eudoxus: b²X⁴ − a·b³X² − Y², a = P1 (dimple), b = P2 (closeness); P3-P5 SOR.
double f_kampyle_of_eudoxus_2d(const double* p) {
    const Plane q = curvePoint(p, 6);
    const double x2 = q.x * q.x, a = p[4], b = p[5];
    return field(p[3], b * b * x2 * x2 - a * b * b * b * x2 - q.y * q.y);
}

// Lemniscate of Gerono: a²b²X² − b²X⁴ − Y², a = P1 (size), b = P2 (width); P3-P5 SOR.
double f_lemniscate_of_gerono_2d(const double* p) {
    const Plane q = curvePoint(p, 6);
    const double x2 = q.x * q.x, a = p[4], b = p[5];
    return field(p[3], a * a * b * b * x2 - b * b * x2 * x2 - q.y * q.y);
}

// Piriform: c²(aX³ + bX⁴) − Y², a = P1, b = P2, c = P3 (fatness); P4-P6 SOR.
double f_piriform_2d(const double* p) {
    const Plane q = curvePoint(p, 7);
    const double x2 = q.x * q.x, a = p[4], b = p[5], c = p[6];
    return field(p[3], c * c * (a * x2 * q.x + b * x2 * x2) - q.y * q.y);
}

// Strophoid: c²X²(X + a) + Y²(X − b), a = P1 (bulb), b = P2 (sharpness), c = P3; P4-P6 SOR.
double f_strophoid_2d(const double* p) {
    const Plane q = curvePoint(p, 7);
    const double a = p[4], b = p[5], c = p[6];
    return field(p[3], c * c * q.x * q.x * (q.x + a) + q.y * q.y * (q.x - b));
}

// Witch of Agnesi: b − a²Y − X²Y, a = P1 (spike size), b = P2 (height); P3-P5 SOR.
double f_witch_of_agnesi_2d(const double* p) {
    const Plane q = curvePoint(p, 6);
    const double a = p[4], b = p[5];
    return field(p[3], b - a * a * q.y - q.x * q.x * q.y);
}

}  // namespace rays::fn::internal
