// Internal functions that are algebraic surfaces: a polynomial in x, y, z times the field
// strength P0, clamped to ±10 (internal_field.h). The reference names the surfaces but gives no
// equations; each polynomial here was recovered by fitting POV-Ray 3.7's values (a least-squares
// fit over a few hundred points, exact to the last digits) and matches the classical equation
// of the named surface (MathWorld, Wikipedia) up to the axes POV-Ray uses.
#include <cmath>
#include <numbers>

#include "rays/fn/internal_field.h"
#include "rays/fn/internal_impl.h"

namespace rays::fn::internal {
namespace {

struct Xyz {
    double x, y, z;
    double x2, y2, z2;
};
Xyz point(const double* p) { return {p[0], p[1], p[2], p[0] * p[0], p[1] * p[1], p[2] * p[2]}; }

}  // namespace

// Bicorn revolved about y: y²(a² − r²) − (r² + 2ay − a²)², r² = x² + z², a = P1.
double f_bicorn(const double* p) {
    const Xyz q = point(p);
    const double a = p[4], r2 = q.x2 + q.z2;
    return field(p[3], q.y2 * (a * a - r2) - sq(r2 + 2 * a * q.y - a * a));
}

// Bifolium revolved about y: a·y·(x² + z²) − (x² + y² + z²)², a = P1.
double f_bifolia(const double* p) {
    const Xyz q = point(p);
    return field(p[3], p[4] * q.y * (q.x2 + q.z2) - sq(q.x2 + q.y2 + q.z2));
}

// Boy's surface (Wikipedia's implicit equation of degree 6), times P1 and the strength P0.
double f_boy_surface(const double* p) {
    const Xyz q = point(p);
    const double x = q.x, y = q.y, z = q.z, r2 = q.x2 + q.y2, s2 = std::numbers::sqrt2;
    const double w = 1 - z;
    const double v = 64 * w * w * w * z * z * z - 48 * w * w * z * z * (3 * q.x2 + 3 * q.y2 + 2 * q.z2) +
                     12 * w * z * (27 * r2 * r2 - 24 * q.z2 * r2 + 36 * s2 * y * z * (q.y2 - 3 * q.x2) + 4 * q.z2 * q.z2) +
                     (9 * q.x2 + 9 * q.y2 - 2 * q.z2) *
                         (-81 * r2 * r2 - 72 * q.z2 * r2 + 108 * s2 * x * z * (q.x2 - 3 * q.y2) + 4 * q.z2 * q.z2);
    return field(p[3], p[4] * v);
}

// Crossed trough: x²z² − y.
double f_crossed_trough(const double* p) {
    const Xyz q = point(p);
    return field(p[3], q.x2 * q.z2 - q.y);
}

// Cubic saddle: y³ − x³ + z.
double f_cubic_saddle(const double* p) {
    const Xyz q = point(p);
    return field(p[3], q.y2 * q.y - q.x2 * q.x + q.z);
}

// Cushion (MathWorld): z²x² − z⁴ − 2zx² + 2z³ + x² − z² − (x² − z)² − y⁴ − 2x²y² − y²z² + 2y²z + y².
double f_cushion(const double* p) {
    const Xyz q = point(p);
    const double z = q.z;
    return field(p[3], q.z2 * q.x2 - q.z2 * q.z2 - 2 * z * q.x2 + 2 * q.z2 * z + q.x2 - q.z2 - sq(q.x2 - z) -
                           q.y2 * q.y2 - 2 * q.x2 * q.y2 - q.y2 * q.z2 + 2 * q.y2 * z + q.y2);
}

// f_odd: POV-Ray 3.7 gives exactly f_cushion's values (measured at 200 points).
double f_odd(const double* p) { return f_cushion(p); }

// Devil's curve revolved: y⁴ − 0.25y² − (x² + z²)² + 0.36x².
double f_devils_curve(const double* p) {
    const Xyz q = point(p);
    return field(p[3], q.y2 * q.y2 - 0.25 * q.y2 - sq(q.x2 + q.z2) + 0.36 * q.x2);
}

// Glob: x⁵/2 + x⁴/2 − y² − z².
double f_glob(const double* p) {
    const Xyz q = point(p);
    return field(p[3], 0.5 * q.x2 * q.x2 * q.x + 0.5 * q.x2 * q.x2 - q.y2 - q.z2);
}

// Heart: −(2x² + y² + z² − 1)³ + 0.1x²z³ + y²z³.
double f_heart(const double* p) {
    const Xyz q = point(p);
    const double z3 = q.z2 * q.z;
    const double b = 2 * q.x2 + q.y2 + q.z2 - 1;
    return field(p[3], -(b * b * b) + 0.1 * q.x2 * z3 + q.y2 * z3);
}

// Hunt's surface: −(4(x² + y² + z² − 13)³ + 27(3x² + y² − 4z² − 12)²).
double f_hunt_surface(const double* p) {
    const Xyz q = point(p);
    const double a = q.x2 + q.y2 + q.z2 - 13, b = 3 * q.x2 + q.y2 - 4 * q.z2 - 12;
    return field(p[3], -(4 * a * a * a + 27 * b * b));
}

// Klein bottle (Wikipedia's implicit form), negated:
// −((r² + 2y − 1)((r² − 2y − 1)² − 8z²) + 16xz(r² − 2y − 1)), r² = x² + y² + z².
double f_klein_bottle(const double* p) {
    const Xyz q = point(p);
    const double r2 = q.x2 + q.y2 + q.z2;
    const double m = r2 - 2 * q.y - 1;
    return field(p[3], -((r2 + 2 * q.y - 1) * (m * m - 8 * q.z2) + 16 * q.x * q.z * m));
}

// Kummer surface: −(x⁴ + y⁴ + z⁴) + x²y² + y²z² + z²x² + x² + y² + z² − 1.
double f_kummer_surface_v1(const double* p) {
    const Xyz q = point(p);
    return field(p[3], -(q.x2 * q.x2 + q.y2 * q.y2 + q.z2 * q.z2) + q.x2 * q.y2 + q.y2 * q.z2 + q.z2 * q.x2 + q.x2 +
                           q.y2 + q.z2 - 1);
}

// Kummer surface, version 2: 1 − a(x² + y² + z²) − b(x²y² + y²z² + z²x²) − (x⁴ + y⁴ + z⁴) − c·xyz
// with a, b, c = P1, P2, P3.
double f_kummer_surface_v2(const double* p) {
    const Xyz q = point(p);
    return field(p[3], 1 - p[4] * (q.x2 + q.y2 + q.z2) - p[5] * (q.x2 * q.y2 + q.y2 * q.z2 + q.z2 * q.x2) -
                           (q.x2 * q.x2 + q.y2 * q.y2 + q.z2 * q.z2) - p[6] * q.x * q.y * q.z);
}

// Lemniscate of Gerono revolved about x: x² − x⁴ − y² − z².
double f_lemniscate_of_gerono(const double* p) {
    const Xyz q = point(p);
    return field(p[3], q.x2 - q.x2 * q.x2 - q.y2 - q.z2);
}

// Mitre: −(4x²(x² + y² + z²) + y²(y² + z² − 1)).
double f_mitre(const double* p) {
    const Xyz q = point(p);
    return field(p[3], -(4 * q.x2 * (q.x2 + q.y2 + q.z2) + q.y2 * (q.y2 + q.z2 - 1)));
}

// Nodal cubic: 6yz − y³ − z³.
double f_nodal_cubic(const double* p) {
    const Xyz q = point(p);
    return field(p[3], 6 * q.y * q.z - q.y2 * q.y - q.z2 * q.z);
}

// Paraboloid about y: y − x² − z².
double f_paraboloid(const double* p) {
    const Xyz q = point(p);
    return field(p[3], q.y - q.x2 - q.z2);
}

// Pillow: x⁴ + y⁴ + z⁴ − (x² + y² + z²).
double f_pillow(const double* p) {
    const Xyz q = point(p);
    return field(p[3], q.x2 * q.x2 + q.y2 * q.y2 + q.z2 * q.z2 - (q.x2 + q.y2 + q.z2));
}

// Piriform revolved about x: x⁴ − x³ + y² + z².
double f_piriform(const double* p) {
    const Xyz q = point(p);
    return field(p[3], q.x2 * q.x2 - q.x2 * q.x + q.y2 + q.z2);
}

// Quartic paraboloid: y − x⁴ − z⁴.
double f_quartic_paraboloid(const double* p) {
    const Xyz q = point(p);
    return field(p[3], q.y - q.x2 * q.x2 - q.z2 * q.z2);
}

// Quartic saddle: y − x⁴ + z⁴.
double f_quartic_saddle(const double* p) {
    const Xyz q = point(p);
    return field(p[3], q.y - q.x2 * q.x2 + q.z2 * q.z2);
}

// Steiner's Roman surface: −(x²y² + y²z² + z²x² + xyz).
double f_steiners_roman(const double* p) {
    const Xyz q = point(p);
    return field(p[3], -(q.x2 * q.y2 + q.y2 * q.z2 + q.z2 * q.x2 + q.x * q.y * q.z));
}

// Torus gumdrop (MathWorld), negated: −(4(x⁴ + (y² + z²)²) + 17x²(y² + z²) − 20(x² + y² + z²) + 17).
double f_torus_gumdrop(const double* p) {
    const Xyz q = point(p);
    const double yz = q.y2 + q.z2;
    return field(p[3], -(4 * (q.x2 * q.x2 + yz * yz) + 17 * q.x2 * yz - 20 * (q.x2 + yz) + 17));
}

// Whitney umbrella: yz² − x².
double f_umbrella(const double* p) {
    const Xyz q = point(p);
    return field(p[3], q.y * q.z2 - q.x2);
}

// Folium surface: (y² + z²)(1 + (b − 4a)x) + (b + 1)x², a = P1 (neck), b = P2 (divergence).
double f_folium_surface(const double* p) {
    const Xyz q = point(p);
    const double a = p[4], b = p[5];
    return field(p[3], (q.y2 + q.z2) * (1 + (b - 4 * a) * q.x) + (b + 1) * q.x2);
}

// Hyperbolic torus (the y-axis torus with z imaginary): 4R²(x² − z²) − (x² + y² − z² + R² − r²)²,
// R = P1, r = P2.
double f_hyperbolic_torus(const double* p) {
    const Xyz q = point(p);
    const double R2 = p[4] * p[4], r2 = p[5] * p[5];
    return field(p[3], 4 * R2 * (q.x2 - q.z2) - sq(q.x2 + q.y2 - q.z2 + R2 - r2));
}

// Kampyle of Eudoxus: b²x²(x² − a²) − y² − z², a = P1 (dimple), b = P2 (closeness).
double f_kampyle_of_eudoxus(const double* p) {
    const Xyz q = point(p);
    const double a = p[4], b = p[5];
    return field(p[3], b * b * q.x2 * (q.x2 - a * a) - q.y2 - q.z2);
}

// Ovals of Cassini about y: f² + tR²(x² + z²) − (x² + y² + z² + R²)², R = P1, f = P2 (filling),
// t = P3 (thickness).
double f_ovals_of_cassini(const double* p) {
    const Xyz q = point(p);
    const double R2 = p[4] * p[4], f = p[5], t = p[6];
    return field(p[3], f * f + t * R2 * (q.x2 + q.z2) - sq(q.x2 + q.y2 + q.z2 + R2));
}

// Parabolic torus (the z-axis torus with z² replaced by z):
// −(x² + y² − z)² + (R² + r²)(x² − z) + (r² − R²)y² − (R² − r²)², R = P1, r = P2.
double f_parabolic_torus(const double* p) {
    const Xyz q = point(p);
    const double R2 = p[4] * p[4], r2 = p[5] * p[5];
    return field(p[3], -sq(q.x2 + q.y2 - q.z) + (R2 + r2) * (q.x2 - q.z) + (r2 - R2) * q.y2 - sq(R2 - r2));
}

// Quartic cylinder: a²b² − (x² + z²)(y² + b²), a = P1 (diameter of the egg), b = P2.
double f_quartic_cylinder(const double* p) {
    const Xyz q = point(p);
    const double a = p[4], b = p[5];
    return field(p[3], a * a * b * b - (q.x2 + q.z2) * (q.y2 + b * b));
}

// Strophoid revolved about x: c²x²(x + a) + (y² + z²)(x − b), a = P1 (bulb size), b = P2
// (sharpness), c = P3 (fatness).
double f_strophoid(const double* p) {
    const Xyz q = point(p);
    const double a = p[4], b = p[5], c = p[6];
    return field(p[3], c * c * q.x2 * (q.x + a) + (q.y2 + q.z2) * (q.x - b));
}

// Torus about y: 4R²(x² + z²) − (x² + y² + z² + R² − r²)², R = P1, r = P2.
double f_torus2(const double* p) {
    const Xyz q = point(p);
    const double R2 = p[4] * p[4], r2 = p[5] * p[5];
    return field(p[3], 4 * R2 * (q.x2 + q.z2) - sq(q.x2 + q.y2 + q.z2 + R2 - r2));
}

// Witch of Agnesi revolved about y: a(1 − y) − y(x² + z²), a = P1.
double f_witch_of_agnesi(const double* p) {
    const Xyz q = point(p);
    return field(p[3], p[4] * (1 - q.y) - q.y * (q.x2 + q.z2));
}

// Enneper's surface: (u/(2w) − 2z²/9)³ + 6(u/(4w))², u = x² − y², w = z except that for
// |z| < 0.2 POV-Ray uses w = 0.2 (measured: the values there are a polynomial in z with that w).
double f_enneper(const double* p) {
    const Xyz q = point(p);
    const double u = q.x2 - q.y2;
    const double w = std::fabs(q.z) < 0.2 ? 0.2 : q.z;
    const double a = u / (2 * w) - 2 * q.z2 / 9, b = u / (4 * w);
    return field(p[3], a * a * a + 6 * b * b);
}

// Dupin cyclid: a torus (major radius R = P1, minor r = P2, about y, moved by (dx, dy, 0) =
// (P3, P4, 0)) inverted in the sphere of radius k = P5, as a quartic in p (with |p|² = s):
//   −k⁸ + 4k⁶(p·d) − k⁴(4(p·d)² + 2C·s − 4R²(x² + z²))
//     + 4k²s(dx(|d|² − R² − r²)x + dy(|d|² − R² + r²)y) − (C² − 4R²dx²)s², C = |d|² + R² − r².
// Fitted to POV-Ray 3.7's values: its y term has r² − R² where the plain inversion has R² − r².
double f_dupin_cyclid(const double* p) {
    const Xyz q = point(p);
    const double R2 = p[4] * p[4], r2 = p[5] * p[5], dx = p[6], dy = p[7], k2 = p[8] * p[8];
    const double k4 = k2 * k2, d2 = dx * dx + dy * dy, C = d2 + R2 - r2;
    const double s = q.x2 + q.y2 + q.z2, pd = dx * q.x + dy * q.y;
    const double v = -k4 * k4 + 4 * k4 * k2 * pd - k4 * (4 * pd * pd + 2 * C * s - 4 * R2 * (q.x2 + q.z2)) +
                     4 * k2 * s * (dx * (d2 - R2 - r2) * q.x + dy * (d2 - R2 + r2) * q.y) - (C * C - 4 * R2 * dx * dx) * s * s;
    return field(p[3], v);
}

}  // namespace rays::fn::internal
