#include "rays/pattern/color_map.h"

namespace rays::pattern {

MapPlace placeInMap(std::span<const MapEntry> map, double v) {
    const int n = int(map.size());
    if (v <= map[0].value) return {0, 0, 0};
    for (int i = 1; i < n; ++i) {
        if (v > map[size_t(i)].value) continue;
        const double span = map[size_t(i)].value - map[size_t(i - 1)].value;
        const double t = span > 0 ? (v - map[size_t(i - 1)].value) / span : 1;
        return {i - 1, i, t};
    }
    return {n - 1, n - 1, 0};
}

}  // namespace rays::pattern
