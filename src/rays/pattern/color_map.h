// Blend maps (POV-Ray 3.7 reference, "Color Maps", "Pigment Maps"): entries sorted by value; a
// value between two entries blends them linearly, below the first or above the last takes that
// entry, and at a value shared by two entries the first of them wins (measured).
#pragma once
#include <span>

#include "rays/pattern/color.h"

namespace rays::pattern {

/// One map entry: a colour, or (pigment >= 0) a pigment node of the same table.
struct MapEntry {
    double value = 0;
    Rgbft color;
    int pigment = -1;
};

/// Where v falls in the map: blend entries[lo] and entries[hi] with weight t of hi (lo == hi: one entry).
struct MapPlace {
    int lo = 0, hi = 0;
    double t = 0;
};
/// The place of v in a non-empty map.
MapPlace placeInMap(std::span<const MapEntry> map, double v);

}  // namespace rays::pattern
