// POV-Ray's internal functions, `internal(N)` in functions.inc (reference 3.4.9.1.7 "functions.inc"):
// f_sphere, f_torus, f_helix1, ... Each takes x, y, z and its own parameters and returns one
// float. Formulas are from the reference where it gives them, otherwise rebuilt from the named
// curves and surfaces and checked against values measured with POV-Ray 3.7 (tests/fn_internal_test.cpp).
#pragma once
#include <string_view>

namespace rays::fn {

/// One internal function: its functions.inc name, its parameter count (x, y, z included) and
/// its code (reads args[0 .. params-1]; safe to call from many threads at once).
struct InternalFunction {
    std::string_view name;
    int params = 3;
    double (*fn)(const double* args) = nullptr;
};

/// internal(number), or nullptr when POV-Ray 3.7 defines no such number (77 is unused).
const InternalFunction* internalFunction(int number);

/// The internal number of a functions.inc name ("f_sphere" → 61), or -1.
int internalNumber(std::string_view name);

}  // namespace rays::fn
