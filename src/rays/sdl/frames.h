// The interpreter's control state: one Frame per file being read or macro being run (each with
// the #if / #switch / #while / #for blocks open in it), the include and macro call stack that
// error messages show.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "rays/sdl/interpreter.h"

namespace rays::sdl {

struct Interpreter::Ctl {
    enum Kind : uint8_t { If, Switch, While, For };
    Kind kind = If;
    Loc loc;               ///< the opening directive
    uint32_t pos = 0;      ///< While: the `#while` token; For: the first token of the body
    // Switch
    double value = 0;
    // For
    uint32_t var = 0;
    double end = 0, step = 1;
};

struct Interpreter::Frame {
    enum Kind : uint8_t { Main, Include, Macro };
    const SourceFile* file = nullptr;
    uint32_t pos = 0;                 ///< next token to read
    Kind kind = Main;
    bool ownScope = false;            ///< a scope level was opened for this frame
    Loc site;                         ///< include directive or macro call
    std::vector<Ctl> ctl;
    std::shared_ptr<const MacroDef> macro;
    SmallVec<ByRefArg, 4> byRef;
};

}  // namespace rays::sdl
