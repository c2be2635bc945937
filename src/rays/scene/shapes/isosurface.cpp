// The isosurface's hit: the ray's span inside the container, then a march that uses max_gradient
// G as a Lipschitz bound — where |f − threshold| = v, no surface lies closer than v / G, so the
// march steps that far (at least `accuracy`, and at most kMaxSteps steps over the span) and never
// steps over a crossing when G is right — then bisection of the step that changed sign until it
// is shorter than accuracy / 16 (the hit is its far end, so that the next search from it, by CSG
// or a ray going on, does not find the same crossing again). This is the textbook Lipschitz
// "sphere tracing" (Hart 1996) on a line, each step first tried 1.6 times as long and kept when
// the two ends prove the longer stretch empty (Keinert et al. 2014), not POV-Ray's own
// subdivision; the reference (3.4.5.1.6) gives the keywords' meaning. The normal is the
// function's gradient by central differences (gradientStep: the accuracy, within [1e-6, 0.01]).
// The function runs on this thread's fn::Scratch, grown once per thread to the largest
// isosurface's frame: no allocation per ray.
#include "rays/scene/shapes/isosurface.h"

#include <algorithm>
#include <cmath>

#include "rays/fn/compile.h"
#include "rays/fn/machine.h"

namespace rays {

namespace {

enum : size_t { kAccuracy, kMaxGradient, kSphere, kValues };

constexpr int kMaxSteps = 4096;   // march steps over the container span at most (a grazing ray's cost)
constexpr int kMaxBisections = 64;
constexpr double kOverStep = 1.6;  // the over-relaxed step, in plain steps

// f − threshold at p on this thread's scratch.
double value(const Object& o, Vec3 p) {
    thread_local fn::Scratch scratch;
    const fn::Program& f = *o.data->function;
    if (!scratch.fitsScalar(f)) scratch.fit(f);
    double args[fn::kMaxParams] = {p.x, p.y, p.z};
    return fn::eval(f, args, scratch) - o.r1;
}

// The ray's span [t0, t1] inside the container and the container's outward normals there.
bool containerSpan(const Object& o, const Ray& r, double& t0, double& t1, Vec3& n0, Vec3& n1) {
    if (o.data->values[kSphere] != 0) {
        const Vec3 oc = r.origin - o.p0;
        const double a = dot(r.dir, r.dir), b = dot(oc, r.dir), c = dot(oc, oc) - o.r0 * o.r0;
        const double disc = b * b - a * c;
        if (!(disc > 0) || a == 0) return false;
        const double sq = std::sqrt(disc);
        t0 = (-b - sq) / a;
        t1 = (-b + sq) / a;
        n0 = r.at(t0) - o.p0;
        n1 = r.at(t1) - o.p0;
        return true;
    }
    t0 = -kInfinity;
    t1 = kInfinity;
    for (int i = 0; i < 3; ++i) {
        const double d = r.dir[i], p = r.origin[i];
        if (d == 0) {
            if (p < o.p0[i] || p > o.p1[i]) return false;
            continue;
        }
        double a = (o.p0[i] - p) / d, b = (o.p1[i] - p) / d;
        Vec3 na, nb;
        na[i] = -1;
        nb[i] = 1;
        if (a > b) std::swap(a, b), std::swap(na, nb);
        if (a > t0) t0 = a, n0 = na;
        if (b < t1) t1 = b, n1 = nb;
    }
    return t0 < t1;
}

// The central-difference step of the gradient: the accuracy, kept within [1e-6, 0.01].
double gradientStep(const Object& o) { return std::clamp(o.data->values[kAccuracy], 1e-6, 0.01); }

// The outward unit normal at p: the gradient of f (f grows outwards); -dir where it vanishes.
Vec3 gradientNormal(const Object& o, Vec3 p, Vec3 dir) {
    const double e = gradientStep(o);
    const Vec3 g{value(o, p + Vec3{e, 0, 0}) - value(o, p - Vec3{e, 0, 0}),
                 value(o, p + Vec3{0, e, 0}) - value(o, p - Vec3{0, e, 0}),
                 value(o, p + Vec3{0, 0, e}) - value(o, p - Vec3{0, 0, e})};
    const double len = length(g);
    return len > 0 && std::isfinite(len) ? g / len : normalize(-dir);
}

}  // namespace

bool makeIsosurface(const IsosurfaceSpec& spec, Object& o, ShapeData& data) {
    if (!spec.function) return false;
    o.type = ShapeType::Isosurface;
    o.r1 = spec.threshold;
    o.open = spec.open;
    data.function = spec.function;
    data.values.assign(kValues, 0.0);
    data.values[kAccuracy] = spec.accuracy > 0 ? spec.accuracy : 0.001;
    data.values[kMaxGradient] = spec.maxGradient > 0 ? spec.maxGradient : 1.1;
    data.values[kSphere] = spec.sphere ? 1 : 0;
    if (spec.sphere) {
        o.p0 = spec.centre;
        o.r0 = std::fabs(spec.radius);
        data.bounds = Bounds{o.p0 - Vec3(o.r0), o.p0 + Vec3(o.r0)};
        return o.r0 > 0;
    }
    o.p0 = vmin(spec.lo, spec.hi);
    o.p1 = vmax(spec.lo, spec.hi);
    data.bounds = Bounds{o.p0, o.p1};
    return o.p0.x < o.p1.x && o.p0.y < o.p1.y && o.p0.z < o.p1.z;
}

double isosurfaceValue(const Object& o, Vec3 p) { return value(o, p); }

bool hitIsosurface(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    double t0, t1;
    Vec3 n0, n1;
    if (!containerSpan(o, r, t0, t1, n0, n1)) return false;
    double a = std::max(t0, tMin);
    const double end = std::min(t1, tMax);
    if (!(a < end)) return false;
    double va = value(o, r.at(a));
    if (t0 > tMin && !o.open && va < 0) {  // the container's face, where the function is inside
        h.t = t0;
        h.normal = normalize(n0);
        return true;
    }
    const double len = length(r.dir);
    const double accuracy = o.data->values[kAccuracy];
    const double g = o.data->values[kMaxGradient] * len;  // the bound per unit of t
    const double minStep = std::max(accuracy / len, (end - a) / kMaxSteps);
    for (;;) {
        double step = std::fabs(va) / g;  // NaN (sqrt of a negative number, say) steps the least
        if (!(step > minStep)) {
            step = minStep;
        } else if (a + kOverStep * step < end) {
            // Over-relaxed (Keinert et al., "Enhanced Sphere Tracing", 2014): a step kOverStep
            // times as long is kept when both ends, of one sign, are too far from 0 for a
            // crossing between them (|va| + |vb| > G·(b − a)); else the plain step is taken.
            const double b = a + kOverStep * step, vb = value(o, r.at(b));
            if ((va < 0) == (vb < 0) && std::fabs(va) + std::fabs(vb) > g * (b - a)) {
                a = b;
                va = vb;
                continue;
            }
        }
        const double b = a + step < end ? a + step : end;
        const double vb = value(o, r.at(b));
        if ((va < 0) != (vb < 0)) {
            double lo = a, hi = b;
            for (int i = 0; i < kMaxBisections && (hi - lo) * len > accuracy / 16; ++i) {
                const double m = 0.5 * (lo + hi);
                if ((value(o, r.at(m)) < 0) == (va < 0)) lo = m;
                else hi = m;
            }
            h.t = hi;
            h.normal = gradientNormal(o, r.at(hi), r.dir);
            return true;
        }
        a = b;
        va = vb;
        if (b >= end) break;
    }
    if (t1 < tMax && !o.open && va < 0) {  // leaving through the container's face while inside
        h.t = t1;
        h.normal = normalize(n1);
        return true;
    }
    return false;
}

bool insideIsosurface(const Object& o, Vec3 p) {
    if (o.data->values[kSphere] != 0) {
        if (!(dot(p - o.p0, p - o.p0) < o.r0 * o.r0)) return false;
    } else if (!(p.x >= o.p0.x && p.x <= o.p1.x && p.y >= o.p0.y && p.y <= o.p1.y && p.z >= o.p0.z && p.z <= o.p1.z)) {
        return false;
    }
    return value(o, p) <= 0;  // closed, and so is the box, as POV-Ray 3.7's inside() (measured)
}

}  // namespace rays
