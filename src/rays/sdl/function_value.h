// A user function value (`function { ... }`): its parameters and where its body is; the
// function machine (src/rays/fn) compiles float bodies. Pattern, pigment, transform and spline
// functions keep the item or spline they wrap.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "rays/sdl/item.h"
#include "rays/sdl/source_file.h"
#include "rays/sdl/value.h"

namespace rays::sdl {

struct FunctionValue {
    enum class Kind : uint8_t { Float, Pattern, Pigment, Transform, Spline };
    Kind kind = Kind::Float;
    Loc loc;                       ///< the `function` keyword
    std::vector<uint32_t> params;  ///< parameter names (x y z when none were written)
    uint32_t file = 0;             ///< Float: the body's tokens, from bodyStart to bodyEnd (the '}')
    uint32_t bodyStart = 0, bodyEnd = 0;
    ItemRef item;                  ///< Pattern, Pigment, Transform: what the host read
    Value spline;                  ///< Spline
};

}  // namespace rays::sdl
