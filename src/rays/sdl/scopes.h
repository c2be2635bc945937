// Identifier scopes as POV-Ray defines them (3.7 reference, "Identifier Name Collisions"):
// level 0 is the main file's (global) table; each include file and macro call opens a new
// level. `#local` binds at the current level; `#declare` assigns the most local binding of a
// name that exists and creates a new name at level 0; lookups find the most local binding.
// Each name keeps its own stack of bindings, so a lookup is one index (shallow binding).
#pragma once
#include <cstdint>
#include <vector>

#include "rays/sdl/value.h"

namespace rays::sdl {

struct Binding {
    Value value;
    uint32_t level = 0;
    uint32_t serial = 0;       ///< unique per binding: macro parameters passed by reference find theirs again
    bool deprecated = false;   ///< `#declare deprecated`: a warning on each use (or once)
    bool deprecatedOnce = false;
    uint32_t deprecatedMessage = UINT32_MAX;  ///< index into the interpreter's message list
};

class Scopes {
public:
    uint32_t level() const { return levels_ - 1; }
    void pushLevel() {
        // Levels are reused (their name lists keep their capacity): macro calls allocate nothing here.
        if (levels_ == levelNames_.size()) levelNames_.emplace_back();
        else levelNames_[levels_].clear();
        ++levels_;
    }
    /// Destroys every binding made at the current level.
    void popLevel();

    /// The most local binding of name, or null.
    Binding* find(uint32_t name) {
        return name < stacks_.size() && !stacks_[name].empty() ? &stacks_[name].back() : nullptr;
    }
    /// The binding of name with this serial number, or null when it is gone.
    Binding* findSerial(uint32_t name, uint32_t serial);

    /// `#declare name = v`.
    Binding& declare(uint32_t name, Value v);
    /// `#local name = v`.
    Binding& local(uint32_t name, Value v) { return localAt(name, std::move(v), level()); }
    /// `#declare` / `#local` made while level `lvl` was current (the value may have been computed
    /// inside a macro called from there, whose level is gone by the time the name is bound).
    Binding& declareAt(uint32_t name, Value v, uint32_t lvl);
    Binding& localAt(uint32_t name, Value v, uint32_t lvl);
    /// `#undef name`: false when it was not defined.
    bool undef(uint32_t name);

private:
    Binding& push(uint32_t name, Value v, uint32_t lvl);

    std::vector<std::vector<Binding>> stacks_;          ///< by name id; back() is the most local
    std::vector<std::vector<uint32_t>> levelNames_{1};  ///< names bound at each level (the first levels_ are in use)
    uint32_t levels_ = 1;
    uint32_t serial_ = 0;
};

}  // namespace rays::sdl
