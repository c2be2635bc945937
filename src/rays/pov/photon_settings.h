// The photons blocks of POV-Ray 3.7 (reference manual, "Photons"): global_settings' (how many
// photons, how they are gathered), an object's (target, refraction, reflection, collect,
// pass_through) and a light's (refraction, reflection).
#pragma once
#include "rays/scene/light.h"
#include "rays/scene/pov_photons.h"
#include "rays/sdl/item.h"

namespace rays::pov {

/// global_settings { photons { ... } } (the grammar has checked its keywords); enabled is set.
PovPhotonSettings readPhotonSettings(const sdl::Item& block);

/// An object's photons block over the flags it inherits (a child's block changes what it says).
PovPhotonFlags readPhotonFlags(const sdl::Item& block, PovPhotonFlags inherited);

/// A light's photons block.
void readLightPhotons(const sdl::Item& block, Light& light);

}  // namespace rays::pov
