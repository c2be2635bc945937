// Warps (POV-Ray 3.7 reference, "Warp"): steps that move the evaluation point, applied in file
// order together with the pattern's transformations (unlike classic turbulence, which always comes
// first). Rendered: turbulence, repeat (with offset and flip), black_hole (black_hole.h) and the
// mapping warps planar, cylindrical and spherical (mapping_warp.h).
#pragma once
#include <cstdint>

#include "rays/math/transform.h"
#include "rays/pattern/black_hole.h"
#include "rays/pattern/mapping_warp.h"
#include "rays/pattern/noise.h"

namespace rays::pattern {

struct WarpStep {
    enum class Kind : uint8_t { Transform, Turbulence, Repeat, Mapping, BlackHole };
    Kind kind = Kind::Transform;
    Transform toInner;      ///< Transform: the enclosing space → the space inside the step
    Turbulence turbulence;  ///< Turbulence
    int axis = 0;           ///< Repeat: the axis the repeat vector lies along
    double width = 1;       ///< Repeat: the repeat vector's length along it
    Vec3 offset, flip;      ///< Repeat: shift per copy; axes mirrored in odd copies (non-zero)
    MappingWarp mapping;    ///< Mapping
    BlackHole hole;         ///< BlackHole
};

/// p moved through one step (from the enclosing space inwards).
Vec3 applyWarp(const WarpStep& w, Vec3 p);

}  // namespace rays::pattern
