#include "rays/scene/text_shape.h"

#include <algorithm>
#include <cmath>

namespace rays {

namespace {

double lerp(double a, double b, double s) { return a + s * (b - a); }

// Point of segment g at parameter s.
void segmentPoint(const TextSegment& g, double s, double& x, double& y) {
    if (!g.quad) {
        x = lerp(g.ax, g.bx, s);
        y = lerp(g.ay, g.by, s);
        return;
    }
    const double u = 1 - s;
    x = u * u * g.ax + 2 * s * u * g.cx + s * s * g.bx;
    y = u * u * g.ay + 2 * s * u * g.cy + s * s * g.by;
}

// Roots of a s² + b s + c in [0, 1] (a tiny slack kept, then clamped); returns how many.
int rootsInUnit(double a, double b, double c, double out[2]) {
    constexpr double kSlack = 1e-9;
    double r[2];
    int n = 0;
    const double scale = std::fabs(a) + std::fabs(b) + std::fabs(c);
    if (scale == 0) return 0;
    if (std::fabs(a) <= 1e-12 * scale) {
        if (b == 0) return 0;
        r[n++] = -c / b;
    } else {
        const double disc = b * b - 4 * a * c;
        if (disc < 0) return 0;
        // The stable pair of roots (Numerical Recipes, "Quadratic and Cubic Equations").
        const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
        r[n++] = q / a;
        if (q != 0) r[n++] = c / q;
    }
    int k = 0;
    for (int i = 0; i < n; ++i)
        if (r[i] >= -kSlack && r[i] <= 1 + kSlack) out[k++] = std::clamp(r[i], 0.0, 1.0);
    return k;
}

// The ray's parameter interval inside box [lo, hi] (slab test with the ray's 1/dir), narrowed
// from [t0, t1].
bool slab(const Ray& r, Vec3 invDir, Vec3 lo, Vec3 hi, double& t0, double& t1) {
    for (int a = 0; a < 3; ++a) {
        if (r.dir[a] == 0) {
            if (r.origin[a] < lo[a] || r.origin[a] > hi[a]) return false;
            continue;
        }
        double n = (lo[a] - r.origin[a]) * invDir[a], f = (hi[a] - r.origin[a]) * invDir[a];
        if (n > f) std::swap(n, f);
        t0 = std::max(t0, n);
        t1 = std::min(t1, f);
        if (t0 > t1) return false;
    }
    return true;
}

// Walls and caps of glyph g: the nearest hit in (tMin, best) lowers best and sets normal.
// boxTest: whether the ray is first tested against the glyph's box (not needed for a lone glyph:
// the text's box is its box).
bool hitGlyph(const TextShape& s, const TextGlyph& g, const Ray& r, Vec3 invDir, bool boxTest, double tMin,
              double& best, Vec3& normal) {
    const double z1 = g.z0 + s.thickness;
    double t0 = tMin, t1 = best;
    if (boxTest && !slab(r, invDir, Vec3{g.xMin, g.yMin, g.z0}, Vec3{g.xMax, g.yMax, z1}, t0, t1)) return false;
    bool found = false;
    // Caps: the planes z0 (normal −z) and z1 (normal +z) where the point is inside the outline.
    if (r.dir.z != 0) {
        for (int i = 0; i < 2; ++i) {
            const double t = ((i ? z1 : g.z0) - r.origin.z) / r.dir.z;
            if (!(t > tMin && t < best)) continue;
            const double x = r.origin.x + t * r.dir.x, y = r.origin.y + t * r.dir.y;
            if (x < g.xMin || x > g.xMax || y < g.yMin || y > g.yMax || glyphWinding(s, g, x, y) == 0) continue;
            best = t;
            normal = Vec3{0, 0, i ? 1.0 : -1.0};
            found = true;
        }
    }
    // Walls: where the ray's x-y projection crosses a segment, within the glyph's depth.
    const double dx = r.dir.x, dy = r.dir.y, dd = dx * dx + dy * dy;
    if (dd == 0) return found;
    const double ox = r.origin.x, oy = r.origin.y;
    const double nx = -dy, ny = dx;  // f(P) = n·(P − o) is zero on the projected ray
    for (uint32_t k = g.first; k < g.first + g.count; ++k) {
        const TextSegment& e = s.segments[k];
        const double fa = nx * (e.ax - ox) + ny * (e.ay - oy);
        const double fb = nx * (e.bx - ox) + ny * (e.by - oy);
        double roots[2];
        int n = 0;
        if (!e.quad) {
            if ((fa > 0 && fb > 0) || (fa < 0 && fb < 0) || fa == fb) continue;
            roots[n++] = fa / (fa - fb);
        } else {
            const double fc = nx * (e.cx - ox) + ny * (e.cy - oy);
            if ((fa > 0 && fb > 0 && fc > 0) || (fa < 0 && fb < 0 && fc < 0)) continue;  // hull on one side
            n = rootsInUnit(fa - 2 * fc + fb, 2 * (fc - fa), fa, roots);
        }
        for (int i = 0; i < n; ++i) {
            double px, py;
            segmentPoint(e, roots[i], px, py);
            const double t = ((px - ox) * dx + (py - oy) * dy) / dd;
            if (!(t > tMin && t < best)) continue;
            const double z = r.origin.z + t * r.dir.z;
            if (z < g.z0 || z > z1) continue;
            const double u = roots[i];
            const double tx = e.quad ? (1 - u) * (e.cx - e.ax) + u * (e.bx - e.cx) : e.bx - e.ax;
            const double ty = e.quad ? (1 - u) * (e.cy - e.ay) + u * (e.by - e.cy) : e.by - e.ay;
            if (tx == 0 && ty == 0) continue;
            best = t;
            normal = normalize(Vec3{ty, -tx, 0});  // the filled side is on the left: outward is right
            found = true;
        }
    }
    return found;
}

// Glyphs [begin, end) whose x range may meet [xLo, xHi].
void glyphRange(const TextShape& s, double xLo, double xHi, size_t& begin, size_t& end) {
    begin = size_t(std::lower_bound(s.xMaxPrefix.begin(), s.xMaxPrefix.end(), xLo) - s.xMaxPrefix.begin());
    end = size_t(std::upper_bound(s.glyphs.begin(), s.glyphs.end(), xHi,
                                  [](double x, const TextGlyph& g) { return x < g.xMin; }) -
                 s.glyphs.begin());
}

// A quadratic Bézier already monotone in y, added as it is to the glyph being built.
void addMonotoneQuad(TextShape& shape, double ax, double ay, double cx, double cy, double bx, double by) {
    if (ax == bx && ay == by) return;
    shape.segments.push_back(TextSegment{ax, ay, cx, cy, bx, by, true});
    ++shape.glyphs.back().count;
}

}  // namespace

void TextShape::addLine(double ax, double ay, double bx, double by) {
    if (ax == bx && ay == by) return;
    segments.push_back(TextSegment{ax, ay, 0, 0, bx, by, false});
    ++glyphs.back().count;
}

void TextShape::addQuad(double ax, double ay, double cx, double cy, double bx, double by) {
    const double den = ay - 2 * cy + by;
    const double s = den != 0 ? (ay - cy) / den : -1;  // where dy/ds = 0
    if (s > 0 && s < 1) {  // de Casteljau split into two pieces monotone in y
        const double p01x = lerp(ax, cx, s), p01y = lerp(ay, cy, s);
        const double p12x = lerp(cx, bx, s), p12y = lerp(cy, by, s);
        const double mx = lerp(p01x, p12x, s), my = lerp(p01y, p12y, s);
        // The tangent at the split is level, so both new control points lie at its height:
        // written so, each piece is exactly monotone and is kept as it is. (Splitting the pieces
        // again, as before, could find a turning point in (0, 1) from rounding every time and
        // recurse until the stack ran out: fuzz finding 28.)
        addMonotoneQuad(*this, ax, ay, p01x, my, mx, my);
        addMonotoneQuad(*this, mx, my, p12x, my, bx, by);
        return;
    }
    addMonotoneQuad(*this, ax, ay, cx, cy, bx, by);
}

void TextShape::finish() {
    std::vector<TextGlyph> kept;
    bounds = Bounds{};
    for (TextGlyph g : glyphs) {
        if (g.count == 0) continue;
        g.xMin = g.yMin = kInfinity;
        g.xMax = g.yMax = -kInfinity;
        for (uint32_t k = g.first; k < g.first + g.count; ++k) {
            const TextSegment& e = segments[k];
            // A quadratic Bézier lies in the hull of its three points.
            const double xs[3] = {e.ax, e.bx, e.quad ? e.cx : e.ax}, ys[3] = {e.ay, e.by, e.quad ? e.cy : e.ay};
            for (int i = 0; i < 3; ++i) {
                g.xMin = std::min(g.xMin, xs[i]), g.xMax = std::max(g.xMax, xs[i]);
                g.yMin = std::min(g.yMin, ys[i]), g.yMax = std::max(g.yMax, ys[i]);
            }
        }
        bounds.extend(Vec3{g.xMin, g.yMin, g.z0});
        bounds.extend(Vec3{g.xMax, g.yMax, g.z0 + thickness});
        kept.push_back(g);
    }
    std::stable_sort(kept.begin(), kept.end(), [](const TextGlyph& a, const TextGlyph& b) { return a.xMin < b.xMin; });
    glyphs = std::move(kept);
    xMaxPrefix.resize(glyphs.size());
    double m = -kInfinity;
    for (size_t i = 0; i < glyphs.size(); ++i) xMaxPrefix[i] = m = std::max(m, glyphs[i].xMax);
}

int glyphWinding(const TextShape& s, const TextGlyph& g, double x, double y) {
    int w = 0;
    for (uint32_t k = g.first; k < g.first + g.count; ++k) {
        const TextSegment& e = s.segments[k];
        if (e.ay == e.by) continue;  // flat (monotone pieces: a flat curve is a flat line)
        const bool up = e.by > e.ay;
        const double lo = up ? e.ay : e.by, hi = up ? e.by : e.ay;
        if (y < lo || y >= hi) continue;  // half-open, so a shared end point counts once
        double xc;
        if (!e.quad) {
            xc = e.ax + (y - e.ay) / (e.by - e.ay) * (e.bx - e.ax);
        } else {
            double roots[2];
            const int n = rootsInUnit(e.ay - 2 * e.cy + e.by, 2 * (e.cy - e.ay), e.ay - y, roots);
            if (n == 0) continue;
            double yy;
            segmentPoint(e, roots[0], xc, yy);
        }
        if (xc > x) w += up ? 1 : -1;
    }
    return w;
}

bool intersectText(const TextShape& s, const Ray& r, double tMin, double tMax, double& t, Vec3& normal) {
    double t0 = tMin, t1 = tMax;
    const Vec3 invDir{1 / r.dir.x, 1 / r.dir.y, 1 / r.dir.z};
    if (s.glyphs.empty() || !slab(r, invDir, s.bounds.lo, s.bounds.hi, t0, t1)) return false;
    const double xa = r.origin.x + t0 * r.dir.x, xb = r.origin.x + t1 * r.dir.x;
    size_t begin, end;
    glyphRange(s, std::min(xa, xb), std::max(xa, xb), begin, end);
    double best = tMax;
    bool found = false;
    const bool boxTest = s.glyphs.size() > 1;
    for (size_t i = begin; i < end; ++i) found = hitGlyph(s, s.glyphs[i], r, invDir, boxTest, tMin, best, normal) || found;
    if (found) t = best;
    return found;
}

bool insideText(const TextShape& s, Vec3 p) {
    size_t begin, end;
    glyphRange(s, p.x, p.x, begin, end);
    for (size_t i = begin; i < end; ++i) {
        const TextGlyph& g = s.glyphs[i];
        if (p.x <= g.xMin || p.x >= g.xMax || p.y <= g.yMin || p.y >= g.yMax) continue;
        if (p.z <= g.z0 || p.z >= g.z0 + s.thickness) continue;
        if (glyphWinding(s, g, p.x, p.y) != 0) return true;
    }
    return false;
}

}  // namespace rays
