// OriginBuffer construction: each bound is projected onto the six faces of the cube around the
// origin (a rectangle of cells per face), listed in the cells of the fine or the coarse level, and
// each cell's list is sorted by distance.
//
// Face f has major axis m = f / 2 and sign s (+ for even f); a direction d with |d_m| largest and
// sign(d_m) = s lies on it at a = d_u / |d_m|, b = d_v / |d_m| in [-1, 1] (u < v the other two
// axes), in cell (floor((a + 1) n / 2), floor((b + 1) n / 2)).
#include "rays/accel/origin_buffer.h"

#include <algorithm>
#include <cmath>

namespace rays {
namespace {

constexpr int kFaces = 6;
constexpr double kGrow = 1e-7;    ///< relative growth of every bound (rounding of the build: ~1e-15)
constexpr double kRound = 1e-9;   ///< relative slack of derived quantities (rectangles, distances)

struct Face {
    int m, u, v;
    double s;
};
Face faceAxes(int f) {
    const int m = f / 2;
    return {m, m == 0 ? 1 : 0, m == 2 ? 1 : 2, (f % 2) ? -1.0 : 1.0};
}

/// The direction of face point (a, b), not normalised.
Vec3 faceDirection(const Face& f, double a, double b) {
    Vec3 e;
    e[f.m] = f.s;
    e[f.u] = a;
    e[f.v] = b;
    return e;
}

int cellOf(double a, int n) { return std::clamp(int((a + 1) * 0.5 * n), 0, n - 1); }

/// A rectangle of one face in (a, b), or none.
struct Rect {
    bool some = false;
    double a0 = -1, a1 = 1, b0 = -1, b1 = 1;
};

/// Clips r to the face; none when it lies outside.
Rect clipped(Rect r) {
    if (!r.some || r.a1 < -1 || r.a0 > 1 || r.b1 < -1 || r.b0 > 1) return {};
    r.a0 = std::max(r.a0, -1.0);
    r.a1 = std::min(r.a1, 1.0);
    r.b0 = std::max(r.b0, -1.0);
    r.b1 = std::min(r.b1, 1.0);
    return r;
}

const Rect kWholeFace{true, -1, 1, -1, 1};

/// A bound relative to the origin, grown.
struct Shape {
    bool isSphere;
    Vec3 c;       // sphere centre
    double r;     // sphere radius
    Vec3 lo, hi;  // box
    double minDist;  // lower bound of the distance of any of its points from the origin
    double scale;
};

Shape relativeShape(const OriginBuffer::Bound& b, Vec3 origin, double dilation) {
    Shape s{};
    s.isSphere = b.isSphere;
    if (b.isSphere) {
        s.c = b.centre - origin;
        // Far from the world's origin, the rounding of c - origin matters too.
        s.scale = length(s.c) + b.radius + 1e-6 * (length(b.centre) + length(origin));
        s.r = b.radius + dilation + kGrow * s.scale + 1e-12;
        s.minDist = std::max(0.0, length(s.c) - s.r);
        return s;
    }
    const Vec3 lo = b.lo - origin, hi = b.hi - origin;
    s.scale = length(0.5 * (lo + hi)) + 0.5 * length(hi - lo) + 1e-6 * (length(b.lo) + length(b.hi) + length(origin));
    const double grow = dilation + kGrow * s.scale + 1e-12;
    s.lo = lo - Vec3(grow);
    s.hi = hi + Vec3(grow);
    Vec3 gap;
    for (int a = 0; a < 3; ++a) gap[a] = std::max({s.lo[a], 0.0, -s.hi[a]});
    s.minDist = length(gap);
    return s;
}

/// Projection of the box onto face f. Its points seen on the face have z >= |x| and z >= |y|, so
/// only the part of the box with z >= min |x|, min |y| counts; that part's corners bound it.
Rect boxRect(Vec3 lo, Vec3 hi, const Face& f, double scale) {
    double x0 = lo[f.u], x1 = hi[f.u], y0 = lo[f.v], y1 = hi[f.v];
    double z0 = f.s > 0 ? lo[f.m] : -hi[f.m], z1 = f.s > 0 ? hi[f.m] : -lo[f.m];
    const double zSeen = std::max({0.0, x0, -x1, y0, -y1});
    z0 = std::max(z0, zSeen);
    if (z0 > z1 || z1 <= 0) return {};
    if (z0 <= kRound * scale) return kWholeFace;  // the box holds the origin, or nearly
    Rect rc{true};
    // x / z over z in [z0, z1] is extreme at an end.
    rc.a0 = std::min(x0 / z0, x0 / z1);
    rc.a1 = std::max(x1 / z0, x1 / z1);
    rc.b0 = std::min(y0 / z0, y0 / z1);
    rc.b1 = std::max(y1 / z0, y1 / z1);
    rc.a0 -= kRound * (1 + std::fabs(rc.a0));
    rc.a1 += kRound * (1 + std::fabs(rc.a1));
    rc.b0 -= kRound * (1 + std::fabs(rc.b0));
    rc.b1 += kRound * (1 + std::fabs(rc.b1));
    return rc;
}

/// Projection of the sphere onto face f: the bounding rectangle of its ellipse when it lies in
/// front of the plane through the origin, else that of its box.
Rect sphereRect(const Shape& sh, const Face& f) {
    const double z = f.s * sh.c[f.m], x = sh.c[f.u], y = sh.c[f.v], r = sh.r;
    // A point p of the face has z_p >= |x_p|, |y_p|; over the sphere z_p - |x_p| is at most
    // z - |x| + sqrt(2) r.
    const double reach = 1.5 * r + kRound * sh.scale;
    if (z + r <= 0 || z - std::fabs(x) + reach < 0 || z - std::fabs(y) + reach < 0) return {};
    if (z - r <= kRound * (z + r)) return boxRect(sh.c - Vec3(r), sh.c + Vec3(r), f, sh.scale);
    const double d = (z - r) * (z + r);
    auto range = [&](double x, double& lo, double& hi) {
        const double ra = r * std::sqrt(x * x + d), xz = x * z;
        const double pad = kRound * (1 + (std::fabs(xz) + ra) / d);
        lo = (xz - ra) / d - pad;
        hi = (xz + ra) / d + pad;
    };
    Rect rc{true};
    range(x, rc.a0, rc.a1);
    range(y, rc.b0, rc.b1);
    return rc;
}

/// Cells of rc at resolution n.
struct CellRange {
    int i0, i1, j0, j1;
    size_t count() const { return size_t(i1 - i0 + 1) * size_t(j1 - j0 + 1); }
};
CellRange cellRange(const Rect& rc, int n) { return {cellOf(rc.a0, n), cellOf(rc.a1, n), cellOf(rc.b0, n), cellOf(rc.b1, n)}; }

struct Pending {
    uint32_t cell;
    OriginBuffer::Entry entry;
};

/// Largest float not above d (d >= 0).
float floatBelow(double d) {
    float f = float(d);
    if (double(f) > d) f = std::nextafter(f, 0.0f);
    return f;
}

/// The cells of one face that the shape may be seen in, with their distance bounds.
template <class Window>
void emitFace(const OriginBuffer::Bound& b, const Shape& sh, Vec3 origin, double dilation, int f, const CellRange& cr,
              int n, const Window& window, std::vector<Pending>& out) {
    const Face face = faceAxes(f);
    auto cellIndex = [&](int i, int j) {
        return window.base + uint32_t(j - window.j0) * uint32_t(window.w) + uint32_t(i - window.i0);
    };
    if (!b.flat && cr.count() <= 4) {  // too few cells for the cone test to drop any
        const OriginBuffer::Entry entry{floatBelow(sh.minDist * (1 - kRound)), b.id};
        for (int j = cr.j0; j <= cr.j1; ++j)
            for (int i = cr.i0; i <= cr.i1; ++i) out.push_back({cellIndex(i, j), entry});
        return;
    }
    // Cone of directions of the sphere: axis w, half-angle beta (none when it holds the origin).
    const double dist = sh.isSphere ? length(sh.c) : 0;
    const bool cone = sh.isSphere && sh.r < dist;
    const Vec3 w = cone ? sh.c / dist : Vec3{};
    const double sinBeta = cone ? sh.r / dist : 1, cosBeta = cone ? std::sqrt(1 - sinBeta * sinBeta) : 0;
    // Plane of a flat object, relative to the origin: |h| is the origin's distance from it.
    const double h = b.flat ? std::fabs(b.offset - dot(b.normal, origin)) - dilation -
                                  kGrow * (sh.scale + std::fabs(b.offset) + length(origin)) - 1e-12
                            : 0;
    const double step = 2.0 / n;
    for (int j = cr.j0; j <= cr.j1; ++j) {
        const double bLo = -1 + step * j, bHi = bLo + step, bc = bLo + 0.5 * step;
        const double bNear = (bLo <= 0 && bHi >= 0) ? 0 : std::min(std::fabs(bLo), std::fabs(bHi));
        for (int i = cr.i0; i <= cr.i1; ++i) {
            const double aLo = -1 + step * i, aHi = aLo + step, ac = aLo + 0.5 * step;
            const double aNear = (aLo <= 0 && aHi >= 0) ? 0 : std::min(std::fabs(aLo), std::fabs(aHi));
            // Angle from the cell's centre direction to any direction of the cell: at most the
            // half-diagonal of the cell over the nearest distance of the cell from the origin.
            const double alpha = (std::sqrt(2.0) / n) / std::sqrt(1 + aNear * aNear + bNear * bNear) + 1e-12;
            const Vec3 e = faceDirection(face, ac, bc) / std::sqrt(1 + ac * ac + bc * bc);
            // cos(beta + alpha) >= cos(beta)(1 - alpha²/2) - sin(beta) alpha
            if (cone && dot(e, w) < cosBeta * (1 - 0.5 * alpha * alpha) - sinBeta * alpha - kRound) continue;
            double md = sh.minDist;
            if (b.flat && h > 0) {
                // Along a direction u the slab |dot(normal, x) - offset| <= grow is at least
                // h / |dot(normal, u)| away; |dot(normal, u)| <= cos(theta - alpha) in the cell.
                const double phi = std::acos(std::min(1.0, std::fabs(dot(b.normal, e)))) - alpha - kRound;
                md = std::max(md, phi > 0 ? h / std::cos(phi) : h);
            }
            out.push_back({cellIndex(i, j), {floatBelow(md * (1 - kRound)), b.id}});
        }
    }
}

}  // namespace

void OriginBuffer::build(const std::vector<Bound>& bounds, Vec3 origin, double dilation) {
    origin_ = origin;
    dilation_ = dilation;
    Level* levels[2] = {&fine_, &coarse_};
    fine_.n = kFineResolution;
    coarse_.n = kCoarseResolution;
    // Pass 1: where each bound projects, in which level, and the window of each face of each level.
    struct FaceJob {
        uint32_t bound;
        int face, level;
        CellRange cells;
    };
    std::vector<FaceJob> jobs;
    jobs.reserve(bounds.size() * 2);
    CellRange used[2][kFaces];
    for (auto& level : used)
        for (CellRange& u : level) u = {INT32_MAX, -1, INT32_MAX, -1};
    size_t upper[2] = {0, 0};  // entries at most
    for (uint32_t k = 0; k < bounds.size(); ++k) {
        const Shape sh = relativeShape(bounds[k], origin, dilation);
        Rect rects[kFaces];
        size_t fineCells = 0;
        for (int f = 0; f < kFaces; ++f) {
            rects[f] = clipped(sh.isSphere ? sphereRect(sh, faceAxes(f)) : boxRect(sh.lo, sh.hi, faceAxes(f), sh.scale));
            if (rects[f].some) fineCells += cellRange(rects[f], fine_.n).count();
        }
        const int l = fineCells > kMaxFineCells ? 1 : 0;
        for (int f = 0; f < kFaces; ++f) {
            if (!rects[f].some) continue;
            const CellRange cr = cellRange(rects[f], levels[l]->n);
            jobs.push_back({k, f, l, cr});
            upper[l] += cr.count();
            CellRange& u = used[l][f];
            u = {std::min(u.i0, cr.i0), std::max(u.i1, cr.i1), std::min(u.j0, cr.j0), std::max(u.j1, cr.j1)};
        }
    }
    size_t cells[2] = {0, 0};
    for (int l = 0; l < 2; ++l)
        for (int f = 0; f < kFaces; ++f) {
            const CellRange& u = used[l][f];
            Window& w = levels[l]->face[f];
            w = u.i1 < 0 ? Window{} : Window{u.i0, u.j0, u.i1 - u.i0 + 1, u.j1 - u.j0 + 1, uint32_t(cells[l])};
            cells[l] += size_t(w.w) * size_t(w.h);
        }
    // Pass 2: the entries, then sorted into their cells.
    std::vector<Pending> pending[2];
    for (int l = 0; l < 2; ++l) pending[l].reserve(upper[l]);
    uint32_t shaped = UINT32_MAX;
    Shape sh{};
    for (const FaceJob& job : jobs) {
        const Bound& b = bounds[job.bound];
        if (job.bound != shaped) {
            sh = relativeShape(b, origin, dilation);
            shaped = job.bound;
        }
        const Level& lv = *levels[job.level];
        emitFace(b, sh, origin, dilation, job.face, job.cells, lv.n, lv.face[job.face], pending[job.level]);
    }
    auto before = [](const Entry& x, const Entry& y) {
        return x.minDist < y.minDist || (x.minDist == y.minDist && x.id < y.id);
    };
    for (int l = 0; l < 2; ++l) {
        Level& lv = *levels[l];
        lv.start.assign(cells[l] + 1, 0);
        for (const Pending& p : pending[l]) ++lv.start[p.cell + 1];
        for (size_t c = 0; c < cells[l]; ++c) lv.start[c + 1] += lv.start[c];
        lv.entries.resize(pending[l].size());
        std::vector<uint32_t> fill(lv.start.begin(), lv.start.end() - 1);
        for (const Pending& p : pending[l]) lv.entries[fill[p.cell]++] = p.entry;
        for (size_t c = 0; c < cells[l]; ++c) {
            Entry* first = lv.entries.data() + lv.start[c];
            Entry* last = lv.entries.data() + lv.start[c + 1];
            if (last - first > 16) {
                std::sort(first, last, before);
                continue;
            }
            for (Entry* e = first + 1; e < last; ++e)  // short lists: insertion sort
                for (Entry* g = e; g > first && before(*g, g[-1]); --g) std::swap(*g, g[-1]);
        }
    }
    built_ = true;
}

OriginBuffer::Cells OriginBuffer::cells(const Vec3& d) const {
    Cells c;
    if (!built_) return c;
    const double ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
    int f;
    double a, b, big;
    if (ax >= ay && ax >= az) {
        f = d.x < 0;
        big = ax;
        a = d.y;
        b = d.z;
    } else if (ay >= az) {
        f = 2 + (d.y < 0);
        big = ay;
        a = d.x;
        b = d.z;
    } else {
        f = 4 + (d.z < 0);
        big = az;
        a = d.x;
        b = d.y;
    }
    const double inv = 1 / big;
    a *= inv;
    b *= inv;
    if (!(big > 0) || !std::isfinite(a) || !std::isfinite(b)) return c;
    c.fine = fine_.cell(f, cellOf(a, fine_.n), cellOf(b, fine_.n));
    c.coarse = coarse_.cell(f, cellOf(a, coarse_.n), cellOf(b, coarse_.n));
    c.valid = true;
    return c;
}

}  // namespace rays
