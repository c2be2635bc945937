// Pattern and pigment functions (`function { pattern { ... } }`, `function { pigment { ... } }`;
// POV-Ray 3.7 reference, "Functions", "Pattern functions"): the item compiled once, as the scene
// builder compiles pigments, into a PigmentTable of its own, and called through a plain host
// function of x, y, z by rays/fn's machine, while parsing and in the render alike.
#pragma once
#include <functional>
#include <string>

#include "rays/fn/program.h"
#include "rays/pov/item_values.h"
#include "rays/pov/not_rendered.h"
#include "rays/pov/pattern_object.h"

namespace rays::pov {

/// The host function of a pattern item (pigment = false: one output, the pattern's value after
/// its transformations, warps, turbulence and wave, its colour map ignored, a block pattern's
/// list index) or of a pigment item (pigment = true: red, green, blue, filter, transmit). It owns
/// its compiled pattern (HostFunction::keep). fn == nullptr when the item names a pattern Rays
/// does not render (noted on `notes`). Image files are found with `findFile`; object patterns'
/// objects are built by `buildObject`. Its patterns without a noise_generator of their own use
/// `noiseGenerator` (the scene's global setting as read so far).
fn::HostFunction compilePatternFunction(const Item& item, bool pigment, NotRendered& notes,
                                        const std::function<std::string(const std::string&)>& findFile,
                                        const PatternObjectBuilder& buildObject, int noiseGenerator = 2);

}  // namespace rays::pov
