// POV-Ray's rainbow (POV-Ray 3.7 reference, "Rainbow"): for each ray the angle θ between the ray
// and the rainbow's direction; within Angle ± Width/2 the colour map at (θ − (Angle − Width/2))/Width
// (plus jitter) is mixed in as a fog's colour is. Measured with povray 3.7: the index as the manual
// says (0 innermost), the fog's mixing (filter does not show the background through, transmit
// does), the arc the full circle by default, `arc_angle` about `up` with a linear fade between
// falloff_angle/2 and arc_angle/2 on each side.
#pragma once
#include <vector>

#include "rays/geometry/ray.h"
#include "rays/scene/pov_surface.h"

namespace rays {

/// The colour behind a ray segment of length t (may be infinite; ray.dir unit) seen through the
/// rainbows; u in [0, 1) draws the jitter.
Vec3 povRainbows(const std::vector<PovRainbow>& rainbows, Vec3 behind, const Ray& ray, double t, double u);

}  // namespace rays
