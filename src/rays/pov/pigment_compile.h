// POV-Ray pigment items → the scene's pattern::PigmentTable (POV-Ray 3.7 reference, "Pigment",
// "Patterns", "Pattern Modifiers", "Color Maps", "Pigment Maps"): a pigment's entries in file
// order (a base pigment identifier first, then the pattern, its colour list, map, modifiers and
// transformations). Each pigment item is compiled once; objects that share it share its nodes.
#pragma once
#include <memory>
#include <vector>
#include <unordered_map>

#include "rays/pattern/normal.h"
#include "rays/pattern/pigment.h"
#include "rays/pov/density_files.h"
#include "rays/pov/image_files.h"
#include "rays/pov/item_cache.h"
#include "rays/pov/item_values.h"
#include "rays/pov/not_rendered.h"
#include "rays/pov/pattern_object.h"

namespace rays::pov {

class NormalCompiler;

class PigmentCompiler {
public:
    /// With `normals`, normal items are compiled too (compileNormal).
    PigmentCompiler(pattern::PigmentTable& table, NotRendered& notes, pattern::NormalTable* normals = nullptr);
    ~PigmentCompiler();
    /// The node of a normal item in the NormalTable, or -1 (smooth; noted when not rendered).
    int compileNormal(const Item& normal, double inherited = 0.5);
    /// compileNormal of an item made while building (not the parsed scene's), kept alive as long
    /// as the compiler: compiled items are remembered by address.
    int compileNormal(std::shared_ptr<const Item> made, double inherited = 0.5);
    /// A normal item's amount and whether it writes one (NormalCompiler::amountOf); {0.5, false}
    /// when normals are not compiled.
    std::pair<double, bool> normalAmount(const Item& normal);
    /// True when normals are compiled (a NormalTable was given).
    bool compilesNormals() const { return normalTable_ != nullptr; }
    /// The node of a pigment with a rendered pattern, or -1 for a flat colour (a pigment with no
    /// pattern, or with only patterns Rays does not render: those are noted).
    int compile(const Item& pigment);
    /// compile of an item made while building, kept alive as long as the compiler.
    int compile(std::shared_ptr<const Item> made);
    /// The node of a density item (its pattern, colour or density map, modifiers; density
    /// identifiers as bases): always a node, a Solid node of density 1 when it has no pattern, and
    /// of density 0 when the pattern is not rendered (noted).
    int compileDensity(const Item& density);
    /// The node of a pattern or pigment item as a pattern or pigment function evaluates it
    /// (`function { pattern { ... } }`): always a node (a flat colour is a Solid node), -1 when
    /// the item names a pattern Rays does not render (noted).
    int compileFunction(const Item& item);
    const pattern::PigmentTable& table() const { return table_; }
    /// The scene's image files (image maps here; height fields share them).
    ImageFiles& imageFiles() { return images_; }
    /// How object patterns' objects are built (without a builder they are not rendered: noted).
    void setObjectBuilder(PatternObjectBuilder build) { buildObject_ = std::move(build); }
    /// The #version in force for the items compiled next (image files' default gamma).
    void setLanguageVersion(double version) { version_ = version; }
    DensityFiles& densityFiles() { return densityFiles_; }
    /// A pigment seen through a transformation (its texture space → the enclosing one); node -1
    /// stands for the flat colour.
    struct Placed {
        int node = -1;
        Rgbft flat;
        Transform toEnclosing;
    };
    /// A node drawing texture layer `top` over `below`, both in the enclosing space.
    int layered(const Placed& below, const Placed& top);
    /// A patterned texture (`texture { checker texture { A } texture { B } }`, `texture_map`) as
    /// a pigment: the texture's pattern and modifiers choosing among the textures' pigments
    /// (entries, at `values` in a map); -1 when the pattern is not rendered (noted).
    int patternedTexture(const Item& texture, const std::vector<Placed>& entries, const std::vector<double>& values);
    /// `texture { tiles { texture {A} tile2 texture {B} } }`: a checker of the two (the tiles
    /// block's transformations, then the texture's, move it); -1 when not two entries.
    int tilesTexture(const Item& texture, const Item& tiles, const std::vector<Placed>& entries);
    /// `texture { material_map { TYPE "file" ... texture {A} texture {B} ... } }`: the image's
    /// palette index (or grey byte) modulo the number of textures picks one (POV-Ray 3.7
    /// reference, "Material Maps"); the map's, then the texture's transformations move the image.
    int materialMapTexture(const Item& texture, const Item& map, const std::vector<Placed>& entries);
    /// The pattern of a normal item (its pattern type, modifiers, transformations, warps and wave;
    /// a base normal identifier first) as a node whose map is unused; bumps, dents, ripples, waves
    /// and wrinkles give a node of kind Bozo carrying their modifiers. -1 when the normal has no
    /// rendered pattern (noted "normal pattern X").
    int normalPattern(const Item& normal);

private:
    struct State;
    void read(const Item& pigment, State& s, int depth);
    /// read, then checks what can only be judged once every modifier is read (pavement's).
    void readWhole(const Item& pigment, State& s, int depth);
    void readEntry(const Entry& e, State& s, int depth);
    void readWarp(const Item& warp, State& s);
    /// The image file read (null when the map is not rendered: noted).
    const ImageFile* readImageMap(const Item& map, State& s, bool asPattern = false, bool bump = false);
    void readColorMap(const Item& map, State& s, int depth);
    void readPigmentMap(const Item& map, State& s, int depth);
    /// `object { OBJECT A, B }`: the pattern and its list (colours, pigments or densities).
    void readObjectPattern(const Entry& e, State& s, int depth);
    int emit(State& s);
    void checkPavement(State& s);
    void place(const State& s, pattern::PigmentNode& node);
    int nested(const Item& pigment, int depth);
    int placed(const Placed& p);

    pattern::PigmentTable& table_;
    NotRendered& notes_;
    ItemCache<int> done_;  ///< pigment items compiled to a pattern node
    std::vector<std::shared_ptr<const Item>> made_;  ///< items made while building (compileNormal)
    pattern::NormalTable* normalTable_ = nullptr;
    std::unique_ptr<NormalCompiler> normals_;  ///< made on the first normal
    ImageFiles images_{notes_};
    DensityFiles densityFiles_{notes_};
    PatternObjectBuilder buildObject_;
    double version_ = 3.7;
    ItemCache<std::shared_ptr<const pattern::PatternObject>> objects_;  ///< built per item
};

}  // namespace rays::pov
