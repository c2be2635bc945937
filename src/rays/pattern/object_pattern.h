// The object pattern (POV-Ray 3.7 reference, "Object Pattern": `object { OBJECT LIST_ITEM_A,
// LIST_ITEM_B }`): a two-entry list pattern, the first entry outside the object, the second inside.
// The pattern knows its object only as an inside test (a plain function pointer over data it keeps
// alive), so that pattern/ stays apart from the scene's shapes; rays/pov builds the object.
#pragma once
#include <memory>

#include "rays/math/vec3.h"

namespace rays::pattern {

struct PatternObject {
    /// True when p (the pattern's space) lies inside the object. Immutable data: any number of
    /// threads may call it at once.
    bool (*inside)(const void* data, Vec3 p) = nullptr;
    const void* data = nullptr;
    std::shared_ptr<const void> keep;  ///< owns data

    /// The list entry at p: 1 inside, 0 outside (measured with POV-Ray 3.7: a point on the surface
    /// is outside, `object { sphere { 0, 1 } }` gives 0 at <1, 0, 0>).
    int index(Vec3 p) const { return inside && inside(data, p) ? 1 : 0; }
};

}  // namespace rays::pattern
