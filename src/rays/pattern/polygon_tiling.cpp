#include "rays/pattern/polygon_tiling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rays::pattern {

PolygonTiling::PolygonTiling(Point2 a, Point2 b, int types) : a_(a), b_(b), types_(types) {
    const double det = a.x * b.z - a.z * b.x;
    inv_[0] = b.z / det, inv_[1] = -b.x / det;
    inv_[2] = -a.z / det, inv_[3] = a.x / det;
}

void PolygonTiling::polygon(int type, std::initializer_list<Point2> vertices) {
    polygon(type, std::vector<Point2>(vertices));
}

void PolygonTiling::polygon(int type, const std::vector<Point2>& vertices) {
    const size_t n = vertices.size();
    double cx = 0, cz = 0, area2 = 0;
    for (size_t i = 0; i < n; ++i) {
        const Point2 p = vertices[i], q = vertices[(i + 1) % n];
        cx += p.x / double(n), cz += p.z / double(n);
        area2 += p.x * q.z - q.x * p.z;
    }
    // Moved by whole periods so that the centroid lies in the cell [0, 1)² of lattice coordinates.
    const double u = std::floor(inv_[0] * cx + inv_[1] * cz + 1e-9), v = std::floor(inv_[2] * cx + inv_[3] * cz + 1e-9);
    const double dx = u * a_.x + v * b_.x, dz = u * a_.z + v * b_.z;
    const double sign = area2 > 0 ? 1 : -1;  // counter-clockwise (x to z): the inward normal is on the left
    Tile t{type, int(edges_.size()), int(n), cx - dx, cz - dz};
    for (size_t i = 0; i < n; ++i) {
        const Point2 p{vertices[i].x - dx, vertices[i].z - dz}, q{vertices[(i + 1) % n].x - dx, vertices[(i + 1) % n].z - dz};
        const double ex = q.x - p.x, ez = q.z - p.z, len = std::hypot(ex, ez);
        const double nx = -ez / len * sign, nz = ex / len * sign;
        edges_.push_back(Edge{nx, nz, nx * p.x + nz * p.z});
    }
    tiles_.push_back(t);
}

void PolygonTiling::regular(int type, Point2 c, int sides, double degrees, double side) {
    const double r = side / (2 * std::sin(std::numbers::pi / sides));
    std::vector<Point2> v;
    for (int k = 0; k < sides; ++k) {
        const double a = (degrees + 360.0 * k / sides) * std::numbers::pi / 180;
        v.push_back(Point2{c.x + r * std::cos(a), c.z + r * std::sin(a)});
    }
    polygon(type, v);
}

void PolygonTiling::rectangle(int type, Point2 lo, Point2 hi) {
    polygon(type, {lo, {hi.x, lo.z}, hi, {lo.x, hi.z}});
}

void PolygonTiling::finish() {
    bevel_ = 1e300;
    for (const Tile& t : tiles_) bevel_ = std::min(bevel_, distanceInside(t, t.cx, t.cz));
}

double PolygonTiling::distanceInside(const Tile& t, double x, double z) const {
    double d = 1e300;
    for (int i = 0; i < t.count; ++i) {
        const Edge& e = edges_[size_t(t.first + i)];
        d = std::min(d, e.nx * x + e.nz * z - e.c);
    }
    return d;
}

double PolygonTiling::value(double x, double z) const {
    double u = inv_[0] * x + inv_[1] * z, v = inv_[2] * x + inv_[3] * z;
    u -= std::floor(u), v -= std::floor(v);
    const double px = u * a_.x + v * b_.x, pz = u * a_.z + v * b_.z;
    double best = -1e300;
    int type = 0;
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j) {
            const double qx = px + i * a_.x + j * b_.x, qz = pz + i * a_.z + j * b_.z;
            for (const Tile& t : tiles_) {
                const double d = distanceInside(t, qx, qz);
                if (d >= 0) return (t.type + 1 - std::min(d / bevel_, 1.0)) / types_;  // tiles do not overlap
                if (d > best) best = d, type = t.type;
            }
        }
    return (type + 1.0) / types_;  // on no tile (rounding on an edge): the nearest tile's edge
}

}  // namespace rays::pattern
