// How a POV-Ray object looks, as far as Rays renders it today: a pigment (a flat colour, or a
// pattern compiled by PigmentCompiler, with its mean colour kept as the flat one), a normal,
// POV-Ray's finish and interior, and for layered and patterned textures their plain textures.
// Textures, pigments, finishes, interiors and materials of an object are applied to it in file
// order (POV-Ray 3.7 reference, "Texture", "Default Directive"); some pigment patterns are noted
// as not rendered yet.
#pragma once
#include <memory>
#include <vector>

#include "rays/pov/item_values.h"
#include "rays/pov/media_compile.h"
#include "rays/pov/not_rendered.h"
#include "rays/pov/pigment_compile.h"
#include "rays/scene/pov_surface.h"

namespace rays::pov {

/// An interior as read: POV-Ray's interior values and its media, which SceneBuilder places in the
/// scene (copied as a PovInterior, it is the values alone).
struct InteriorLook : PovInterior {
    std::vector<MediaLook> media;
};

struct Appearance {
    bool set = false;     ///< a texture, pigment, finish or material was given
    Rgbft pigment;        ///< POV-Ray's default pigment is black; a pattern's mean colour
    int pigmentNode = -1; ///< the pattern's node in the scene's PigmentTable; -1: the flat colour
    /// Texture space → the space the look was given in: the transformations written after the
    /// pigment (in the texture, then on the object); SceneBuilder completes it to world space.
    Transform pigmentToObject;
    /// POV-Ray's uv_mapping (reference, "UV Mapping"): the pigment is looked up at the surface's
    /// (u, v, 0) moved by pigmentToObject, which the object's transformations then leave alone.
    bool pigmentUV = false;
    int normalNode = -1;  ///< the normal's node in the scene's NormalTable; -1: the surface's own normal
    Transform normalToObject;  ///< like pigmentToObject, for the normal
    /// The normal block normalNode was compiled from: a later `normal { }` without a pattern of
    /// its own modifies it (POV-Ray 3.7 reference, "Default Directive": a texture starts as a
    /// copy of the default one).
    std::shared_ptr<const Item> normalSource;
    /// The pigment block pigmentNode was compiled from: a later `pigment { }` without a pattern or
    /// colour of its own modifies it, as normalSource.
    std::shared_ptr<const Item> pigmentSource;
    PovFinish finish;
    InteriorLook interior;
    bool interiorSet = false;
    /// A layered texture: its layers, the bottom one first, each a plain look (POV-Ray 3.7
    /// reference, "Layered Textures"); the fields above then hold their mix. Empty otherwise.
    std::vector<Appearance> layers;
    /// A patterned texture: the textures its pattern chooses among, in its map's or list's order
    /// ("Patterned Textures"); the fields above then hold their mix. Empty otherwise.
    std::vector<Appearance> choices;
    int patternNode = -1;       ///< the pattern (a node of the PigmentTable) choosing among choices
    Transform patternToObject;  ///< like pigmentToObject, for the pattern
    bool patternUV = false;     ///< like pigmentUV, for the pattern
    int parts = 1;              ///< plain looks in the tree of layers and choices (bounded)
    /// interior_texture: the look of the surface's inner side (one look), or none.
    std::vector<Appearance> inside;
};

/// The look moved by `outer`, applied after what moves it already: its pigment, normal, pattern,
/// layers, choices and its interior's media.
void moveLook(Appearance& a, const Transform& outer);
/// moveLook by a transformation entry (translate, rotate, scale, matrix, transform).
void moveLook(Appearance& a, const Entry& transformation);
/// The look placed by an object's transformation `outer`: moveLook, except that uv-mapped
/// pigments and patterns stay where they are (in the surface's uv space).
void placeLook(Appearance& a, const Transform& outer);
void placeLook(Appearance& a, const Entry& transformation);
/// uv_mapping on a texture or an object: every pigment and pattern of the look is uv-mapped.
void mapLookByUV(Appearance& a);

/// Applies an object modifier entry that concerns appearance (texture, pigment, normal, finish,
/// interior, material); false when the entry is something else. `fallback` is what an unset
/// appearance starts from (the default texture).
/// `pigments` compiles patterns for rendering; without it patterns are drawn in their mean colour.
bool applyAppearanceEntry(const Entry& e, Appearance& a, const Appearance& fallback, NotRendered& notes,
                          PigmentCompiler* pigments = nullptr);

/// c becomes the pigment's flat colour (a pattern's mean colour); patterns are noted when
/// `noteUnrendered` (PigmentCompiler notes those it cannot render itself).
void applyPigment(const Item& pigment, Rgbft& c, NotRendered& notes, bool noteUnrendered = true);
void applyFinish(const Item& finish, PovFinish& f, NotRendered& notes);
/// Applies an interior item over in; its media's densities are compiled by `pigments` (without
/// it: density 1).
void applyInterior(const Item& interior, InteriorLook& in, NotRendered& notes, PigmentCompiler* pigments = nullptr);
/// Applies a texture item over a. A layer of a layered texture starts from `layerBase` (the
/// default texture; POV-Ray's defaults when null), not from the layer below (measured).
void applyTexture(const Item& texture, Appearance& a, NotRendered& notes, PigmentCompiler* pigments = nullptr,
                  const Appearance* layerBase = nullptr);

}  // namespace rays::pov
