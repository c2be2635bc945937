// How a POV-Ray object looks, as far as Rays renders it today: a flat pigment colour (rgb,
// filter, transmit), POV-Ray's finish and interior. Textures, pigments, finishes, interiors and
// materials of an object are applied to it in file order (POV-Ray 3.7 reference, "Texture",
// "Default Directive"); patterns, normals and layers are noted as not rendered yet.
#pragma once
#include "rays/pov/item_values.h"
#include "rays/pov/not_rendered.h"
#include "rays/scene/pov_surface.h"

namespace rays::pov {

struct Appearance {
    bool set = false;     ///< a texture, pigment, finish or material was given
    Rgbft pigment;        ///< POV-Ray's default pigment is black
    PovFinish finish;
    PovInterior interior;
    bool interiorSet = false;
};

/// Applies an object modifier entry that concerns appearance (texture, pigment, normal, finish,
/// interior, material); false when the entry is something else. `fallback` is what an unset
/// appearance starts from (the default texture).
bool applyAppearanceEntry(const Entry& e, Appearance& a, const Appearance& fallback, NotRendered& notes);

void applyPigment(const Item& pigment, Rgbft& c, NotRendered& notes);
void applyFinish(const Item& finish, PovFinish& f, NotRendered& notes);
void applyInterior(const Item& interior, PovInterior& in, NotRendered& notes);
void applyTexture(const Item& texture, Appearance& a, NotRendered& notes);

}  // namespace rays::pov
