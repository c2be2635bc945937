// Warps (POV-Ray 3.7 reference, "Warp"): steps that move the evaluation point, applied in file
// order together with the pattern's transformations (unlike classic turbulence, which always comes
// first). Rendered: turbulence and repeat (with offset and flip) warps.
#pragma once
#include <cstdint>

#include "rays/math/transform.h"
#include "rays/pattern/noise.h"

namespace rays::pattern {

struct WarpStep {
    enum class Kind : uint8_t { Transform, Turbulence, Repeat };
    Kind kind = Kind::Transform;
    Transform toInner;      ///< Transform: the enclosing space → the space inside the step
    Turbulence turbulence;  ///< Turbulence
    int axis = 0;           ///< Repeat: the axis the repeat vector lies along
    double width = 1;       ///< Repeat: the repeat vector's length along it
    Vec3 offset, flip;      ///< Repeat: shift per copy; axes mirrored in odd copies (non-zero)
};

/// p moved through one step (from the enclosing space inwards).
Vec3 applyWarp(const WarpStep& w, Vec3 p);

}  // namespace rays::pattern
