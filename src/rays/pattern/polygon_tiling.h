// A periodic tiling of the x-z plane by convex polygons, each of a type, with POV-Ray 3.7's tiling
// pattern's bevel (pattern/tiling.h): the value of type t of T is t/T where the point is at least
// the bevel width inside its tile and rises linearly with nearness to the tile's nearest edge to
// (t + 1)/T on it. Built once (the polygons of one period cell), then read only.
#pragma once
#include <initializer_list>
#include <vector>

namespace rays::pattern {

struct Point2 {
    double x = 0, z = 0;
};

class PolygonTiling {
public:
    /// The lattice of periods a and b (not parallel) and the number of tile types.
    PolygonTiling(Point2 a, Point2 b, int types);

    /// A convex polygon of the given type (vertices in either order); a polygon anywhere: it is
    /// moved by whole periods next to the lattice cell.
    void polygon(int type, std::initializer_list<Point2> vertices);
    void polygon(int type, const std::vector<Point2>& vertices);
    /// A regular polygon of `sides` sides of length `side` about c, its first vertex at `degrees`
    /// from +x towards +z.
    void regular(int type, Point2 c, int sides, double degrees, double side = 1);
    /// The rectangle between two corners.
    void rectangle(int type, Point2 lo, Point2 hi);
    /// Sets the bevel width to the smallest tile's inradius (its vertices' mean's distance to its
    /// edges: the tiles are regular polygons, rectangles and rhombi).
    void finish();
    /// Sets the bevel width.
    void finish(double bevel) { bevel_ = bevel; }

    /// The value at (x, z), in [0, 1].
    double value(double x, double z) const;

private:
    struct Edge {
        double nx, nz, c;  // distance inside: nx·x + nz·z − c (n the unit inward normal)
    };
    struct Tile {
        int type, first, count;  // edges [first, first + count)
        double cx, cz;           // the vertices' mean
    };
    double distanceInside(const Tile& t, double x, double z) const;
    Point2 a_, b_;
    double inv_[4] = {};  // (x, z) → lattice coordinates (u, v)
    int types_;
    double bevel_ = 1;
    std::vector<Tile> tiles_;
    std::vector<Edge> edges_;
};

}  // namespace rays::pattern
