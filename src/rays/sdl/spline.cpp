// Spline values: `spline { [type] t, <p>, ... }` and their evaluation (POV-Ray 3.7 reference,
// "Spline"). Parameters need not be in order; a repeated parameter replaces the earlier point;
// outside the range the end points hold (for cubic splines the second and next-to-last).
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "rays/sdl/frames.h"
#include "rays/sdl/interpreter.h"

namespace rays::sdl {

namespace {
using P = std::array<double, 5>;

P lerp(const P& a, const P& b, double s) {
    P r;
    for (int i = 0; i < 5; ++i) r[i] = a[i] + (b[i] - a[i]) * s;
    return r;
}

// Quadratic through three points (Lagrange form in the spline parameter).
P quadratic(const Spline& sp, size_t i0, double t) {
    const double t0 = sp.t[i0], t1 = sp.t[i0 + 1], t2 = sp.t[i0 + 2];
    const double l0 = (t - t1) * (t - t2) / ((t0 - t1) * (t0 - t2));
    const double l1 = (t - t0) * (t - t2) / ((t1 - t0) * (t1 - t2));
    const double l2 = (t - t0) * (t - t1) / ((t2 - t0) * (t2 - t1));
    P r;
    for (int k = 0; k < 5; ++k) r[k] = l0 * sp.points[i0][k] + l1 * sp.points[i0 + 1][k] + l2 * sp.points[i0 + 2][k];
    return r;
}

// Cubic Hermite segment between points i and i+1 with Catmull-Rom tangents from the neighbours.
P cubic(const Spline& sp, size_t i, double t) {
    const double ta = sp.t[i - 1], t0 = sp.t[i], t1 = sp.t[i + 1], tb = sp.t[i + 2];
    const double h = t1 - t0, s = (t - t0) / h;
    const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
    const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
    P r;
    for (int k = 0; k < 5; ++k) {
        const double m0 = (sp.points[i + 1][k] - sp.points[i - 1][k]) / (t1 - ta) * h;
        const double m1 = (sp.points[i + 2][k] - sp.points[i][k]) / (tb - t0) * h;
        r[k] = h00 * sp.points[i][k] + h10 * m0 + h01 * sp.points[i + 1][k] + h11 * m1;
    }
    return r;
}

// Natural cubic spline (second derivative 0 at both ends), solved per component.
P natural(const Spline& sp, double t) {
    const size_t n = sp.t.size();
    size_t i = size_t(std::upper_bound(sp.t.begin(), sp.t.end(), t) - sp.t.begin());
    i = std::clamp<size_t>(i, 1, n - 1) - 1;
    P r;
    std::vector<double> m(n), a(n), b(n), c(n), d(n);
    for (int k = 0; k < 5; ++k) {
        std::fill(m.begin(), m.end(), 0.0);
        for (size_t j = 1; j + 1 < n; ++j) {
            const double h0 = sp.t[j] - sp.t[j - 1], h1 = sp.t[j + 1] - sp.t[j];
            a[j] = h0;
            b[j] = 2 * (h0 + h1);
            c[j] = h1;
            d[j] = 6 * ((sp.points[j + 1][k] - sp.points[j][k]) / h1 - (sp.points[j][k] - sp.points[j - 1][k]) / h0);
        }
        for (size_t j = 2; j + 1 < n; ++j) {  // Thomas algorithm
            const double w = a[j] / b[j - 1];
            b[j] -= w * c[j - 1];
            d[j] -= w * d[j - 1];
        }
        for (size_t j = n - 2; j >= 1; --j) {
            m[j] = (d[j] - (j + 2 < n ? c[j] * m[j + 1] : 0.0)) / b[j];
            if (j == 1) break;
        }
        const double h = sp.t[i + 1] - sp.t[i];
        const double u = sp.t[i + 1] - t, w = t - sp.t[i];
        r[k] = m[i] * u * u * u / (6 * h) + m[i + 1] * w * w * w / (6 * h) +
               (sp.points[i][k] / h - m[i] * h / 6) * u + (sp.points[i + 1][k] / h - m[i + 1] * h / 6) * w;
    }
    return r;
}
}  // namespace

std::array<double, 5> evaluateSpline(const Spline& sp, Spline::Type type, double t) {
    const size_t n = sp.t.size();
    if (n == 0) return {};
    if (n == 1) return sp.points[0];
    if (type == Spline::Type::Cubic && n < 4) type = Spline::Type::Natural;
    if (type == Spline::Type::Quadratic && n < 3) type = Spline::Type::Linear;
    size_t lo = 0, hi = n - 1;
    if (type == Spline::Type::Cubic) {
        lo = 1;
        hi = n - 2;
    }
    if (t <= sp.t[lo]) return sp.points[lo];
    if (t >= sp.t[hi]) return sp.points[hi];
    size_t i = size_t(std::upper_bound(sp.t.begin(), sp.t.end(), t) - sp.t.begin()) - 1;  // t in [t_i, t_i+1)
    switch (type) {
        case Spline::Type::Linear:
            return lerp(sp.points[i], sp.points[i + 1], (t - sp.t[i]) / (sp.t[i + 1] - sp.t[i]));
        case Spline::Type::Quadratic:
            return quadratic(sp, std::min(i, n - 3), t);
        case Spline::Type::Cubic:
            return cubic(sp, i, t);
        case Spline::Type::Natural:
            return natural(sp, t);
    }
    return {};
}

Value Interpreter::parseSplineBlock() {
    const Loc at = loc();
    next();  // spline
    expectSym('{', "after 'spline'");
    auto sp = std::make_shared<Spline>();
    if (const Binding* b = identBinding(); b && b->value.type == VType::Spline) {
        *sp = b->value.spline();
        next();
    } else if (b && b->value.type == VType::Array && b->value.arr().elemType == VType::Spline) {
        // `spline { A[i] }`: a spline of an array of splines (meshmaker.inc's MSM does so).
        const Value arr = b->value;
        const Loc eAt = loc();
        next();
        const Value e = arrayElement(arr, false, nullptr);
        if (e.type != VType::Spline) error(eAt, "expected a spline, found " + std::string(typeName(e.type)));
        *sp = e.spline();
    }
    const char* const counted = "array elements and spline points made (new and copied)";
    spend(arrayElements_, sp->t.size(), limits_.arrayElements, at, counted);  // spline { S ... } in a loop
    int widest = sp->t.empty() ? 0 : sp->dim;
    std::vector<std::pair<double, P>> pts;
    std::unordered_map<double, size_t> index;  // a point at a time already given replaces it (NaN never matches)
    for (size_t i = 0; i < sp->t.size(); ++i) {
        index.emplace(sp->t[i], pts.size());
        pts.emplace_back(sp->t[i], sp->points[i]);
    }
    for (;;) {
        if (isSym('}')) break;
        if (atEnd()) error(at, "'{' of 'spline' is never closed (end of file reached)");
        switch (kw()) {
            case Kw::linear_spline: sp->type = Spline::Type::Linear; next(); continue;
            case Kw::quadratic_spline: sp->type = Spline::Type::Quadratic; next(); continue;
            case Kw::cubic_spline: sp->type = Spline::Type::Cubic; next(); continue;
            case Kw::natural_spline: sp->type = Spline::Type::Natural; next(); continue;
            default: break;
        }
        const double t = parseFloat();
        acceptSym(',');
        const Loc pAt = loc();
        const Value p = parseNumeric(false);
        if (!p.isNumeric()) error(pAt, "a spline point must be a vector");
        P c{};
        if (p.type == VType::Float) c.fill(p.c[0]);
        else for (int k = 0; k < p.dim; ++k) c[k] = p.c[k];
        if (p.type != VType::Float) widest = std::max(widest, int(p.dim));
        if (auto same = index.find(t); same != index.end()) {
            pts[same->second].second = c;
        } else {
            spend(arrayElements_, 1, limits_.arrayElements, pAt, counted);
            index.emplace(t, pts.size());
            pts.emplace_back(t, c);
        }
        acceptSym(',');
    }
    next();
    sp->dim = widest >= 2 ? widest : 3;
    // NaN times (sqrt(-1)) go last: a < b alone is no ordering once a NaN is among them.
    std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) {
        return !std::isnan(a.first) && (std::isnan(b.first) || a.first < b.first);
    });
    sp->t.clear();
    sp->points.clear();
    for (auto& [t, p] : pts) {
        sp->t.push_back(t);
        sp->points.push_back(p);
    }
    return Value::spline(std::move(sp));
}

}  // namespace rays::sdl
