// Real roots of a polynomial in one variable on a bounded interval, for the ray tests of the
// polynomial shapes (torus, quartic, poly). Method: isolation by the derivative's roots — between
// two neighbouring critical points a polynomial is monotone, so it has a root there exactly when
// its sign changes, found by safeguarded Newton iteration (Newton steps kept inside a shrinking
// bracket, bisection when they leave it; Press et al., Numerical Recipes, "rtsafe"). The critical
// points are the roots of the derivative, found the same way, down to degree 2, which has its
// closed form. Robust for any
// degree up to kMaxPolyDegree; double roots where the sign does not change (grazing rays) are
// missed. No heap allocation.
#pragma once

namespace rays {

/// Highest degree polyRoots accepts (POV-Ray's poly allows order 35).
constexpr int kMaxPolyDegree = 35;

/// p(t) = c[0] + c[1] t + … + c[n] t^n by Horner's rule.
double evalPoly(const double* c, int n, double t);

/// The real roots of p(t) = c[0] + c[1] t + … + c[n] t^n in the open interval (lo, hi) (finite),
/// ascending, into roots (room for n); returns their count. n ≤ kMaxPolyDegree; zero leading
/// coefficients lower the degree.
int polyRoots(const double* c, int n, double lo, double hi, double* roots);
/// The same, stopping after the first `limit` roots (the nearest hits of a ray need one).
int polyRoots(const double* c, int n, double lo, double hi, double* roots, int limit);

/// The smallest root in (lo, hi) that valid(root) accepts (a ray's nearest hit, checked after
/// the shift back to the ray's parameter), into root; false when none. The nearest root alone is
/// found first, and all of them only when it is refused.
template <class Valid>
bool firstValidRoot(const double* c, int n, double lo, double hi, Valid&& valid, double& root) {
    double roots[kMaxPolyDegree];
    if (polyRoots(c, n, lo, hi, roots, 1) == 0) return false;
    if (valid(roots[0])) {
        root = roots[0];
        return true;
    }
    const int count = polyRoots(c, n, lo, hi, roots);
    for (int i = 0; i < count; ++i)
        if (valid(roots[i])) {
            root = roots[i];
            return true;
        }
    return false;
}

/// The cubic c[0] + c[1]·u + c[2]·u² + c[3]·u³ and its slope (spline segments of lathes and prisms).
inline double cubicAt(const double* c, double u) { return c[0] + u * (c[1] + u * (c[2] + u * c[3])); }
inline double cubicSlope(const double* c, double u) { return c[1] + u * (2 * c[2] + u * 3 * c[3]); }
/// Widens [lo, hi] to take in the cubic's values for u in [0, 1] (its ends and turning points).
void cubicRange(const double* c, double& lo, double& hi);

}  // namespace rays
