// POV-Ray 3.7's clock functions: `now` (days since 2000-01-01 00:00:00 UTC) and
// datetime(D [, FORMAT]), measured with the installed povray binary (cases and answers in
// tests/data/povray/pov_strings.* and pov_string_errors.*; docs/scene-language-numbers.md).
#pragma once
#include <string_view>

#include "rays/sdl/outcome.h"
#include "rays/sdl/pov_strings.h"

namespace rays::sdl {

/// datetime's format when none is given.
constexpr std::string_view kDatetimeDefaultFormat = "%Y-%m-%d %H:%M:%SZ";

/// now: the current time in days since 2000-01-01 00:00:00 UTC (fractional; each call reads the clock).
double povNow();

/// datetime(D, FORMAT): the UTC time D days after 2000-01-01 00:00:00, rounded to the nearest
/// second, formatted by the C library's strftime (C locale names; %Z and %z print nothing).
/// Errors as POV-Ray's: "Empty format string."; "Year is out of valid range: 1400..9999" (the
/// proleptic Gregorian calendar from 1400-01-01 to 9999-12-31 23:59:59); "Invalid formatting code
/// in format string, or resulting string too long." when the result is empty or over 199 characters.
Outcome<PovString> povDatetime(double days, const PovString& format);

}  // namespace rays::sdl
