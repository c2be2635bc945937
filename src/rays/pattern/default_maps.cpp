#include "rays/pattern/default_maps.h"

namespace rays::pattern {
namespace {

MapEntry at(double v, double r, double g, double b) { return MapEntry{v, Rgbft{Vec3{r, g, b}}, -1}; }

}  // namespace

std::vector<MapEntry> defaultMap(PatternKind kind) {
    switch (kind) {
        // object without a list: blue outside, green inside, as checker (measured).
        case PatternKind::Checker: case PatternKind::Object: return {at(0, 0, 0, 1), at(0, 0, 1, 0)};
        case PatternKind::Hexagon: return {at(0, 0, 0, 1), at(0, 0, 1, 0), at(0, 1, 0, 0)};
        case PatternKind::Square: return {at(0, 1, 0, 0), at(0, 0, 1, 0), at(0, 0, 0, 1), at(0, 1, 1, 0)};  // measured
        case PatternKind::Triangular: case PatternKind::Cubic:  // measured
            return {at(0, 1, 0, 0), at(0, 0, 1, 0), at(0, 0, 0, 1), at(0, 1, 1, 0), at(0, 0, 1, 1), at(0, 1, 0, 1)};
        case PatternKind::Brick: return {at(0, 0.5, 0.5, 0.5), at(0, 0.6, 0.15, 0.15)};
        case PatternKind::Wood:
            return {at(0, 0.666, 0.312, 0.2), at(0.6, 0.666, 0.312, 0.2), at(0.6, 0.4, 0.1333, 0.066),
                    at(1, 0.4, 0.1333, 0.066)};
        case PatternKind::Marble:
            return {at(0, 0.9, 0.8, 0.8), at(0.9, 0.9, 0.08, 0.08), at(0.9, 0, 0, 0), at(1, 0, 0, 0)};
        case PatternKind::Agate:
            return {at(0, 1, 1, 1), at(0.5, 0.95, 0.75, 0.5), at(0.5, 0.9, 0.7, 0.5), at(0.6, 0.9, 0.7, 0.4),
                    at(0.6, 1, 0.7, 0.4), at(1, 0.6, 0.3, 0)};
        case PatternKind::Radial:  // a colour wheel
            return {at(0, 0, 1, 1), at(0.333, 1, 1, 0), at(0.666, 1, 0, 1), at(1, 0, 1, 1)};
        case PatternKind::Mandel: case PatternKind::Julia:
            return {at(0, 0, 0, 0), at(0.015, 1, 0, 1), at(0.1, 0, 1, 1), at(1, 0, 1, 1)};
        case PatternKind::Bozo:
            return {at(0.4, 1, 1, 1), at(0.4, 0, 1, 0), at(0.6, 0, 1, 0), at(0.6, 0, 0, 1), at(0.8, 0, 0, 1),
                    at(0.8, 1, 0, 0)};
        default: return {at(0, 0, 0, 0), at(1, 1, 1, 1)};
    }
}

}  // namespace rays::pattern
