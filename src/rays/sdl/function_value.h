// A user function value (`function { ... }`): an entry of the parse's function table
// (src/rays/fn), compiled from its body as it was read (macros in the body ran once, identifiers
// of floats became constants). Pattern, pigment, transform and spline functions are the table's
// host entries (the host compiles pattern and pigment items: ItemHost::patternFunction); they
// keep the item they wrap.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "rays/fn/function_table.h"
#include "rays/sdl/item.h"
#include "rays/sdl/source_file.h"
#include "rays/sdl/value.h"

namespace rays::sdl {

struct FunctionValue {
    enum class Kind : uint8_t { Float, Pattern, Pigment, Transform, Spline };
    Kind kind = Kind::Float;
    Loc loc;                                  ///< the `function` keyword
    std::vector<uint32_t> params;             ///< parameter names (x y z when none were written)
    std::shared_ptr<fn::FunctionTable> table; ///< the parse's functions
    int index = -1;                           ///< this function's entry in table
    ItemRef item;                             ///< Pattern, Pigment, Transform: what the host read
    Value spline;                             ///< Spline
};

/// True for the host function standing in for a pattern or pigment function that the host could
/// not compile (it gives 0).
bool isPatternStub(const fn::HostFunction& h);

}  // namespace rays::sdl
