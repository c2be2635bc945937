// The built-in functions that depend on their arguments only (POV-Ray 3.7 reference, "Float
// Functions", "Vector Functions"), kept apart from the reader (builtins.cpp) so that any other
// evaluator of expressions computes exactly the same values.
#pragma once
#include "rays/sdl/keywords.h"
#include "rays/sdl/value.h"

namespace rays::sdl {

/// The function of one float (abs … tanh, int, ln, log, degrees, radians) of keyword k, or null.
double (*mathFunction1(Kw k))(double);
/// atan2, pow, mod and div of two floats; false for any other keyword.
bool mathFunction2(Kw k, double a, double b, double& out);
/// vdot, vlength, vcross, vnormalize, vrotate, vaxis_rotate (n arguments, floats promoted to
/// <f, f, f>); false for another keyword, a wrong count, a non-numeric argument, or a zero vector
/// where one is not allowed (the reader reports those).
bool vectorFunction(Kw k, const Num* args, int n, Num& out);

}  // namespace rays::sdl
