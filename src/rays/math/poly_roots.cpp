#include "rays/math/poly_roots.h"

#include <algorithm>
#include <cmath>

namespace rays {

double evalPoly(const double* c, int n, double t) {
    double v = c[n];
    for (int i = n - 1; i >= 0; --i) v = v * t + c[i];
    return v;
}

namespace {

// The root of monotone p (derivative d) in [a, b], where p(a) = fa and p(b) = fb differ in sign.
double refineRoot(const double* c, const double* d, int n, double a, double b, double fa, double fb) {
    // Keep a on the side where p has fa's sign. Start where the chord crosses zero (regula
    // falsi), nearer the root than the middle on a monotone piece, or the middle if that fails.
    const double chord = a - fa * (b - a) / (fb - fa);
    double x = chord > a && chord < b ? chord : 0.5 * (a + b);
    for (int it = 0; it < 100; ++it) {
        // p(x) by Horner's rule, with the bound of its rounding error (Higham, "Accuracy and
        // Stability of Numerical Algorithms", §5.1: |error| ≤ γ(2n) Σ|c_i||x|^i): once |p(x)| is
        // below it, x is a root as far as p can be evaluated, and further steps only wander.
        double f = c[n], mag = std::fabs(c[n]);
        const double ax = std::fabs(x);
        for (int i = n - 1; i >= 0; --i) {
            f = f * x + c[i];
            mag = mag * ax + std::fabs(c[i]);
        }
        if (std::fabs(f) <= 4 * n * 1.12e-16 * mag) return x;
        if ((f < 0) == (fa < 0)) a = x;
        else b = x;
        const double df = evalPoly(d, n - 1, x);
        double next = df != 0 ? x - f / df : 0.5 * (a + b);
        const double lo = a < b ? a : b, hi = a < b ? b : a;
        if (!(next > lo && next < hi)) next = 0.5 * (a + b);
        if (std::fabs(next - x) <= 1e-15 * (1 + std::fabs(x)) || hi - lo <= 1e-15 * (1 + std::fabs(x)))
            return next;
        x = next;
    }
    return x;
}

// The real roots of c[0] + c[1] t + c[2] t² (c[2] ≠ 0) in (lo, hi), ascending, by the formula
// that avoids cancellation (Press et al., Numerical Recipes, §5.6: q = −(b + sgn(b)√D)/2, roots
// q/a and c/q); a double root (D = 0) counts once.
int quadraticRoots(const double* c, double lo, double hi, double* roots) {
    const double a = c[2], b = c[1], cc = c[0];
    const double disc = b * b - 4 * a * cc;
    if (disc < 0) return 0;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double r0 = q / a, r1 = q != 0 ? cc / q : r0;
    if (r0 > r1) std::swap(r0, r1);
    int count = 0;
    if (r0 > lo && r0 < hi) roots[count++] = r0;
    if (r1 > lo && r1 < hi && (count == 0 || r1 != roots[0])) roots[count++] = r1;
    return count;
}

}  // namespace

int polyRoots(const double* c, int n, double lo, double hi, double* roots) {
    return polyRoots(c, n, lo, hi, roots, n);
}

int polyRoots(const double* c, int n, double lo, double hi, double* roots, int limit) {
    while (n > 0 && c[n] == 0) --n;
    if (n <= 0 || !(lo < hi) || limit <= 0) return 0;
    if (n == 1) {
        const double t = -c[0] / c[1];
        if (!(t > lo && t < hi)) return 0;
        roots[0] = t;
        return 1;
    }
    if (n == 2) return std::min(limit, quadraticRoots(c, lo, hi, roots));
    double d[kMaxPolyDegree];
    for (int i = 1; i <= n; ++i) d[i - 1] = i * c[i];
    double ends[kMaxPolyDegree + 1];  // lo, the critical points, hi
    ends[0] = lo;
    const int m = polyRoots(d, n - 1, lo, hi, ends + 1);
    ends[m + 1] = hi;
    int count = 0;
    double fa = evalPoly(c, n, lo);
    for (int i = 0; i <= m; ++i) {
        const double a = ends[i], b = ends[i + 1];
        const double fb = evalPoly(c, n, b);
        if ((fa < 0) != (fb < 0) && fa != 0) roots[count++] = refineRoot(c, d, n, a, b, fa, fb);
        else if (fb == 0 && i < m) roots[count++] = b;  // a root exactly at a critical point
        if (count == limit) break;
        fa = fb;
    }
    return count;
}

void cubicRange(const double* c, double& lo, double& hi) {
    const double d[3] = {c[1], 2 * c[2], 3 * c[3]};
    double roots[2];
    const int k = polyRoots(d, 2, 0, 1, roots);
    for (double u : {0.0, 1.0, k > 0 ? roots[0] : 0.0, k > 1 ? roots[1] : 0.0}) {
        lo = std::min(lo, cubicAt(c, u));
        hi = std::max(hi, cubicAt(c, u));
    }
}

}  // namespace rays
