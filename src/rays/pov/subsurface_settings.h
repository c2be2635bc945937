// global_settings { subsurface { samples N, M radiosity B } } (POV-Ray 3.7 reference manual,
// "Subsurface Light Transport").
#pragma once
#include "rays/scene/pov_subsurface.h"
#include "rays/sdl/item.h"

namespace rays::pov {

/// Reads the block into s (mm_per_unit, a global setting of its own, is left as it is) and
/// enables subsurface light transport.
void readSubsurfaceSettings(const sdl::Item& block, PovSubsurfaceSettings& s);

}  // namespace rays::pov
