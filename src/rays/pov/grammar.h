// POV-Ray's scene items as data: for every block (sphere, texture, pigment, finish, camera,
// light_source, global_settings, ...) the keywords it accepts and what follows each keyword.
// One generic reader (grammar.cpp) reads any block into an sdl::Item with the interpreter's
// token and expression calls, so every keyword of POV-Ray 3.7 is recognised in its place; the
// scene builder later decides which of them Rays renders.
#pragma once
#include <array>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "rays/sdl/interpreter.h"
#include "rays/sdl/item.h"

namespace rays::pov {

using sdl::Kw;

/// What follows a keyword.
enum class Arg : uint8_t {
    Flag,       ///< nothing
    Bool,       ///< [Bool]: an optional float, true when absent
    Float,      ///< a float expression
    OptFloat,   ///< an optional float expression
    Expr,       ///< a float, vector or colour expression
    OptExpr,    ///< an optional expression
    List,       ///< expressions separated by commas: at least one, at most n (0: any number)
    Color,      ///< a colour ([color] ...)
    String,     ///< a string expression
    Sub,        ///< `{ ... }` read with the rule's sub-block spec
    Item,       ///< a whole item the host reads (texture, pigment, an object, ...)
    SubOrExpr,  ///< `{ ... }` with the sub spec, or an expression (finish's `reflection`, ...)
    Function,   ///< `function { ... }` (isosurface, function pattern)
    Custom,     ///< the rule's own reader
};

struct BlockSpec;
using CustomReader = void (*)(sdl::Interpreter& in, sdl::Entry& e);

struct Rule {
    Kw kw;
    Arg arg = Arg::Flag;
    int n = 0;                       ///< List: most expressions (0: any)
    const BlockSpec* sub = nullptr;  ///< Sub, SubOrExpr
    CustomReader custom = nullptr;   ///< Custom
};

/// The key of a `[ ... ]` map entry (colour map, pigment map, ...).
inline constexpr uint16_t kMapEntry = 0xFFFE;

struct BlockSpec {
    enum class Map : uint8_t { None, Colors, Bodies, Slopes };
    const char* name = "";     ///< for messages: "a sphere", "a finish", ...
    Kw kind = Kw::object;      ///< the item kind a map entry's body becomes (pigment_map: pigment)
    bool positionals = false;  ///< bare values (a sphere's centre, a pigment's colour)
    bool children = false;     ///< objects and lights inside (CSG, light_group, clipped_by, ...)
    bool coefficients = false; ///< `<...>` holds any number of floats (cubic, quartic, poly)
    Map map = Map::None;
    const BlockSpec* mapBody = nullptr;  ///< Bodies: what a `[v BODY]` entry holds
    std::vector<Rule> rules;

    /// The rule for keyword k, or null.
    const Rule* find(Kw k) const {
        const int16_t i = index[size_t(k)];
        return i < 0 ? nullptr : &rules[size_t(i)];
    }
    /// Builds the keyword index; call once the rules are final.
    void seal();

private:
    std::array<int16_t, sdl::kKeywordCount> index{};
};

/// Rules grouped for reuse: a spec is made of several groups.
using RuleGroup = std::vector<Rule>;
BlockSpec makeSpec(const char* name, Kw kind, std::initializer_list<const RuleGroup*> groups, bool positionals = false,
                   bool children = false, BlockSpec::Map map = BlockSpec::Map::None, const BlockSpec* mapBody = nullptr);

/// Reads the block whose keyword is current: `KEYWORD { body }` with spec.
sdl::ItemRef readBlock(sdl::Interpreter& in, const BlockSpec& spec);
/// Reads `{ body }` (the '{' current) as an item of the given kind.
sdl::ItemRef readBlockBody(sdl::Interpreter& in, const BlockSpec& spec, Kw kind);
/// `first` and the `texture { }` blocks that follow it in the text (the next is `texture`), as one
/// layered texture: a texture item whose bare entries are the layers, bottom first.
sdl::ItemRef readTextureLayers(sdl::Interpreter& in, const BlockSpec& spec, sdl::ItemRef first);
/// Reads a block's body up to (not including) terminator into item.
void readBody(sdl::Interpreter& in, sdl::Item& item, const BlockSpec& spec, char terminator);

/// The spec of an item keyword (objects, textures, camera, ...), or null when k starts no item.
const BlockSpec* itemSpec(Kw k);

}  // namespace rays::pov
