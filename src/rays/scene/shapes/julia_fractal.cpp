// Quaternion products (Hamilton): (a, v)(b, w) = (ab − v·w, aw + bv + v × w). Hypercomplex numbers
// a + bi + cj + dk (ij = ji = k, i² = j² = −1, k² = 1) are commutative and split into two complex
// numbers, w1 = (a − d) + (b + c)i and w2 = (a + d) + (b − c)i, on which any complex function acts
// one by one (the reference's functions are defined on the hypercomplex numbers this way); the
// 4-D norm is then |h|² = (|w1|² + |w2|²) / 2.
#include "rays/scene/shapes/julia_fractal.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <vector>

#include "rays/math/regula_falsi.h"
#include "rays/scene/shapes/box_clip.h"

namespace rays {

namespace {

using Cx = std::complex<double>;

enum JuliaSlot { kJuliaP = 0, kJuliaN = 4, kJuliaD = 8, kJuliaIter, kJuliaStep, kJuliaR2, kJuliaAlgebra, kJuliaFn, kJuliaPwr,
                 kJuliaSlots = kJuliaPwr + 2 };

// Bisection stops when the crossing is bracketed this tightly in object units: far below the
// march step (1/precision) and the 0.001 offset of secondary rays, and half the halvings of a
// bracket at double precision.
constexpr double kJuliaTolerance = 1e-9;

struct Quat {
    double a, b, c, d;
};

Quat qmul(const Quat& x, const Quat& y) {
    return {x.a * y.a - x.b * y.b - x.c * y.c - x.d * y.d, x.a * y.b + x.b * y.a + x.c * y.d - x.d * y.c,
            x.a * y.c - x.b * y.d + x.c * y.a + x.d * y.b, x.a * y.d + x.b * y.c - x.c * y.b + x.d * y.a};
}

double qnorm2(const Quat& x) { return x.a * x.a + x.b * x.b + x.c * x.c + x.d * x.d; }

Cx juliaComplex(JuliaFunction f, Cx w, const double* pw) {
    switch (f) {
        case JuliaFunction::Sqr: case JuliaFunction::Cube: return w * w;  // POV-Ray's hypercomplex cube squares (measured)
        case JuliaFunction::Exp: return std::exp(w);
        case JuliaFunction::Reciprocal: return 1.0 / w;
        case JuliaFunction::Sin: return std::sin(w);
        case JuliaFunction::Asin: return std::asin(w);
        case JuliaFunction::Sinh: return std::sinh(w);
        case JuliaFunction::Asinh: return std::asinh(w);
        case JuliaFunction::Cos: return std::cos(w);
        case JuliaFunction::Acos: return std::acos(w);
        case JuliaFunction::Cosh: return std::cosh(w);
        case JuliaFunction::Acosh: return std::acosh(w);
        case JuliaFunction::Tan: return std::tan(w);
        case JuliaFunction::Atan: return std::atan(w);
        case JuliaFunction::Tanh: return std::tanh(w);
        case JuliaFunction::Atanh: return std::atanh(w);
        case JuliaFunction::Ln: return std::log(w);
        case JuliaFunction::Pwr: return std::pow(w, Cx(pw[0], pw[1]));
    }
    return w;
}

// h(0) of the object-space point: t from the slice n·h = d.
Quat juliaStart(const double* v, Vec3 p) {
    const double* n = v + kJuliaN;
    return {p.x, p.y, p.z, (v[kJuliaD] - n[0] * p.x - n[1] * p.y - n[2] * p.z) / n[3]};
}

// f'(w) of the complex function (for the normal).
Cx juliaSlope(JuliaFunction f, Cx w, const double* pw) {
    const Cx one(1, 0);
    switch (f) {
        case JuliaFunction::Sqr: case JuliaFunction::Cube: return 2.0 * w;
        case JuliaFunction::Exp: return std::exp(w);
        case JuliaFunction::Reciprocal: return -one / (w * w);
        case JuliaFunction::Sin: return std::cos(w);
        case JuliaFunction::Asin: return one / std::sqrt(one - w * w);
        case JuliaFunction::Sinh: return std::cosh(w);
        case JuliaFunction::Asinh: return one / std::sqrt(one + w * w);
        case JuliaFunction::Cos: return -std::sin(w);
        case JuliaFunction::Acos: return -one / std::sqrt(one - w * w);
        case JuliaFunction::Cosh: return std::sinh(w);
        case JuliaFunction::Acosh: return one / (std::sqrt(w - one) * std::sqrt(w + one));
        case JuliaFunction::Tan: return one / (std::cos(w) * std::cos(w));
        case JuliaFunction::Atan: return one / (one + w * w);
        case JuliaFunction::Tanh: return one / (std::cosh(w) * std::cosh(w));
        case JuliaFunction::Atanh: return one / (one - w * w);
        case JuliaFunction::Ln: return one / w;
        case JuliaFunction::Pwr: {
            const Cx e(pw[0], pw[1]);
            return e * std::pow(w, e - one);
        }
    }
    return one;
}

// The iteration steps h ← f(h) + p, each also giving grow2, a bound on |f'(h)|² (the derivative's
// growth, squared, for juliaIterate's reach). n2 is |h|². Quaternions are (a, v) with a real and v
// a 3-vector; hypercomplex numbers are carried as their two complex parts (w1, w2) in the four slots.

// Steps with kExact bound how far apart two states can be after the step: for states h and h + e
// with |h| ≤ a (a² = size2, what the step reports), |f(h + e) − f(h)| ≤ after(|e|, a), from
// |(h + e)ⁿ − hⁿ| ≤ (|h| + |e|)ⁿ − |h|ⁿ (expand the product; norms multiply in the quaternions).

// Quaternion square: (a, v)² = (a² − |v|², 2av); |d(h²)| ≤ 2|h|.
struct QuatSqrStep {
    static constexpr bool kExact = true;
    static constexpr double kStartGap = 1;  // a step of δ in h(0) moves the state by δ
    static double after(double e, double a) { return e * (2 * a + e); }
    const double* p;
    Quat operator()(const Quat& h, double n2, double& grow2, double& size2) const {
        grow2 = 4 * n2;
        size2 = n2;
        const double a2 = 2 * h.a;
        return {h.a * h.a - h.b * h.b - h.c * h.c - h.d * h.d + p[0], a2 * h.b + p[1], a2 * h.c + p[2], a2 * h.d + p[3]};
    }
    // The same for four states at once (escapeLanes), one per lane of the vectors.
    template <class V>
    void lanes(V& a, V& b, V& c, V& d, V n2, V& grow2, V& size2) const {
        grow2 = 4.0 * n2;
        size2 = n2;
        const V a2 = 2.0 * a;
        const V na = a * a - b * b - c * c - d * d + p[0];
        b = a2 * b + p[1];
        c = a2 * c + p[2];
        d = a2 * d + p[3];
        a = na;
    }
};

// Quaternion cube: h and h² share their vector's direction, so (a, v)³ = (a³ − 3a|v|², (3a² − |v|²)v);
// |d(h³)| ≤ 3|h|².
struct QuatCubeStep {
    static constexpr bool kExact = true;
    static constexpr double kStartGap = 1;
    static double after(double e, double a) { return e * (3 * a * a + e * (3 * a + e)); }
    const double* p;
    Quat operator()(const Quat& h, double n2, double& grow2, double& size2) const {
        grow2 = 9 * n2 * n2;
        size2 = n2;
        const double a2 = h.a * h.a, v2 = h.b * h.b + h.c * h.c + h.d * h.d, k = 3 * a2 - v2;
        return {h.a * (a2 - 3 * v2) + p[0], k * h.b + p[1], k * h.c + p[2], k * h.d + p[3]};
    }
    template <class V>
    void lanes(V& a, V& b, V& c, V& d, V n2, V& grow2, V& size2) const {
        grow2 = 9.0 * n2 * n2;
        size2 = n2;
        const V a2 = a * a, v2 = b * b + c * c + d * d, k = 3.0 * a2 - v2;
        a = a * (a2 - 3.0 * v2) + p[0];
        b = k * b + p[1];
        c = k * c + p[2];
        d = k * d + p[3];
    }
};

// Hypercomplex square (POV-Ray's hypercomplex cube squares too): each complex part squared, in real
// arithmetic; |f'| ≤ 2 max(|w1|, |w2|). c holds p's two complex parts. Its gaps are the larger of
// the parts' gaps: a step of δ in h(0) moves each part by at most √2·δ, and two states whose parts
// are within e of each other are within e in |h|² = (|w1|² + |w2|²) / 2.
struct HyperSqrStep {
    static constexpr bool kExact = true;
    static constexpr double kStartGap = 1.4142135623730951;
    static double after(double e, double a) { return e * (2 * a + e); }
    double c[4];
    Quat operator()(const Quat& w, double, double& grow2, double& size2) const {
        const double n1 = w.a * w.a + w.b * w.b, n2 = w.c * w.c + w.d * w.d;
        grow2 = 4 * std::max(n1, n2);
        size2 = std::max(n1, n2);
        return {w.a * w.a - w.b * w.b + c[0], 2 * w.a * w.b + c[1], w.c * w.c - w.d * w.d + c[2], 2 * w.c * w.d + c[3]};
    }
    template <class V>
    void lanes(V& a, V& b, V& x, V& y, V, V& grow2, V& size2) const {
        const V n1 = a * a + b * b, n2 = x * x + y * y, most = n1 > n2 ? n1 : n2;
        grow2 = 4.0 * most;
        size2 = most;
        const V na = a * a - b * b + c[0], nx = x * x - y * y + c[2];
        b = 2.0 * a * b + c[1];
        y = 2.0 * x * y + c[3];
        a = na;
        x = nx;
    }
};

// Any other hypercomplex function, through std::complex; grow2 only when asked (it costs f').
struct HyperAnyStep {
    static constexpr bool kExact = false;
    static constexpr double kStartGap = 1;
    static double after(double e, double) { return e; }
    JuliaFunction fn;
    const double* pw;
    Cx c1, c2;
    bool wantGrowth;
    Quat operator()(const Quat& w, double, double& grow2, double& size2) const {
        size2 = 0;
        const Cx w1(w.a, w.b), w2(w.c, w.d);
        grow2 = wantGrowth ? std::max(std::norm(juliaSlope(fn, w1, pw)), std::norm(juliaSlope(fn, w2, pw))) : 1;
        const Cx f1 = juliaComplex(fn, w1, pw) + c1, f2 = juliaComplex(fn, w2, pw) + c2;
        return {f1.real(), f1.imag(), f2.real(), f2.imag()};
    }
};

// |h|² of a state: the quaternion's norm, or (|w1|² + |w2|²) / 2 for the hypercomplex parts.
template <bool kHyper>
double stateNorm2(const Quat& h) {
    return kHyper ? 0.5 * qnorm2(h) : qnorm2(h);
}

// The distance from h(0) within which every state escapes too, for a state whose iterate k is
// the first outside the escape sphere, by gap = |h(k)| − R: a nearby state stays inside only if
// its iterate k is within gap of h(k). The gap after k steps from a start δ away, e(δ)
// (Step::after step by step over the sizes whose squares are sizes2[0..k)), grows faster than δ,
// so e(δ)/δ rises with δ; δ₀ = gap / e'(0) is then at least the distance sought and
// gap·δ₀ / e(δ₀) at most it: that is returned. slope is e'(0)/kStartGap, the product of the
// steps' derivative bounds. 0 when it cannot be told, or when δ₀ is below least (the caller's
// shortest step: no need to know more).
template <class Step>
double escapeReach(const double* sizes2, int k, double gap, double slope, double least) {
    const double d0 = gap / (Step::kStartGap * slope);
    if (!(d0 > least) || !std::isfinite(d0)) return 0;
    double e = Step::kStartGap * d0;
    for (int j = 0; j < k; ++j) e = Step::after(e, std::sqrt(sizes2[j]));
    const double reach = gap * d0 / e;
    return std::isfinite(reach) ? reach : 0;
}

// Whether the state h(0) stays within the escape sphere (|h|² ≤ r2) for count iterations. When it
// escapes, *reach gets a step along which no inside point lies: escapeReach for the exact steps
// (0 past kExactSteps iterations), else half the first-order distance to the sphere of the escaping
// iterate, (|h(k)| − R) / D(k), D(k) the product of the steps' derivative bounds. NaN counts as
// escaped. *margin gets max |h(k)| − R over the iterates looked at (up to the escaping one): ≤ 0
// exactly when inside, and continuous where a point crosses the surface (the crossing iterate
// passes R), which the crossing's refinement uses.
constexpr int kExactSteps = 64;

template <bool kHyper, class Step>
bool escapeLoop(Quat h, int count, double r2, double* reach, double least, double* margin, const Step& step) {
    double n2 = stateNorm2<kHyper>(h), slope2 = 1, most = n2;
    double sizes2[kExactSteps];
    bool in = true;
    for (int k = 0; k <= count; ++k) {
        most = std::max(most, n2);
        if (!(n2 <= r2)) {
            if (reach) {
                const double gap = std::sqrt(n2) - std::sqrt(r2);
                if (!std::isfinite(n2)) *reach = kInfinity;
                else if (!Step::kExact) *reach = 0.5 * gap / std::sqrt(slope2);
                else *reach = k <= kExactSteps ? escapeReach<Step>(sizes2, k, gap, std::sqrt(slope2), least) : 0;
            }
            most = std::isnan(n2) ? kInfinity : n2;
            in = false;
            break;
        }
        if (k == count) break;
        double grow2, size2;
        h = step(h, n2, grow2, size2);
        if (Step::kExact && k < kExactSteps) sizes2[k] = size2;
        slope2 *= grow2;
        n2 = stateNorm2<kHyper>(h);
    }
    if (margin) *margin = in ? std::min(-1e-300, std::sqrt(most) - std::sqrt(r2)) : std::max(std::sqrt(most) - std::sqrt(r2), 1e-300);
    return in;
}

// Whether h(0) stays within the escape sphere for max_iteration − 1 iterations (see escapeLoop;
// least: the reach below which the caller takes its shortest step anyway).
bool juliaIterate(const double* v, Quat h, double* reach, double* margin = nullptr, double least = 0) {
    const double* p = v + kJuliaP;
    const double r2 = v[kJuliaR2];
    const int count = int(v[kJuliaIter]) - 1;
    const JuliaFunction fn = JuliaFunction(int(v[kJuliaFn]));
    if (v[kJuliaAlgebra] == 0) {
        if (fn == JuliaFunction::Cube) return escapeLoop<false>(h, count, r2, reach, least, margin, QuatCubeStep{p});
        return escapeLoop<false>(h, count, r2, reach, least, margin, QuatSqrStep{p});
    }
    const Quat w = {h.a - h.d, h.b + h.c, h.a + h.d, h.b - h.c};
    if (fn == JuliaFunction::Sqr || fn == JuliaFunction::Cube)
        return escapeLoop<true>(w, count, r2, reach, least, margin, HyperSqrStep{{p[0] - p[3], p[1] + p[2], p[0] + p[3], p[1] - p[2]}});
    return escapeLoop<true>(w, count, r2, reach, least, margin,
                            HyperAnyStep{fn, v + kJuliaPwr, Cx(p[0] - p[3], p[1] + p[2]), Cx(p[0] + p[3], p[1] - p[2]),
                                         reach != nullptr});
}

bool juliaInside(const double* v, Vec3 p) { return juliaIterate(v, juliaStart(v, p), nullptr); }

// Four points of the march at once, in the lanes of vectors (GCC's vector extensions: AVX where
// the processor has it): their iterations are independent, so the four run side by side. Each
// lane's outcome is what escapeLoop gives for its point alone.
constexpr int kLanes = 4;
using LaneReal = double __attribute__((vector_size(kLanes * sizeof(double))));
using LaneMask = int64_t __attribute__((vector_size(kLanes * sizeof(int64_t))));  // comparisons: −1 or 0

struct LaneOutcome {
    bool in;
    double margin;  // escapeLoop's *margin
    int k;          // the escaping iterate (out lanes)
    double n2;      // its |h|²
    double slope2;  // the product of the derivative bounds up to it
};

// The exact steps only (kExact), and count < kExactSteps: lane l's sizes² are sizes2[j][l].
template <bool kHyper, class Step>
void escapeLanes(const Quat* start, int count, double r2, const Step& step, LaneOutcome* out,
                 double (*sizes2)[kLanes]) {
    LaneReal a, b, c, d;
    for (int l = 0; l < kLanes; ++l) a[l] = start[l].a, b[l] = start[l].b, c[l] = start[l].c, d[l] = start[l].d;
    auto norm2 = [](LaneReal a, LaneReal b, LaneReal c, LaneReal d) {
        const LaneReal n = a * a + b * b + c * c + d * d;
        return kHyper ? 0.5 * n : n;
    };
    const LaneReal r2s = LaneReal{} + r2;
    LaneReal n2 = norm2(a, b, c, d), most = n2, slope2 = LaneReal{} + 1.0;
    LaneMask live = LaneMask{} - 1;
    int escaped[kLanes];  // the escaping iterate, count + 1 while none has
    for (int l = 0; l < kLanes; ++l) escaped[l] = count + 1;
    for (int k = 0; k <= count; ++k) {
        // Lanes are frozen (not stepped) once out, so each keeps its escaping state; NaN is out.
        const LaneMask leaving = live & ~(n2 <= r2s);
        bool any = false;
        for (int l = 0; l < kLanes; ++l) {
            if (leaving[l]) escaped[l] = k;
            any |= escaped[l] > k;
        }
        live &= ~leaving;
        if (!any || k == count) break;
        LaneReal na = a, nb = b, nc = c, nd = d, grow2, size2;
        step.lanes(na, nb, nc, nd, n2, grow2, size2);
        for (int l = 0; l < kLanes; ++l) sizes2[k][l] = size2[l];
        const LaneReal m = norm2(na, nb, nc, nd);
        a = live ? na : a;
        b = live ? nb : b;
        c = live ? nc : c;
        d = live ? nd : d;
        slope2 = live ? slope2 * grow2 : slope2;
        n2 = live ? m : n2;
        most = live & (m > most) ? m : most;
    }
    const double radius = std::sqrt(r2);
    for (int l = 0; l < kLanes; ++l) {
        if (escaped[l] > count) {
            out[l] = {true, std::min(-1e-300, std::sqrt(most[l]) - radius), count, n2[l], slope2[l]};
        } else {
            const double m = std::isnan(n2[l]) ? kInfinity : n2[l];
            out[l] = {false, std::max(std::sqrt(m) - radius, 1e-300), escaped[l], n2[l], slope2[l]};
        }
    }
}

// escapeLoop's *reach for an out lane of escapeLanes.
template <class Step>
double laneReach(const LaneOutcome& o, double (*sizes2)[kLanes], int lane, double r2, double least) {
    if (!std::isfinite(o.n2)) return kInfinity;
    double own[kExactSteps];
    for (int j = 0; j < o.k; ++j) own[j] = sizes2[j][lane];
    return escapeReach<Step>(own, o.k, std::sqrt(o.n2) - std::sqrt(r2), std::sqrt(o.slope2), least);
}

// escapeLanes for one kind of step, with the reach of the last lane (when it is out; 0 otherwise).
template <class Step, bool kHyper>
void iterateLanes(const double* v, const Quat* start, const Step& step, LaneOutcome* out, double* lastReach,
                  double least) {
    double sizes2[kExactSteps][kLanes];
    const int count = int(v[kJuliaIter]) - 1;
    escapeLanes<kHyper>(start, count, v[kJuliaR2], step, out, sizes2);
    const LaneOutcome& last = out[kLanes - 1];
    *lastReach = last.in ? 0 : laneReach<Step>(last, sizes2, kLanes - 1, v[kJuliaR2], least);
}

// juliaIterate for four points (see iterateLanes). False (nothing done) for the functions without
// exact steps and for kExactSteps iterations or more.
bool juliaIterateLanes(const double* v, const Quat* h, LaneOutcome* out, double* lastReach, double least) {
    const double* p = v + kJuliaP;
    const int count = int(v[kJuliaIter]) - 1;
    const JuliaFunction fn = JuliaFunction(int(v[kJuliaFn]));
    if (count >= kExactSteps) return false;
    if (v[kJuliaAlgebra] == 0) {
        if (fn == JuliaFunction::Cube) iterateLanes<QuatCubeStep, false>(v, h, QuatCubeStep{p}, out, lastReach, least);
        else iterateLanes<QuatSqrStep, false>(v, h, QuatSqrStep{p}, out, lastReach, least);
        return true;
    }
    if (fn != JuliaFunction::Sqr && fn != JuliaFunction::Cube) return false;
    Quat w[kLanes];
    for (int l = 0; l < kLanes; ++l) w[l] = {h[l].a - h[l].d, h[l].b + h[l].c, h[l].a + h[l].d, h[l].b - h[l].c};
    iterateLanes<HyperSqrStep, true>(v, w, HyperSqrStep{{p[0] - p[3], p[1] + p[2], p[0] + p[3], p[1] - p[2]}}, out,
                                     lastReach, least);
    return true;
}

// The normal: the gradient of |h(max_iteration)| with respect to h(0)'s x, y and z components
// (POV-Ray's normals leave the slice's t alone: measured with a slice <1, 1, 0, 1>), by carrying
// the three derivatives along the iteration (rescaled each step; only the direction matters).
Vec3 juliaNormal(const double* v, Vec3 pt) {
    const int n = int(v[kJuliaIter]);
    const double* p = v + kJuliaP;
    Quat z = juliaStart(v, pt);
    Vec3 g;
    if (v[kJuliaAlgebra] == 0) {
        const bool cube = JuliaFunction(int(v[kJuliaFn])) == JuliaFunction::Cube;
        Quat t[3] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
        for (int k = 0; k < n && qnorm2(z) < 1e200; ++k) {
            const Quat s = qmul(z, z);
            double big = 0;
            for (Quat& d : t) {
                Quat e = cube ? qmul(s, d) : qmul(z, d);
                const Quat f = cube ? qmul(qmul(z, d), z) : qmul(d, z);
                const Quat h = cube ? qmul(d, s) : Quat{0, 0, 0, 0};
                d = {e.a + f.a + h.a, e.b + f.b + h.b, e.c + f.c + h.c, e.d + f.d + h.d};
                big = std::max(big, qnorm2(d));
            }
            if (big > 0 && std::isfinite(big))
                for (Quat& d : t) {
                    const double k2 = 1 / std::sqrt(big);
                    d = {d.a * k2, d.b * k2, d.c * k2, d.d * k2};
                }
            const Quat f = cube ? qmul(s, z) : s;
            z = {f.a + p[0], f.b + p[1], f.c + p[2], f.d + p[3]};
        }
        for (int a = 0; a < 3; ++a) g[a] = z.a * t[a].a + z.b * t[a].b + z.c * t[a].c + z.d * t[a].d;
        return g;
    }
    const JuliaFunction fn = JuliaFunction(int(v[kJuliaFn]));
    const Cx c1(p[0] - p[3], p[1] + p[2]), c2(p[0] + p[3], p[1] - p[2]);
    Cx w1(z.a - z.d, z.b + z.c), w2(z.a + z.d, z.b - z.c);
    // x, y, z of h(0) as (w1, w2) tangents: (1, 1), (i, i), (i, −i).
    Cx t1[3] = {Cx(1, 0), Cx(0, 1), Cx(0, 1)}, t2[3] = {Cx(1, 0), Cx(0, 1), Cx(0, -1)};
    for (int k = 0; k < n && std::norm(w1) + std::norm(w2) < 1e200; ++k) {
        const Cx s1 = juliaSlope(fn, w1, v + kJuliaPwr), s2 = juliaSlope(fn, w2, v + kJuliaPwr);
        double big = 0;
        for (int a = 0; a < 3; ++a) {
            t1[a] *= s1;
            t2[a] *= s2;
            big = std::max(big, std::norm(t1[a]) + std::norm(t2[a]));
        }
        if (big > 0 && std::isfinite(big))
            for (int a = 0; a < 3; ++a) t1[a] /= std::sqrt(big), t2[a] /= std::sqrt(big);
        w1 = juliaComplex(fn, w1, v + kJuliaPwr) + c1;
        w2 = juliaComplex(fn, w2, v + kJuliaPwr) + c2;
    }
    for (int a = 0; a < 3; ++a) g[a] = (w1 * std::conj(t1[a])).real() + (w2 * std::conj(t2[a])).real();
    return g;
}

// The crossing of the surface between lo and hi (margins glo and ghi of opposite states, see
// escapeLoop), narrowed to kJuliaTolerance by regula falsi on the margin (math/regula_falsi.h).
// Returns the end on hi's side.
double refineCrossing(const double* v, const Ray& r, double len, double lo, double glo, double hi, double ghi) {
    auto margin = [&](double t) {
        double g;
        juliaIterate(v, juliaStart(v, r.at(t)), nullptr, &g);
        return g;
    };
    illinoisBracket(margin, lo, glo, hi, ghi, [&](double a, double b) { return (b - a) * len > kJuliaTolerance; }, 60);
    return hi;
}

}  // namespace

// A box holding every inside point, proven with the reaches. The escape sphere's box is cut into
// kBoxCells³ cells; a cell is empty when it lies wholly outside the escape sphere (h(0) escapes at
// once) or when its centre escapes with a reach (a distance in h(0)'s four dimensions) beyond the
// cell's half diagonal as h(0) sees it (a step δ in x, y, z moves h(0) by at most δ/|n₄|, n the
// slice's unit normal); a cell neither empty nor with its centre inside is cut in eight, down to
// kBoxDepth times. The box is that of the cells not shown empty: first those whose centre is
// inside, then the others that reach out of it. Only for the exact steps, whose reach is a bound
// (escapeReach); else the escape sphere's box.
constexpr int kBoxCells = 16;
constexpr int kBoxDepth = 4;

struct BoxProof {
    const double* v;
    double radius;  // the escape sphere's
    double spread;  // 1/|n₄|: how far h(0) moves for a unit step in x, y, z

    bool outsideSphere(Vec3 lo, double size) const {
        Vec3 near;
        for (int a = 0; a < 3; ++a) near[a] = std::clamp(0.0, lo[a], lo[a] + size);
        return length(near) > radius;
    }
    // Whether the centre c is inside; else *empty tells whether the reach covers the cell. A centre
    // outside the escape sphere is first moved onto it (just inside), the cell's points then lying
    // as much further from it: those outside the sphere escape anyway, the others need the reach
    // of the iterates after the first, which a point outside cannot show.
    bool centreInside(Vec3 c, double size, bool* empty) const {
        double shift = 0;
        if (const double d = length(c); d >= radius * (1 - 1e-6)) {
            const Vec3 onto = c * (radius * (1 - 1e-6) / d);
            shift = length(c - onto);
            c = onto;
        }
        double reach = 0;
        if (juliaIterate(v, juliaStart(v, c), &reach, nullptr, 0)) return true;
        *empty = reach > (0.5 * std::sqrt(3.0) * size + shift) * spread * (1 + 1e-9);
        return false;
    }
    static bool within(const Bounds& box, Vec3 lo, double size) {
        return !box.empty() && lo.x >= box.lo.x && lo.y >= box.lo.y && lo.z >= box.lo.z && lo.x + size <= box.hi.x &&
               lo.y + size <= box.hi.y && lo.z + size <= box.hi.z;
    }
    void extend(Bounds& box, Vec3 lo, double size) const {
        box.extend(lo);
        box.extend(lo + Vec3(size));
    }
    // Adds to box the parts of the cell not shown empty.
    void collect(Vec3 lo, double size, int depth, Bounds& box) const {
        if (within(box, lo, size) || outsideSphere(lo, size)) return;
        bool empty = false;
        if (centreInside(lo + Vec3(0.5 * size), size, &empty) || (!empty && depth == 0)) return extend(box, lo, size);
        if (empty) return;
        const double half = 0.5 * size;
        for (int i = 0; i < 8; ++i) collect(lo + Vec3(i & 1 ? half : 0, i & 2 ? half : 0, i & 4 ? half : 0), half, depth - 1, box);
    }
};

Bounds provenBox(const double* v, double radius) {
    const Bounds whole{Vec3(-radius), Vec3(radius)};
    const JuliaFunction fn = JuliaFunction(int(v[kJuliaFn]));
    const bool exact = v[kJuliaAlgebra] == 0 || fn == JuliaFunction::Sqr || fn == JuliaFunction::Cube;
    if (!exact || int(v[kJuliaIter]) - 1 > kExactSteps) return whole;
    const BoxProof proof{v, std::sqrt(v[kJuliaR2]), 1 / std::fabs(v[kJuliaN + 3])};
    const double cell = 2 * radius / kBoxCells;
    auto cellLo = [&](int i, int j, int k) { return Vec3{-radius + i * cell, -radius + j * cell, -radius + k * cell}; };
    Bounds box;
    std::vector<int> open;  // the cells neither inside nor shown empty at once
    for (int i = 0; i < kBoxCells; ++i)
        for (int j = 0; j < kBoxCells; ++j)
            for (int k = 0; k < kBoxCells; ++k) {
                const Vec3 lo = cellLo(i, j, k);
                if (proof.outsideSphere(lo, cell)) continue;
                bool empty = false;
                if (proof.centreInside(lo + Vec3(0.5 * cell), cell, &empty)) proof.extend(box, lo, cell);
                else if (!empty) open.push_back((i * kBoxCells + j) * kBoxCells + k);
            }
    for (const int n : open) {
        const Vec3 lo = cellLo(n / (kBoxCells * kBoxCells), n / kBoxCells % kBoxCells, n % kBoxCells);
        const double half = 0.5 * cell;
        for (int i = 0; i < 8; ++i)
            proof.collect(lo + Vec3(i & 1 ? half : 0, i & 2 ? half : 0, i & 4 ? half : 0), half, kBoxDepth - 1, box);
    }
    return box.empty() ? whole : box;
}

bool makeJuliaFractal(const JuliaParams& q, ShapeData& data) {
    if (q.maxIteration < 2 || !(q.precision > 0)) return false;
    if (!q.hypercomplex && q.function != JuliaFunction::Sqr && q.function != JuliaFunction::Cube) return false;
    const double len = std::sqrt(q.slice[0] * q.slice[0] + q.slice[1] * q.slice[1] + q.slice[2] * q.slice[2] +
                                 q.slice[3] * q.slice[3]);
    if (!(len > 0) || q.slice[3] == 0) return false;
    std::vector<double>& v = data.values;
    v.assign(kJuliaSlots, 0.0);
    for (int i = 0; i < 4; ++i) v[kJuliaP + i] = q.p[i], v[kJuliaN + i] = q.slice[i] / len;
    v[kJuliaD] = q.distance;
    v[kJuliaIter] = q.maxIteration;
    v[kJuliaStep] = 1 / q.precision;
    const double pn = std::sqrt(q.p[0] * q.p[0] + q.p[1] * q.p[1] + q.p[2] * q.p[2] + q.p[3] * q.p[3]);
    const double r = q.hypercomplex ? 4.0 : 1 + pn;
    v[kJuliaR2] = r * r;
    v[kJuliaAlgebra] = q.hypercomplex ? 1 : 0;
    v[kJuliaFn] = double(int(q.function));
    v[kJuliaPwr] = q.pwr[0];
    v[kJuliaPwr + 1] = q.pwr[1];
    data.bounds = provenBox(v.data(), r * (1 + 1e-9));
    return true;
}

bool hitJuliaFractal(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const double* v = o.data->values.data();
    // The ray's stretch inside the escape sphere |(x, y, z)| ≤ R (h(0) lies outside the 4-D sphere
    // beyond it), widened a little so that its points are outside (for p = 0 the fractal's surface
    // is the sphere itself).
    const double dd = dot(r.dir, r.dir), b = dot(r.origin, r.dir), cc = dot(r.origin, r.origin) - v[kJuliaR2] * (1 + 1e-9);
    const double disc = b * b - dd * cc;
    if (disc <= 0) return false;
    const double sq = std::sqrt(disc);
    double t0 = std::max(tMin, (-b - sq) / dd), t1 = std::min(tMax, (-b + sq) / dd);
    if (t0 >= t1) return false;
    const double len = std::sqrt(dd), step = v[kJuliaStep] / len;
    // Outside the proven box every point is outside: the march starts at its last point before
    // the box (so that its points stay those of the march from t0) and ends where the ray leaves it.
    double bIn = t0, bOut = t1;
    if (!clipRayToBox(o.data->bounds, r, bIn, bOut)) return false;
    t0 += std::floor((bIn - t0) / step) * step;
    t1 = bOut;
    // Steps of 1/precision, longer where the point's iterate escaped far (juliaIterate's reach, a
    // distance in h(0)'s four dimensions: a unit of t moves h(0) by len4, its t component too).
    const double* n = v + kJuliaN;
    const double dw = (n[0] * r.dir.x + n[1] * r.dir.y + n[2] * r.dir.z) / n[3], len4 = std::sqrt(dd + dw * dw);
    double reach = 0, margin = 0;
    const double least = v[kJuliaStep];  // reaches below one step make no difference
    const bool startIn = juliaIterate(v, juliaStart(v, r.at(t0)), &reach, &margin, least);
    // A whole number of steps, at least one: the points looked at are those of the march of
    // single steps from t0 (which POV-Ray's precision describes), less those a reach shows are
    // outside, so the crossings found are that march's.
    auto stepsAhead = [&](double r) { return step * std::max(1.0, std::floor(r / len4 / step)); };
    auto crossing = [&](double lo, double glo, double t, double gt) {
        const double hi = refineCrossing(v, r, len, lo, glo, t, gt);
        if (!(hi > tMin && hi < tMax)) return false;
        h.t = hi;
        Vec3 n = juliaNormal(v, r.at(hi));
        if (!(length(n) > 0)) n = -r.dir;
        h.normal = normalize(n);
        return true;
    };
    double prev = t0, prevMargin = margin, ahead = startIn ? step : stepsAhead(reach);
    bool lanes = true;  // while the fractal's steps can run four points at once
    while (prev < t1) {
        if (lanes && ahead == step && prev + kLanes * step < t1) {
            // Single steps: the next four points at once. Every point of the march is looked at
            // then (the plain march's), so the first on the other side is the crossing's.
            Quat starts[kLanes];
            double ts[kLanes];
            for (int l = 0; l < kLanes; ++l) {
                ts[l] = (l ? ts[l - 1] : prev) + step;
                starts[l] = juliaStart(v, r.at(ts[l]));
            }
            LaneOutcome out[kLanes];
            lanes = juliaIterateLanes(v, starts, out, &reach, least);
            if (lanes) {
                for (int l = 0; l < kLanes; ++l) {
                    if (out[l].in == startIn) continue;
                    return crossing(l ? ts[l - 1] : prev, l ? out[l - 1].margin : prevMargin, ts[l], out[l].margin);
                }
                prev = ts[kLanes - 1];
                prevMargin = out[kLanes - 1].margin;
                ahead = stepsAhead(reach);  // 0 when the lanes are inside
                continue;
            }
        }
        const double t = std::min(t1, prev + ahead);
        reach = 0;
        const bool in = juliaIterate(v, juliaStart(v, r.at(t)), startIn ? nullptr : &reach, &margin, least);
        if (in != startIn) return crossing(prev, prevMargin, t, margin);
        prev = t;
        prevMargin = margin;
        ahead = stepsAhead(reach);
    }
    return false;  // no crossing (no inside point reaches the widened sphere)
}

bool insideJuliaFractal(const Object& o, Vec3 p) { return juliaInside(o.data->values.data(), p); }

}  // namespace rays
