// What the files of SceneBuilder (scene_builder*.cpp) share besides the class.
#pragma once
#include <vector>

#include "rays/pov/item_values.h"  // clampedInt, isOn
#include "rays/sdl/item.h"
#include "rays/sdl/keywords.h"

namespace rays::pov {

/// True for the keywords that start an object (primitives, CSG, object copies, light groups and
/// light sources, which may stand among objects).
bool isObjectKind(sdl::Kw k);

/// An object item's entries with its copies unrolled (`object { Base ... }`, `mesh { M ... }`):
/// the base's entries first, then the copy's; returns the kind of what it draws.
sdl::Kw unrollObject(const sdl::Item& item, std::vector<const sdl::Entry*>& out, int depth,
                     std::vector<uint32_t>* marks = nullptr);

}  // namespace rays::pov
