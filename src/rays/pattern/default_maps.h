// The colours a pattern uses when the pigment gives no map or list (POV-Ray 3.7 reference,
// "Patterns": checker blue and green, hexagon blue, green and red, brick grey mortar and red
// bricks, radial a colour wheel, wood, marble, agate and bozo their own maps, the others black to white); the exact
// entries were measured with POV-Ray 3.7.0.10.
#pragma once
#include <vector>

#include "rays/pattern/color_map.h"
#include "rays/pattern/pattern.h"

namespace rays::pattern {

/// The built-in map (or block-pattern list) of a pattern kind.
std::vector<MapEntry> defaultMap(PatternKind kind);

}  // namespace rays::pattern
