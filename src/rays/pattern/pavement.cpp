#include "rays/pattern/pavement.h"

#include <memory>

#include "rays/pattern/polygon_tiling.h"

namespace rays::pattern {
namespace {

constexpr double kSqrt3 = 1.7320508075688772;  // √3
constexpr double kTriangleHeight = kSqrt3 / 2;              // an equilateral triangle's height (side 1)
constexpr double kTriangleBevel = kSqrt3 / 6;  // the unit triangle's inradius

// The tilings drawn, as measured with POV-Ray 3.7 (one type each).
struct Pavings {
    PolygonTiling triangle{{1, 0}, {0.5, kTriangleHeight}, 1}, rhombus{{1, 0}, {0.5, kTriangleHeight}, 1};
    PolygonTiling square{{1, 0}, {0, 1}, 1}, domino{{1, 0}, {0, 2}, 1};
    PolygonTiling hexagon{{1.5, kTriangleHeight}, {0, kSqrt3}, 1};
    PolygonTiling trapezoid{{3, 0}, {0, 2 * kTriangleHeight}, 1}, bar{{3, 0}, {0, 1}, 1};
    Pavings() {
        // Triangles in rows √3/2 deep, bases on z = 0 from integer x (as tiling 3's).
        triangle.polygon(0, {{0, 0}, {1, 0}, {0.5, kTriangleHeight}});
        triangle.polygon(0, {{0.5, kTriangleHeight}, {1, 0}, {1.5, kTriangleHeight}});
        triangle.finish(kTriangleBevel);
        // Two triangles: rhombi leaning towards −x, one with its base from (0, 0) to (1, 0).
        rhombus.polygon(0, {{0, 0}, {1, 0}, {0.5, kTriangleHeight}, {-0.5, kTriangleHeight}});
        rhombus.finish(kTriangleBevel);
        square.rectangle(0, {0, 0}, {1, 1});
        square.finish(0.5);
        domino.rectangle(0, {0, 0}, {1, 2});  // 1×2 along z, in columns
        domino.finish(0.5);
        hexagon.regular(0, {1, 0}, 6, 0);  // two vertices on the x-axis, one about (1, 0)
        hexagon.finish(kTriangleBevel);
        // Three triangles: trapezoids of bases 2 and 1, in rows √3/2 deep, pointing up and down in
        // turn along a row, the next row turned the other way.
        const double h = kTriangleHeight;
        trapezoid.polygon(0, {{0, 0}, {2, 0}, {1.5, h}, {0.5, h}});
        trapezoid.polygon(0, {{2, 0}, {3, 0}, {3.5, h}, {1.5, h}});
        trapezoid.polygon(0, {{0.5, h}, {1.5, h}, {2, 2 * h}, {0, 2 * h}});
        trapezoid.polygon(0, {{1.5, h}, {3.5, h}, {3, 2 * h}, {2, 2 * h}});
        trapezoid.finish(kTriangleBevel);
        bar.rectangle(0, {0, 0}, {3, 1});  // three squares, pattern 1: 3×1 bars along x, in columns
        bar.finish(0.5);
    }
};

const Pavings& pavings() {
    static const Pavings p;
    return p;
}

const PolygonTiling* tiling(const Pavement& m) {
    if (!pavementDrawn(m)) return nullptr;
    const Pavings& p = pavings();
    switch (m.sides) {
        case 3: return m.tiles == 1 ? &p.triangle : m.tiles == 2 ? &p.rhombus : &p.trapezoid;
        case 4: return m.tiles == 1 ? &p.square : m.tiles == 2 ? &p.domino : &p.bar;
        default: return &p.hexagon;
    }
}

}  // namespace

bool pavementDrawn(const Pavement& m) {
    // Measured: interior changes nothing for these tiles but the trapezoids, nor does form for
    // squares and single triangles, nor exterior for hexagons.
    const bool sharpForm = m.form == 0 || m.form == 3;
    switch (m.sides) {
        case 3:
            if (m.tiles == 3) return m.pattern == 1 && m.exterior == 0 && m.interior == 0 && sharpForm;
            return (m.tiles == 1 || m.tiles == 2) && m.exterior == 0 && (m.tiles == 1 || sharpForm);
        case 4:
            if (m.tiles == 3) return m.pattern == 1 && m.exterior == 0;
            return (m.tiles == 1 || m.tiles == 2) && m.exterior == 0;
        case 6: return m.tiles == 1 && sharpForm;
        default: return false;
    }
}

double pavementValue(const Pavement& m, Vec3 p) {
    const PolygonTiling* t = tiling(m);
    return t ? t->value(p.x, p.z) : 0;
}

}  // namespace rays::pattern
