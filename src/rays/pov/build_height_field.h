// POV-Ray's height_field item (reference 3.4.5.1.5) → the heights of scene/shapes/height_field:
// from an image file (a palette image's index, a grey image's grey, 8- or 16-bit; other colour
// images by their luminance) or from `function W, H { f(x, y) }` sampled on a W × H grid, with
// `smooth` and `water_level`. The image's top row is at z = 1, its columns run along x.
#pragma once
#include <string>
#include <vector>

#include "rays/pov/image_files.h"
#include "rays/scene/shapes/shape_data.h"

namespace rays::pov {

/// Fills data from a height_field's entries (file type, function, smooth, water_level) and sets
/// smooth; false when the field has fewer than 2 × 2 samples. Throws Error "WHERE: error: ..."
/// for a field with neither an image nor a function, or an unreadable file.
/// `name` is the file written without a type (`height_field { "file.png" }`: png), or empty.
/// Returns false also for a file type Rays does not read (noted, the field left out).
/// sampleBudget: the samples a function may be evaluated at before its resolution is refused (what
/// is left of the scene's object limit: each sample counts as an object, as a mesh's triangles do).
bool buildHeightField(const std::vector<const Entry*>& entries, const std::string& name, const sdl::Loc& at,
                      ImageFiles& files, NotRendered& notes, ShapeData& data, bool& smooth, uint64_t sampleBudget);

}  // namespace rays::pov
