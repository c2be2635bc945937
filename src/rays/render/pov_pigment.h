// The colour of a POV-Ray surface at a point: its pigment pattern evaluated at the world point
// (PovSurface::pigment ≥ 0), else the flat colour of the material.
#pragma once
#include <algorithm>

#include "rays/scene/scene.h"

namespace rays {

struct PovPigmentSample {
    Vec3 color;
    double filter = 0, transmit = 0;
};

/// The pattern colour of surface s at world point P; s.pigment must be ≥ 0.
inline PovPigmentSample povPigmentAt(const Scene& scene, const PovSurface& s, Vec3 P) {
    const pattern::Rgbft c = scene.pigments.atRoot(s.pigment, P);
    return {c.rgb, std::clamp(c.filter, 0.0, 1.0), c.transmit};
}

}  // namespace rays
