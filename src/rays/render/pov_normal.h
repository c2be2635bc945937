// The shading normal of a POV-Ray surface with a normal pattern (PovSurface::normal ≥ 0).
#pragma once
#include "rays/scene/scene.h"

namespace rays {

/// The unit normal N (world space; the shading code passes the one facing the viewer, as POV-Ray
/// tilts that one) at world point P tilted by surface s's normal pattern.
inline Vec3 povNormalAt(const Scene& scene, const PovSurface& s, Vec3 P, Vec3 N) {
    return scene.normals.atRoot(scene.pigments, s.normal, P, N);
}

}  // namespace rays
