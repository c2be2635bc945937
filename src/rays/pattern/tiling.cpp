#include "rays/pattern/tiling.h"

#include <array>
#include <cmath>
#include <memory>
#include <numbers>

#include "rays/pattern/polygon_tiling.h"

namespace rays::pattern {
namespace {

constexpr double kS3 = 1.7320508075688772;  // √3
constexpr double kH = kS3 / 2;              // an equilateral triangle's height (side 1)
constexpr double kS2 = 1.4142135623730951;  // √2

Point2 hexVertex(Point2 c, int k) {  // vertex k of the hexagon of side 1 about c, vertex 0 towards +x
    const double a = k * std::numbers::pi / 3;
    return {c.x + std::cos(a), c.z + std::sin(a)};
}

// Each tiling as measured with POV-Ray 3.7: its periods, its tiles' types (in the value order) and
// shapes. All polygons have sides of length 1 unless said otherwise.
std::unique_ptr<PolygonTiling> build(int n) {
    std::unique_ptr<PolygonTiling> t;
    switch (n) {
        case 1:  // unit squares, one type
            t = std::make_unique<PolygonTiling>(Point2{1, 0}, Point2{0, 1}, 1);
            t->rectangle(0, {0, 0}, {1, 1});
            break;
        case 2:  // hexagons with two vertices on the x-axis, one about (−1, 0)
            t = std::make_unique<PolygonTiling>(Point2{1.5, kH}, Point2{0, kS3}, 1);
            t->regular(0, {-1, 0}, 6, 0);
            break;
        case 3:  // triangles in rows √3/2 deep, bases on z = 0 from integer x: upward 0, downward 1
            t = std::make_unique<PolygonTiling>(Point2{1, 0}, Point2{0.5, kH}, 2);
            t->polygon(0, {{0, 0}, {1, 0}, {0.5, kH}});
            t->polygon(1, {{0.5, kH}, {1, 0}, {1.5, kH}});
            break;
        case 4:  // rhombi of 60°, one with its corner at the origin and sides along x and 60°
            t = std::make_unique<PolygonTiling>(Point2{1, 0}, Point2{0.5, kH}, 1);
            t->polygon(0, {{0, 0}, {1, 0}, {1.5, kH}, {0.5, kH}});
            break;
        case 5: {  // tumbling blocks: the hexagon about (1, 0) (as tiling 2's) cut into three rhombi
            t = std::make_unique<PolygonTiling>(Point2{1.5, kH}, Point2{0, kS3}, 3);
            const Point2 c{1, 0};
            constexpr int kType[3] = {1, 0, 2};  // the rhombus round vertex 0, 2, 4
            for (int i = 0; i < 3; ++i)
                t->polygon(kType[i], {c, hexVertex(c, 2 * i - 1), hexVertex(c, 2 * i), hexVertex(c, 2 * i + 1)});
            break;
        }
        case 6:  // herringbone of 2×1 bricks in a 4×4 period: across (0) and along z (1), in steps of one
            t = std::make_unique<PolygonTiling>(Point2{4, 0}, Point2{0, 4}, 2);
            for (int k = 0; k < 4; ++k) {
                t->rectangle(0, {double((k + 1) % 4), double(k)}, {double((k + 1) % 4 + 2), double(k + 1)});
                t->rectangle(1, {double(k), double(k)}, {double(k + 1), double(k + 2)});
            }
            break;
        case 7:  // octagons (1) with sides across the axes about the origin, squares (0) between
            t = std::make_unique<PolygonTiling>(Point2{1 + kS2, 0}, Point2{0, 1 + kS2}, 2);
            t->regular(1, {0, 0}, 8, 22.5);
            t->regular(0, {(1 + kS2) / 2, (1 + kS2) / 2}, 4, 0);
            break;
        case 8:  // rows of unit squares (2) and of triangles (upward 0, downward 1), each square row
                 // shifted half a unit from the one below
            t = std::make_unique<PolygonTiling>(Point2{1, 0}, Point2{0.5, 1 + kH}, 3);
            t->rectangle(2, {0, 0}, {1, 1});
            t->polygon(0, {{0, 1}, {1, 1}, {0.5, 1 + kH}});
            t->polygon(1, {{0.5, 1 + kH}, {1, 1}, {1.5, 1 + kH}});
            break;
        case 9:  // hexagons (2) with a bottom side from (0, 0) to (1, 0), triangles between them:
                 // upward (0) and downward (1)
            t = std::make_unique<PolygonTiling>(Point2{2, 0}, Point2{1, kS3}, 3);
            t->regular(2, {0.5, kH}, 6, 0);
            t->polygon(0, {{-1, 0}, {0, 0}, {-0.5, kH}});
            t->polygon(1, {{0, 0}, {1, 0}, {0.5, -kH}});
            break;
        case 10:  // unit squares in rows shifted half a unit each
            t = std::make_unique<PolygonTiling>(Point2{1, 0}, Point2{0.5, 1}, 1);
            t->rectangle(0, {0, 0}, {1, 1});
            break;
        case 11:  // a unit square (0) with 2×1 bricks round it, across (1) and along z (2), period 3
            t = std::make_unique<PolygonTiling>(Point2{3, 0}, Point2{0, 3}, 3);
            t->rectangle(0, {1, 1}, {2, 2});
            t->rectangle(1, {1, 0}, {3, 1});
            t->rectangle(1, {0, 2}, {2, 3});
            t->rectangle(2, {0, 0}, {1, 2});
            t->rectangle(2, {2, 1}, {3, 3});
            break;
        case 12:  // unit squares (0) with 2×1 bricks, across (1) and along z (2), mirrored in a 6×6 period
            t = std::make_unique<PolygonTiling>(Point2{6, 0}, Point2{0, 6}, 3);
            for (const Point2 c : {Point2{1, 1}, Point2{4, 1}, Point2{1, 4}, Point2{4, 4}}) t->rectangle(0, c, {c.x + 1, c.z + 1});
            for (const Point2 c : {Point2{1, 0}, Point2{3, 0}, Point2{0, 2}, Point2{4, 2}, Point2{0, 3}, Point2{4, 3},
                                   Point2{1, 5}, Point2{3, 5}})
                t->rectangle(1, c, {c.x + 2, c.z + 1});
            for (const Point2 c : {Point2{0, 0}, Point2{0, 4}, Point2{2, 1}, Point2{2, 3}, Point2{3, 1}, Point2{3, 3},
                                   Point2{5, 0}, Point2{5, 4}})
                t->rectangle(2, c, {c.x + 1, c.z + 2});
            break;
        case 15:  // unit squares (0) and 2×2 squares (1) (the Pythagorean tiling), period (−1, 2), (2, 1)
            t = std::make_unique<PolygonTiling>(Point2{-1, 2}, Point2{2, 1}, 2);
            t->rectangle(0, {0, 0}, {1, 1});
            t->rectangle(1, {1, -1}, {3, 1});
            break;
        case 16: case 17: {  // hexagons, squares and triangles (3.4.6.4): hexagons about (−1, 0) with
                             // two vertices on the x-axis, 1 + √3 apart along z
            const Point2 a{0, 1 + kS3}, b{(3 + kS3) / 2, (1 + kS3) / 2};
            const bool six = n == 17;  // 16: squares 0, triangles 1, hexagons 2; 17: each square
                                       // and triangle of the period its own type, hexagons 5
            t = std::make_unique<PolygonTiling>(a, b, six ? 6 : 3);
            const Point2 c{-1, 0};
            t->regular(six ? 5 : 2, c, 6, 0);
            t->regular(0, {c.x, c.z + a.z / 2}, 4, 45);
            t->regular(six ? 1 : 0, {c.x + b.x / 2, c.z + b.z / 2}, 4, 75);
            t->regular(six ? 2 : 0, {c.x + b.x / 2, c.z - b.z / 2}, 4, 15);
            t->regular(six ? 3 : 1, {c.x + (a.x + b.x) / 3, c.z + (a.z + b.z) / 3}, 3, 0);
            t->regular(six ? 4 : 1, {c.x + (2 * b.x - a.x) / 3, c.z + (2 * b.z - a.z) / 3}, 3, 180);
            break;
        }
        case 18:  // basket weave: 2×2 blocks of two bricks along z (1) or across (0), alternating
            t = std::make_unique<PolygonTiling>(Point2{4, 0}, Point2{0, 4}, 2);
            for (const Point2 c : {Point2{0, 0}, Point2{1, 0}, Point2{2, 2}, Point2{3, 2}}) t->rectangle(1, c, {c.x + 1, c.z + 2});
            for (const Point2 c : {Point2{2, 0}, Point2{2, 1}, Point2{0, 2}, Point2{0, 3}}) t->rectangle(0, c, {c.x + 2, c.z + 1});
            break;
        case 19:  // hexagons (2) among triangles (upward 0, downward 1): 3.3.3.3.6, hexagons about (−1, 0)
                  // with two vertices on the x-axis, √7 apart (the unit triangles of the period computed
                  // from the hexagons)
            t = std::make_unique<PolygonTiling>(Point2{2.5, -kH}, Point2{2, kS3}, 3);
            t->regular(2, {3.5, 0.866025403784439}, 6, 60);
            t->regular(0, {2.5, 0.288675134594812}, 3, 90);
            t->regular(0, {1.5, 0.288675134594812}, 3, 90);
            t->regular(1, {2, 0.577350269189625}, 3, 30);
            t->regular(0, {2, 1.15470053837925}, 3, 90);
            t->regular(1, {2.5, 1.44337567297406}, 3, 30);
            t->regular(0, {0.5, 0.288675134594813}, 3, 90);
            t->regular(1, {1, 0.577350269189626}, 3, 30);
            t->regular(1, {2.5, -0.288675134594813}, 3, 30);
            break;
        case 20:  // tiling 19 mirrored in the x-axis (hexagons about (0.5, −√3/2))
            t = std::make_unique<PolygonTiling>(Point2{2.5, kH}, Point2{0.5, 3 * kH}, 3);
            t->regular(2, {1, 1.73205080756888}, 6, 60);
            t->regular(0, {2.5, 2.02072594216369}, 3, 90);
            t->regular(0, {0.5, 0.288675134594813}, 3, 90);
            t->regular(1, {1, 0.577350269189626}, 3, 30);
            t->regular(1, {2, 2.3094010767585}, 3, 30);
            t->regular(0, {2, 2.88675134594813}, 3, 90);
            t->regular(1, {2.5, 3.17542648054294}, 3, 30);
            t->regular(0, {2, 1.15470053837925}, 3, 90);
            t->regular(1, {2.5, 1.44337567297406}, 3, 30);
            break;
        case 21:  // squares and triangles (3.3.4.3.4), period 1 + √3: squares about (±h, ±h), h = (1 + √3)/4,
                  // turned ±15° (4 where x·z > 0, 5 elsewhere), triangles of four types 0 to 3
            t = std::make_unique<PolygonTiling>(Point2{1 + kS3, 0}, Point2{0, 1 + kS3}, 6);
            t->regular(4, {0.683012701892219, 0.683012701892219}, 4, 15);
            t->regular(4, {2.04903810567666, 2.04903810567666}, 4, 15);
            t->regular(5, {0.683012701892219, 2.04903810567666}, 4, 75);
            t->regular(5, {2.04903810567666, 0.683012701892219}, 4, 75);
            t->regular(2, {1.07735026918963, 1.36602540378444}, 3, 60);
            t->regular(3, {1.36602540378444, 0.288675134594813}, 3, 90);
            t->regular(0, {1.65470053837925, 1.36602540378444}, 3, 0);
            t->regular(1, {0, 1.07735026918963}, 3, 30);
            t->regular(3, {0, 1.65470053837925}, 3, 90);
            t->regular(0, {0.288675134594813, 0}, 3, 1.42108547152e-14);
            t->regular(2, {2.44337567297406, 0}, 3, 60);
            t->regular(1, {1.36602540378444, 2.44337567297406}, 3, 30);
            break;
        case 23: case 24: {  // dodecagons, hexagons and squares (4.6.12): dodecagons about (0, −(1 + √3)/2),
                             // 3 + √3 apart, each with a hexagon above and below and squares between
                             // dodecagons; 23: hexagons 0, squares 1, dodecagons 2; 24: hexagons 0, the
                             // squares towards 0°, 60° and 120° from a dodecagon 1, 2, 3, dodecagons 4
            const double l = 3 + kS3, cz = -(1 + kS3) / 2, r = (2 + kS3) / 2 + 0.5;
            const bool five = n == 24;
            t = std::make_unique<PolygonTiling>(Point2{l, 0}, Point2{l / 2, l * kH}, five ? 5 : 3);
            t->regular(five ? 4 : 2, {0, cz}, 12, 15);
            t->regular(0, {0, cz + 1 + kS3}, 6, 0);
            t->regular(0, {0, cz - 1 - kS3}, 6, 0);
            for (int k = 0; k < 3; ++k) {
                const double a = k * std::numbers::pi / 3;
                t->regular(five ? 1 + k : 1, {r * std::cos(a), cz + r * std::sin(a)}, 4, 60.0 * k + 45);
            }
            break;
        }
        default: return nullptr;
    }
    t->finish();
    return t;
}

const std::array<std::unique_ptr<PolygonTiling>, 28>& tilings() {
    static const std::array<std::unique_ptr<PolygonTiling>, 28> all = [] {
        std::array<std::unique_ptr<PolygonTiling>, 28> a;
        for (int n = 1; n < 28; ++n) a[size_t(n)] = build(n);
        return a;
    }();
    return all;
}

}  // namespace

bool tilingDrawn(int number) { return number >= 1 && number <= 27 && tilings()[size_t(number)] != nullptr; }

double tilingValue(int number, Vec3 p) {
    if (number < 1 || number > 27) return 0;
    const PolygonTiling* t = tilings()[size_t(number)].get();
    return t ? t->value(p.x, p.z) : 0;
}

}  // namespace rays::pattern
