// An object item built alone, as the scene builder builds it for the scene, into a Scene of its own
// (not part of the rendered scene): what trace(), inside(), min_extent() and max_extent() ask
// about while parsing, and the object of an object pattern (pattern_object.h).
#pragma once
#include <functional>
#include <string>

#include "rays/io/ttf_font.h"
#include "rays/scene/scene.h"
#include "rays/sdl/item.h"

namespace rays::pov {

struct StandaloneObject {
    Scene scene;
    /// Every shape of the object could be built (a texture drawn otherwise does not count: only the
    /// shapes matter here).
    bool complete = true;
};

/// Builds `object` (any object item: a shape, CSG, text, a mesh, `object { ... }`) with its own
/// transformations; notes stay quiet. where formats "FILE:LINE:COL" for errors; files (fonts,
/// images) are found with findFile; fonts are read through `fonts` (kept by the caller).
StandaloneObject buildStandalone(const sdl::ItemRef& object, const std::function<std::string(const sdl::Loc&)>& where,
                                 const std::function<std::string(const std::string&)>& findFile, FontCache* fonts);

}  // namespace rays::pov
