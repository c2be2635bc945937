// global_settings { radiosity { ... } } → PovRadiosity (POV-Ray 3.7 reference, "Radiosity").
#pragma once
#include "rays/scene/pov_radiosity.h"
#include "rays/sdl/item.h"

namespace rays::pov {

/// The settings of a radiosity block (the grammar has checked its keywords); enabled is set.
PovRadiosity readRadiosity(const sdl::Item& block);

}  // namespace rays::pov
