// The polynomial along the ray, p(O + tD), is expanded term by term with the binomial theorem
// and its real roots found by polyRoots (poly_roots.h). The origin is first moved to the point of
// the ray nearest the object's origin, which keeps the coefficients small for cameras far away.
#include "rays/scene/shapes/poly.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "rays/math/poly_roots.h"

namespace rays {

int polyTermCount(int n) { return (n + 1) * (n + 2) * (n + 3) / 6; }

int polyTermIndex(int n, int i, int j, int k) {
    // Terms before x^i: those with a higher x power; before y^j within x^i: higher y powers.
    int idx = 0;
    for (int a = n; a > i; --a) idx += (n - a + 1) * (n - a + 2) / 2;
    const int m = n - i;  // the y, z degrees left
    for (int b = m; b > j; --b) idx += m - b + 1;
    return idx + (m - j - k);
}

namespace {

// pw[i] = v^i for i ≤ n.
void powers(double v, int n, double* pw) {
    pw[0] = 1;
    for (int i = 1; i <= n; ++i) pw[i] = pw[i - 1] * v;
}

// Coefficients of (o + t d)^i for i ≤ n: row i of out (stride kMaxPolyDegree + 1).
constexpr int kStride = kMaxPolyDegree + 1;
void binomialRows(double o, double d, int n, double* out) {
    out[0] = 1;
    for (int i = 1; i <= n; ++i) {
        const double* prev = out + (i - 1) * kStride;
        double* row = out + i * kStride;
        row[0] = prev[0] * o;
        for (int m = 1; m < i; ++m) row[m] = prev[m] * o + prev[m - 1] * d;
        row[i] = prev[i - 1] * d;
    }
}

// Quadrics (order 2: shapes.inc's cylinders, cones, paraboloids, hyperboloids) in closed form.
// The ten values in the order above: x² xy xz x y² yz y z² z 1.
double evalQuadric(const double* a, Vec3 q) {
    return q.x * (a[0] * q.x + a[1] * q.y + a[2] * q.z + a[3]) + q.y * (a[4] * q.y + a[5] * q.z + a[6]) +
           q.z * (a[7] * q.z + a[8]) + a[9];
}

Vec3 quadricGradient(const double* a, Vec3 q) {
    return {2 * a[0] * q.x + a[1] * q.y + a[2] * q.z + a[3], a[1] * q.x + 2 * a[4] * q.y + a[5] * q.z + a[6],
            a[2] * q.x + a[5] * q.y + 2 * a[7] * q.z + a[8]};
}

// The roots of A t² + B t + C in increasing order (the stable form: q = −(B + sign(B)·√disc)/2,
// roots q/A and C/q); a vanishing A leaves the linear root.
int quadraticRoots(double A, double B, double C, double* roots) {
    if (A == 0) {
        if (B == 0) return 0;
        roots[0] = -C / B;
        return 1;
    }
    const double disc = B * B - 4 * A * C;
    if (disc < 0) return 0;
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    double r0 = q / A, r1 = q != 0 ? C / q : r0;
    if (r0 > r1) std::swap(r0, r1);
    roots[0] = r0, roots[1] = r1;
    return 2;
}

bool hitQuadric(const ShapeData& sd, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const double* a = sd.values.data();
    const double dd = dot(r.dir, r.dir);
    const double t0 = -dot(r.origin, r.dir) / dd;  // the new origin's t, as for higher orders
    const Vec3 O = r.origin + t0 * r.dir, D = r.dir;
    const double A = a[0] * D.x * D.x + a[1] * D.x * D.y + a[2] * D.x * D.z + a[4] * D.y * D.y + a[5] * D.y * D.z +
                     a[7] * D.z * D.z;
    const double B = dot(quadricGradient(a, O), D);  // d/dt p(O + tD) at t = 0
    const double C = evalQuadric(a, O);
    double roots[2];
    const int count = quadraticRoots(A, B, C, roots);
    int i = 0;
    while (i < count && !(roots[i] + t0 > tMin && roots[i] + t0 < tMax)) ++i;
    if (i == count) return false;
    h.t = roots[i] + t0;
    const Vec3 g = quadricGradient(a, r.at(h.t));
    h.normal = length(g) > 0 ? normalize(g) : -r.dir / std::sqrt(dd);
    return true;
}

// The plan's terms a·x^i y^j z^k (makePolySurface), in the coefficients' order: f(i, j, k, a).
template <class F>
void forEachPlanTerm(const ShapeData& d, F&& f) {
    const double* g = d.values.data() + polyTermCount(d.order);
    const int groups = int(*g++);
    for (int gi = 0; gi < groups; ++gi) {
        const int i = int(g[0]), j = int(g[1]), terms = int(g[2]);
        g += 3;
        for (int t = 0; t < terms; ++t, g += 2) f(i, j, int(g[0]), g[1]);
    }
}

}  // namespace

double evalPolySurface(const ShapeData& d, Vec3 q) {
    const int n = d.order;
    if (n == 2 && d.values.size() >= 10) return evalQuadric(d.values.data(), q);
    double px[kStride], py[kStride], pz[kStride];
    powers(q.x, n, px), powers(q.y, n, py), powers(q.z, n, pz);
    // The sum of all the terms but the zero ones, which add nothing (0·∞ at coordinates beyond 1e77
    // aside).
    double v = 0;
    forEachPlanTerm(d, [&](int i, int j, int k, double a) { v += a * px[i] * py[j] * pz[k]; });
    return v;
}

std::unique_ptr<ShapeData> makePolySurface(int n, const std::vector<double>& coef) {
    auto d = std::make_unique<ShapeData>();
    d->order = n;
    std::vector<double>& v = d->values;
    v = coef;
    v.resize(size_t(polyTermCount(n)), 0.0);
    // The plan (poly.h): the groups of x^i y^j terms with a nonzero coefficient, in the order of
    // the coefficients.
    const size_t countAt = v.size();
    v.push_back(0);
    int idx = 0;
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j) {
            const size_t head = v.size();
            int terms = 0;
            for (int k = n - i - j; k >= 0; --k, ++idx) {
                const double a = v[size_t(idx)];
                if (a == 0) continue;
                if (terms++ == 0) v.insert(v.end(), {double(i), double(j), 0.0});
                v.insert(v.end(), {double(k), a});
            }
            if (terms == 0) continue;
            v[head + 2] = terms;
            v[countAt] += 1;
        }
    return d;
}

bool hitPolySurface(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const ShapeData& sd = *o.data;
    const int n = sd.order;
    if (n == 2 && sd.values.size() >= 10) return hitQuadric(sd, r, tMin, tMax, h);
    const double dd = dot(r.dir, r.dir);
    const double t0 = -dot(r.origin, r.dir) / dd;  // the new origin's t
    const Vec3 O = r.origin + t0 * r.dir, D = r.dir;
    double X[kStride * kStride], Y[kStride * kStride], Z[kStride * kStride];
    binomialRows(O.x, D.x, n, X), binomialRows(O.y, D.y, n, Y), binomialRows(O.z, D.z, n, Z);
    double c[kStride];
    std::fill_n(c, n + 1, 0.0);
    // The plan's groups: zs(t) = Σ_k a_ijk (Oz + t Dz)^k, then c += X_i · Y_j · zs.
    const double* plan = sd.values.data() + polyTermCount(n);
    const int groups = int(plan[0]);
    const double* g = plan + 1;
    for (int gi = 0; gi < groups; ++gi) {
        const int i = int(g[0]), j = int(g[1]), terms = int(g[2]), kMax = n - i - j;
        g += 3;
        double zs[kStride];
        std::fill_n(zs, kMax + 1, 0.0);
        for (int t = 0; t < terms; ++t, g += 2) {
            const int k = int(g[0]);
            const double a = g[1];
            for (int m = 0; m <= k; ++m) zs[m] += a * Z[k * kStride + m];
        }
        double xy[kStride];
        std::fill_n(xy, i + j + 1, 0.0);
        for (int p = 0; p <= i; ++p)
            for (int q = 0; q <= j; ++q) xy[p + q] += X[i * kStride + p] * Y[j * kStride + q];
        for (int p = 0; p <= i + j; ++p)
            for (int m = 0; m <= kMax; ++m) c[p + m] += xy[p] * zs[m];
    }
    // Real roots are bounded by Cauchy's bound 1 + max |c_m / c_top| (in the shifted variable).
    int top = n;
    while (top > 0 && c[top] == 0) --top;
    if (top == 0) return false;
    double bound = 0;
    for (int m = 0; m < top; ++m) bound = std::max(bound, std::fabs(c[m] / c[top]));
    bound = 1 + bound;
    const double lo = std::max(tMin - t0, -bound), hi = std::min(tMax - t0, bound);
    // The first root whose t, after the shift back and the rounding, is still in (tMin, tMax).
    double root;
    if (!firstValidRoot(c, top, lo, hi, [&](double x) { return x + t0 > tMin && x + t0 < tMax; }, root)) return false;
    h.t = root + t0;
    // The gradient at the hit.
    const Vec3 q = r.at(h.t);
    double px[kStride], py[kStride], pz[kStride];
    powers(q.x, n, px), powers(q.y, n, py), powers(q.z, n, pz);
    Vec3 grad;
    forEachPlanTerm(sd, [&](int i, int j, int k, double a) {
        if (i) grad.x += a * i * px[i - 1] * py[j] * pz[k];
        if (j) grad.y += a * j * px[i] * py[j - 1] * pz[k];
        if (k) grad.z += a * k * px[i] * py[j] * pz[k - 1];
    });
    h.normal = length(grad) > 0 ? normalize(grad) : -r.dir / std::sqrt(dd);
    return true;
}

// As POV-Ray 3.7's inside() answers (measured 10^-4 … 10^-16 either side of the surfaces of cubics,
// quartics and a poly of order 5): a quadric is closed, a higher order holds the points where the
// polynomial is below 1e-4.
bool insidePolySurface(const Object& o, Vec3 q) {
    const double f = evalPolySurface(*o.data, q);
    return o.data->order <= 2 ? f <= 0 : f < 1e-4;
}

void quadricInsideInterval(const ShapeData& d, const Ray& r, double& lo, double& hi) {
    const double* a = d.values.data();
    const Vec3 O = r.origin, D = r.dir;
    // p(O + tD) = A t² + B t + C with A ≥ 0 (a convex quadric): inside between the two roots.
    const double A = a[0] * D.x * D.x + a[1] * D.x * D.y + a[2] * D.x * D.z + a[4] * D.y * D.y + a[5] * D.y * D.z +
                     a[7] * D.z * D.z;
    const double B = dot(quadricGradient(a, O), D), C = evalQuadric(a, O);
    if (!(A > 0)) {  // along a cylinder's axis: p is (nearly) constant
        if (C > 0 && B == 0) hi = lo;
        return;
    }
    double roots[2];
    if (quadraticRoots(A, B, C, roots) < 2) {
        hi = lo;
        return;
    }
    lo = std::max(lo, roots[0]);
    hi = std::min(hi, roots[1]);
}

bool quadricInsideBox(const ShapeData& d, Bounds& box) {
    if (d.order != 2 || d.values.size() < 10) return false;
    // p(x) = xᵀAx + b·x + c. Where A's block over the variables that appear is positive definite,
    // {p ≤ 0} is the ellipsoid (x − m)ᵀA(x − m) ≤ r with m = −A⁻¹b/2 and r = −p(m), whose extent
    // along axis i is √(r·(A⁻¹)ᵢᵢ) (the support function of an ellipsoid); A is tested and
    // inverted by Cholesky factorisation (Golub & Van Loan, "Matrix Computations", §4.2).
    const double* a = d.values.data();
    const double A[3][3] = {{a[0], a[1] / 2, a[2] / 2}, {a[1] / 2, a[4], a[5] / 2}, {a[2] / 2, a[5] / 2, a[7]}};
    const double b[3] = {a[3], a[6], a[8]}, c = a[9];
    int idx[3], k = 0;
    for (int i = 0; i < 3; ++i)
        if (A[i][0] != 0 || A[i][1] != 0 || A[i][2] != 0 || b[i] != 0) idx[k++] = i;
    if (k == 0) return false;
    double L[3][3] = {};
    for (int i = 0; i < k; ++i)
        for (int j = 0; j <= i; ++j) {
            double s = A[idx[i]][idx[j]];
            for (int m = 0; m < j; ++m) s -= L[i][m] * L[j][m];
            if (i == j) {
                if (!(s > 1e-12 * std::fabs(A[idx[i]][idx[i]]))) return false;  // not positive definite
                L[i][i] = std::sqrt(s);
            } else {
                L[i][j] = s / L[j][j];
            }
        }
    // Columns of A⁻¹ by two triangular solves each.
    double inv[3][3] = {};
    for (int col = 0; col < k; ++col) {
        double y[3];
        for (int i = 0; i < k; ++i) {
            double s = i == col ? 1.0 : 0.0;
            for (int m = 0; m < i; ++m) s -= L[i][m] * y[m];
            y[i] = s / L[i][i];
        }
        for (int i = k - 1; i >= 0; --i) {
            double s = y[i];
            for (int m = i + 1; m < k; ++m) s -= L[m][i] * inv[m][col];
            inv[i][col] = s / L[i][i];
        }
    }
    double m[3] = {}, bm = 0;
    for (int i = 0; i < k; ++i) {
        for (int j = 0; j < k; ++j) m[i] -= 0.5 * inv[i][j] * b[idx[j]];
        bm += b[idx[i]] * m[i];
    }
    const double r = std::max(0.0, -(c + 0.5 * bm));  // −p(m) = −(c + b·m/2); below 0: no inside
    box = Bounds{Vec3(-kInfinity), Vec3(kInfinity)};
    for (int i = 0; i < k; ++i) {
        const double half = std::sqrt(r * inv[i][i]);
        box.lo[idx[i]] = m[i] - half;
        box.hi[idx[i]] = m[i] + half;
    }
    return true;
}

namespace {

// The least of a·t² + b·t over [lo, hi] (ends may be infinite; −∞ when unbounded below).
double leastOver(double a, double b, double lo, double hi) {
    if (a == 0 && b == 0) return 0;
    auto f = [&](double t) {
        if (!std::isinf(t)) return a * t * t + b * t;
        return a > 0 || (a == 0 && b * t > 0) ? kInfinity : -kInfinity;
    };
    double least = std::min(f(lo), f(hi));
    if (a > 0) {
        const double v = -b / (2 * a);
        if (v > lo && v < hi) least = std::min(least, f(v));
    }
    return least;
}

// The hull of {t in [lo, hi] : a·t² + b·t + k ≤ 0}; lo > hi when empty.
void hullWhereNegative(double a, double b, double k, double& lo, double& hi) {
    if (a == 0) {
        if (b == 0) {
            if (k > 0) lo = kInfinity, hi = -kInfinity;
            return;
        }
        const double root = -k / b;
        if (b > 0) hi = std::min(hi, root);
        else lo = std::max(lo, root);
        return;
    }
    const double disc = b * b - 4 * a * k;
    if (disc < 0) {  // the quadratic keeps a's sign
        if (a > 0) lo = kInfinity, hi = -kInfinity;
        return;
    }
    const double sq = std::sqrt(disc), r1 = std::min((-b - sq) / (2 * a), (-b + sq) / (2 * a)),
                 r2 = std::max((-b - sq) / (2 * a), (-b + sq) / (2 * a));
    if (a > 0) {  // between the roots
        lo = std::max(lo, r1);
        hi = std::min(hi, r2);
        return;
    }
    // Outside the roots: the hull of [lo, r1] and [r2, hi] where they are not empty.
    const bool below = lo <= r1, above = hi >= r2;
    if (!below && !above) lo = kInfinity, hi = -kInfinity;
    else if (!below) lo = std::max(lo, r2);
    else if (!above) hi = std::min(hi, r1);
}

}  // namespace

bool quadricBoxWithin(const ShapeData& d, const Bounds& clip, Bounds& box) {
    if (d.order != 2 || d.values.size() < 10) return false;
    const double* v = d.values.data();
    if (v[1] != 0 || v[2] != 0 || v[5] != 0) return false;
    const double a[3] = {v[0], v[4], v[7]}, b[3] = {v[3], v[6], v[8]}, c = v[9];
    double least[3];
    for (int i = 0; i < 3; ++i) least[i] = leastOver(a[i], b[i], clip.lo[i], clip.hi[i]);
    box = clip;
    for (int i = 0; i < 3; ++i) {
        const double rest = c + least[(i + 1) % 3] + least[(i + 2) % 3];
        if (std::isnan(rest) || (std::isinf(rest) && rest < 0)) continue;  // the other axes reach any depth: no limit
        if (!(rest < kInfinity)) return box = Bounds{}, true;
        hullWhereNegative(a[i], b[i], rest, box.lo[i], box.hi[i]);
        if (!(box.lo[i] <= box.hi[i])) return box = Bounds{}, true;
        // A margin of a millionth of the ends' size for the rounding of the roots.
        const double pad = 1e-6 * (1 + (std::isfinite(box.lo[i]) ? std::fabs(box.lo[i]) : 0) +
                                   (std::isfinite(box.hi[i]) ? std::fabs(box.hi[i]) : 0));
        box.lo[i] = std::max(clip.lo[i], box.lo[i] - pad);
        box.hi[i] = std::min(clip.hi[i], box.hi[i] + pad);
    }
    return true;
}

}  // namespace rays
