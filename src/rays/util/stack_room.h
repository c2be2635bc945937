// How close the calling thread is to the end of its stack: recursive walks whose depth the input
// decides (the SDL reader's nesting, reflection and refraction rays, GI bounces, CSG trees,
// pattern maps) stop before they exhaust it (docs/errors.md "Limits": deep recursion never
// overflows the stack).
#pragma once
#include <cstddef>
#include <cstdint>

namespace rays {

/// Stack kept free below the deepest level a guarded recursion may reach: room for the work
/// between two checks and for throwing an error.
inline constexpr size_t kStackReserve = size_t(256) << 10;

/// The lowest stack address a guarded recursion on this thread may go down to (the stack grows
/// down on the platforms Rays builds for): the stack's low end plus kStackReserve (at most half
/// the stack); 0 when the thread's stack is unknown. Computed once per thread.
uintptr_t threadStackFloor();

/// True when the caller's frame lies below threadStackFloor(): a recursion must not go deeper.
inline bool stackNearlyFull() {
    return reinterpret_cast<uintptr_t>(__builtin_frame_address(0)) < threadStackFloor();
}

}  // namespace rays
