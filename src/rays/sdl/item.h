// A scene item as the language holds it: what the host's grammar read (an object, texture,
// pigment, finish, camera, light, transform, colour map, ...), kept as a tree of entries in file
// order with their locations. The language stores items in identifiers and copies them; only the
// host gives them meaning (pbrt-v4 keeps a parsed scene's parameters the same way).
#pragma once
#include <memory>
#include <vector>

#include "rays/sdl/keywords.h"
#include "rays/sdl/value.h"

namespace rays::sdl {

/// The key of an entry that is a bare value (a sphere's centre, a map entry's colour, an
/// identifier naming another item) rather than a keyword and its arguments.
inline constexpr uint16_t kPositional = 0xFFFF;

struct Entry {
    uint16_t key = kPositional;  ///< Kw, or kPositional
    Loc loc;                     ///< where the keyword (or value) was written
    std::vector<Value> args;     ///< arguments in order; nested blocks are Item values

    Kw kw() const { return Kw(key); }
    bool positional() const { return key == kPositional; }
};

/// Made through std::make_shared (ItemRef) by the host's grammar; weak_from_this() lets a cache
/// keyed by an item's address keep it alive (pov/item_cache.h).
struct Item : std::enable_shared_from_this<Item> {
    Kw kind = Kw::object;  ///< the keyword that opened it (sphere, union, texture, pigment, ...)
    Loc loc;
    std::vector<Entry> entries;
    uint32_t depth = 1;  ///< levels of items in it, itself included (the host sets it when read)
    /// What the host noted when it read the item (POV-Ray scenes: how many #default entries were
    /// in force then); the language only copies it.
    uint32_t hostMark = 0;
    uint64_t size = 1;   ///< items in it, itself included, a shared item once per use (the host sets it)
};

using ItemRef = std::shared_ptr<const Item>;

}  // namespace rays::sdl
