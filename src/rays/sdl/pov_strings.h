// POV-Ray's string functions as plain functions (no source locations: errors come back as
// Outcome messages the interpreter places).
#pragma once
#include <string>
#include <string_view>

#include "rays/sdl/outcome.h"

namespace rays::sdl {

/// str(v, L, P): |L| minimum width (L < 0 pads with zeros), P decimals (P < 0: 6).
Outcome<std::string> povStr(double v, int minLen, int precision);
/// vstr(N, V, S, L, P): the first N (2..5) components of V joined by S, each as str.
Outcome<std::string> povVstr(int n, const double* comps, int dim, const std::string& sep, int minLen, int precision);
/// chr(c).
Outcome<std::string> povChr(int code);
/// substr(s, p, l): p is 1-based.
Outcome<std::string> povSubstr(const std::string& s, int pos, int len);
/// datetime(days since 2000-01-01, strftime format).
Outcome<std::string> povDatetime(double days, const std::string& format);
/// val(s): the number at the start of s (0 when none).
double povVal(std::string_view s);

}  // namespace rays::sdl
