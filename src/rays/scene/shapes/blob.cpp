// The blob's field is piecewise polynomial along a ray: each component is mapped to a unit frame
// (a sphere's centre at the origin, a cylinder's axis from z = 0 to z = h, the radius 1), where
// the squared distance d² is a quadratic in the ray parameter and the component's field
// s·(1 − d²)² a quartic, on the interval where d² < 1 (a cylinder's on up to three: its two
// hemispherical ends and its middle, split where the ray crosses the end planes). The intervals'
// ends are sorted (only components whose boxes the ray meets, found through a box tree of the
// components: POV-Ray's "hierarchy"); between two neighbours the field is the sum of the quartics covering the gap
// (kept as a running sum), and its first root with the threshold is found exactly by polyRoots.
// Gaps whose positive strengths cannot reach the threshold are skipped. The formula is the
// reference's ("Blob Density"); the cylinder's hemispherical ends as measured with POV-Ray 3.7's
// trace() (tests/pov_blob_test.cpp).
#include "rays/scene/shapes/blob.h"

#include <algorithm>
#include <cmath>

#include "rays/math/poly_roots.h"

namespace rays {

namespace {

// Per component: kind (0 sphere, 1 cylinder), strength, h (the cylinder's length in radii), part,
// then the 3×4 matrix blob space → unit frame, row by row.
constexpr size_t kStride = 16;

Transform frameOf(const double* v) {
    Transform m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) m.m[i][j] = v[4 + 4 * i + j];
    return m;
}

// The offset of q from the component's core (the centre, or the nearest point of the axis).
Vec3 offsetFromCore(Vec3 q, bool cylinder, double h) {
    if (cylinder) q.z -= std::clamp(q.z, 0.0, h);
    return q;
}

constexpr int kLeafSize = 4;  // components per leaf of the box tree

// Calls visit(v) for the numbers v of each component in a leaf whose box passes `enter`.
template <class Enter, class Visit>
void forComponents(const ShapeData& d, Enter enter, Visit visit) {
    int stack[64];
    int n = 0;
    stack[n++] = 0;
    while (n > 0) {
        const BoxNode& node = d.tree[size_t(stack[--n])];
        if (!enter(node.box)) continue;
        if (node.count == 0) {
            stack[n++] = node.first;
            stack[n++] = node.first + 1;
            continue;
        }
        for (int i = node.first; i < node.first + node.count; ++i) visit(&d.values[size_t(i) * kStride]);
    }
}

bool containsPoint(const Bounds& b, Vec3 p) {
    return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y && p.z >= b.lo.z && p.z <= b.hi.z;
}

// Whether the line o + u·d meets box b for some u in [u0, u1] (slab test).
bool meetsBox(const Bounds& b, Vec3 o, Vec3 invDir, double u0, double u1) {
    for (int a = 0; a < 3; ++a) {
        double n = (b.lo[a] - o[a]) * invDir[a], f = (b.hi[a] - o[a]) * invDir[a];
        if (n > f) std::swap(n, f);
        if (std::isnan(n)) n = -kInfinity;  // along the slab's planes: 0·∞
        if (std::isnan(f)) f = kInfinity;
        u0 = std::max(u0, n);
        u1 = std::min(u1, f);
        if (u0 > u1) return false;
    }
    return true;
}

// One component's field on a stretch of the ray: s·g(u)² with g = 1 − d² on (lo, hi).
struct Piece {
    double lo, hi;
    double c[5];
    double strength;
};

struct Event {
    double u;
    int piece;
    bool enter;
};

// Adds the piece where d²(u) = d0 + d1 u + d2 u² is below 1 within (lo, hi).
void addPiece(std::vector<Piece>& out, double s, double d0, double d1, double d2, double lo, double hi) {
    double a = lo, b = hi;
    if (d2 > 0) {
        const double disc = d1 * d1 - 4 * d2 * (d0 - 1);
        if (disc <= 0) return;
        const double sq = std::sqrt(disc);
        const double q = -0.5 * (d1 + std::copysign(sq, d1));  // the stable pair of roots
        double r0 = q / d2, r1 = q != 0 ? (d0 - 1) / q : -r0;
        if (r0 > r1) std::swap(r0, r1);
        a = std::max(a, r0);
        b = std::min(b, r1);
    } else if (d0 >= 1) {
        return;  // d² constant (a ray along a cylinder's axis) and outside
    }
    if (!(a < b) || !std::isfinite(a) || !std::isfinite(b)) return;
    const double e0 = 1 - d0, e1 = -d1, e2 = -d2;
    out.push_back(Piece{a, b, {s * e0 * e0, s * 2 * e0 * e1, s * (e1 * e1 + 2 * e0 * e2), s * 2 * e1 * e2, s * e2 * e2}, s});
}

// d² = |q0 + u q1|² over the chosen axes (mask) as a quadratic in u.
void squaredDistance(Vec3 q0, Vec3 q1, Vec3 mask, double& d0, double& d1, double& d2) {
    q0 = q0 * mask;
    q1 = q1 * mask;
    d0 = dot(q0, q0);
    d1 = 2 * dot(q0, q1);
    d2 = dot(q1, q1);
}

// The pieces of one component along the ray q(u) = q0 + u q1 in its unit frame.
void componentPieces(std::vector<Piece>& out, bool cylinder, double s, double h, Vec3 q0, Vec3 q1) {
    double d0, d1, d2;
    if (!cylinder) {
        squaredDistance(q0, q1, Vec3(1), d0, d1, d2);
        addPiece(out, s, d0, d1, d2, -kInfinity, kInfinity);
        return;
    }
    // The ray's stretches below z = 0, between the end planes, and above z = h.
    double ranges[3][2] = {{-kInfinity, kInfinity}, {-kInfinity, kInfinity}, {-kInfinity, kInfinity}};
    if (q1.z != 0) {
        const double u0 = -q0.z / q1.z, uh = (h - q0.z) / q1.z;
        if (q1.z > 0) {
            ranges[0][1] = u0, ranges[1][0] = u0, ranges[1][1] = uh, ranges[2][0] = uh;
        } else {
            ranges[2][1] = uh, ranges[1][0] = uh, ranges[1][1] = u0, ranges[0][0] = u0;
        }
    } else {
        const int only = q0.z < 0 ? 0 : q0.z > h ? 2 : 1;
        for (int i = 0; i < 3; ++i)
            if (i != only) ranges[i][0] = ranges[i][1] = 0;
    }
    squaredDistance(q0, q1, Vec3(1), d0, d1, d2);
    addPiece(out, s, d0, d1, d2, ranges[0][0], ranges[0][1]);
    squaredDistance(q0, q1, Vec3{1, 1, 0}, d0, d1, d2);
    addPiece(out, s, d0, d1, d2, ranges[1][0], ranges[1][1]);
    squaredDistance(q0 - Vec3{0, 0, h}, q1, Vec3(1), d0, d1, d2);
    addPiece(out, s, d0, d1, d2, ranges[2][0], ranges[2][1]);
}

// The outward normal at p (minus the field's gradient) and the part of the component adding most
// field there.
void normalAndPart(const ShapeData& d, Vec3 p, Vec3 rayDir, ShapeHit& h) {
    Vec3 grad;
    double most = 0;
    int part = -1;
    forComponents(d, [&](const Bounds& b) { return containsPoint(b, p); }, [&](const double* v) {
        const Transform m = frameOf(v);
        const Vec3 e = offsetFromCore(m.point(p), v[0] != 0, v[2]);
        const double d2 = dot(e, e);
        if (d2 >= 1) return;
        const double g = 1 - d2, s = v[1];
        grad += (-4 * s * g) * m.transposedVector(e);  // ∇(s·g²) = s·2g·(−∇d²), ∇d² = 2·Mᵀe
        if (s * g * g > most) most = s * g * g, part = int(v[3]);
    });
    const double len = length(grad);
    h.normal = len > 0 && std::isfinite(len) ? -grad / len : -normalize(rayDir);
    h.part = part >= 0 ? &d.parts[size_t(part)] : nullptr;
}

}  // namespace

bool makeBlob(const std::vector<BlobComponent>& components, ShapeData& data) {
    data = ShapeData{};
    std::vector<std::vector<double>> rows;  // each component's numbers
    std::vector<Bounds> boxes;              // and its box
    for (const BlobComponent& c : components) {
        if (!(c.radius > 0) || c.strength == 0) continue;
        bool cylinder = c.cylinder && length(c.b - c.a) > 0;
        // Unit frame → component space, then the component's transformations.
        Transform frame;
        double h = 0;
        if (cylinder) {
            const Vec3 w = normalize(c.b - c.a);
            const Vec3 helper = std::fabs(w.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
            const Vec3 u = normalize(cross(helper, w));
            frame = Transform::fromColumns(u, cross(w, u), w, c.a) * Transform::scale(Vec3(c.radius));
            h = length(c.b - c.a) / c.radius;
        } else {
            frame = Transform::translate(c.a) * Transform::scale(Vec3(c.radius));
        }
        const Transform toFrame = c.toBlob * frame;
        if (toFrame.determinant() == 0) continue;
        const Transform m = toFrame.inverse();
        std::vector<double> row{cylinder ? 1.0 : 0.0, c.strength, h, double(c.part)};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 4; ++j) row.push_back(m.m[i][j]);
        // The box of the unit ball(s) mapped to blob space: half-widths are the rows' lengths.
        const Vec3 half{length(Vec3{toFrame.m[0][0], toFrame.m[0][1], toFrame.m[0][2]}),
                        length(Vec3{toFrame.m[1][0], toFrame.m[1][1], toFrame.m[1][2]}),
                        length(Vec3{toFrame.m[2][0], toFrame.m[2][1], toFrame.m[2][2]})};
        Bounds box;
        for (const double z : {0.0, h}) {
            const Vec3 centre = toFrame.point(Vec3{0, 0, z});
            box.extend(centre - half);
            box.extend(centre + half);
        }
        if (c.strength > 0) data.bounds.extend(box);  // negative components only take field away
        rows.push_back(std::move(row));
        boxes.push_back(box);
    }
    if (data.bounds.empty()) return false;
    // The box tree: median splits along the longest side of the boxes' centres, leaves of up to
    // kLeafSize components; the components are stored in leaf order.
    std::vector<int> order(rows.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
    struct Task {
        int node, lo, hi;
    };
    std::vector<Task> tasks{{0, 0, int(order.size())}};
    data.tree.emplace_back();
    while (!tasks.empty()) {
        const Task t = tasks.back();
        tasks.pop_back();
        Bounds box, centres;
        for (int i = t.lo; i < t.hi; ++i) {
            box.extend(boxes[size_t(order[size_t(i)])]);
            centres.extend(boxes[size_t(order[size_t(i)])].centroid());
        }
        data.tree[size_t(t.node)].box = box;
        if (t.hi - t.lo <= kLeafSize) {
            data.tree[size_t(t.node)].first = t.lo;
            data.tree[size_t(t.node)].count = t.hi - t.lo;
            continue;
        }
        const Vec3 e = centres.extent();
        const int axis = e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
        const int mid = (t.lo + t.hi) / 2;
        std::nth_element(order.begin() + t.lo, order.begin() + mid, order.begin() + t.hi, [&](int a, int b) {
            return boxes[size_t(a)].centroid()[axis] < boxes[size_t(b)].centroid()[axis];
        });
        const int child = int(data.tree.size());
        data.tree[size_t(t.node)].first = child;
        data.tree.emplace_back();
        data.tree.emplace_back();
        tasks.push_back({child, t.lo, mid});
        tasks.push_back({child + 1, mid, t.hi});
    }
    for (const int i : order) data.values.insert(data.values.end(), rows[size_t(i)].begin(), rows[size_t(i)].end());
    return true;
}

double blobField(const ShapeData& d, Vec3 p) {
    double f = 0;
    forComponents(d, [&](const Bounds& b) { return containsPoint(b, p); }, [&](const double* v) {
        const Vec3 e = offsetFromCore(frameOf(v).point(p), v[0] != 0, v[2]);
        const double d2 = dot(e, e);
        if (d2 < 1) f += v[1] * (1 - d2) * (1 - d2);
    });
    return f;
}

bool hitBlob(const Object& o, const Ray& r, double tMin, double tMax, ShapeHit& h) {
    const ShapeData& d = *o.data;
    const double threshold = o.r0;
    // Per-thread scratch: grows to the largest blob once, then no allocation per ray.
    thread_local std::vector<Piece> pieces;
    thread_local std::vector<Event> events;
    pieces.clear();
    // The origin moved to the ray's point nearest the blob's middle keeps the quartics' numbers small.
    const double s0 = dot(d.bounds.centroid() - r.origin, r.dir) / dot(r.dir, r.dir);
    const Vec3 origin = r.origin + s0 * r.dir;
    const double uMin = tMin - s0, uMax = tMax - s0;
    const Vec3 invDir{1 / r.dir.x, 1 / r.dir.y, 1 / r.dir.z};
    forComponents(d, [&](const Bounds& b) { return meetsBox(b, origin, invDir, uMin, uMax); }, [&](const double* v) {
        const Transform m = frameOf(v);
        componentPieces(pieces, v[0] != 0, v[1], v[2], m.point(origin), m.vector(r.dir));
    });
    if (pieces.empty()) return false;
    events.clear();
    for (size_t i = 0; i < pieces.size(); ++i) {
        events.push_back(Event{pieces[i].lo, int(i), true});
        events.push_back(Event{pieces[i].hi, int(i), false});
    }
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.u < b.u; });
    double sum[5] = {0, 0, 0, 0, 0};
    double positive = 0;  // the active positive strengths: the field cannot exceed it
    int active = 0;
    for (size_t k = 0; k + 1 < events.size(); ++k) {
        const Piece& p = pieces[size_t(events[k].piece)];
        const double sign = events[k].enter ? 1 : -1;
        for (int j = 0; j < 5; ++j) sum[j] += sign * p.c[j];
        if (p.strength > 0) positive += sign * p.strength;
        active += events[k].enter ? 1 : -1;
        if (active == 0) std::fill(sum, sum + 5, 0.0), positive = 0;  // no drift carried over
        const double a = std::max(events[k].u, uMin), b = std::min(events[k + 1].u, uMax);
        if (events[k].u >= uMax) break;
        if (!(a < b) || positive <= threshold) continue;
        double c[5] = {sum[0] - threshold, sum[1], sum[2], sum[3], sum[4]};
        double root;
        if (!firstValidRoot(c, 4, a, b, [&](double x) { return x + s0 > tMin && x + s0 < tMax; }, root)) continue;
        h.t = root + s0;
        normalAndPart(d, r.at(h.t), r.dir, h);
        return true;
    }
    return false;
}

bool insideBlob(const Object& o, Vec3 p) { return blobField(*o.data, p) > o.r0; }

}  // namespace rays
