// The object of an object pattern (`object { OBJECT LIST_ITEM_A, LIST_ITEM_B }`; POV-Ray 3.7
// reference, "Object Pattern"): the pattern item's object with its modifiers, built alone as
// inside() builds its object (standalone_object.h), kept as pattern::PatternObject's inside test.
// Built once while building the scene; immutable afterwards, so the render's threads share it.
#pragma once
#include <functional>
#include <memory>
#include <string>

#include "rays/io/ttf_font.h"
#include "rays/pattern/object_pattern.h"
#include "rays/sdl/item.h"

namespace rays::pov {

/// True for the entries of an object pattern item that are its list's items (colours, pigments,
/// normals, textures, densities) rather than its object or the object's modifiers.
bool isObjectPatternListEntry(const sdl::Entry& e);

struct BuiltPatternObject {
    std::shared_ptr<const pattern::PatternObject> object;  ///< null when the item names no object
    bool complete = true;    ///< every shape of the object was built
};

/// The inside test of an object item built alone inside an intersection of one, so that `inverse`
/// turns it inside out (alone when that leaves a part out: a mesh without inside_vector). What the
/// inside() function and the object pattern ask.
BuiltPatternObject buildInsideTest(const sdl::ItemRef& object, const std::function<std::string(const sdl::Loc&)>& where,
                                   const std::function<std::string(const std::string&)>& findFile, FontCache* fonts);

/// The object of the object pattern item `pattern` (its entries but the list's items, as an
/// `object { }` item), with its own transformations; the pattern's transformations apply on top
/// (the pigment node's).
BuiltPatternObject buildPatternObject(const sdl::Item& pattern, const std::function<std::string(const sdl::Loc&)>& where,
                                      const std::function<std::string(const std::string&)>& findFile, FontCache* fonts);

/// How a pigment compiler has its object patterns' objects built (null: not rendered).
using PatternObjectBuilder = std::function<BuiltPatternObject(const sdl::Item& pattern)>;

}  // namespace rays::pov
