// POV-Ray 3.7's string values and its string functions (str, vstr, val, chr, asc, strlen, substr,
// strupr, strlwr, strcmp, concat) and how #write prints floats, reproduced from black-box
// experiments with the installed povray binary: the cases and POV-Ray's answers are in
// tests/data/povray/pov_strings.* and pov_string_errors.*; docs/scene-language-numbers.md sums up
// the rules. Integer parameters arrive already converted with povInt (pov_int.h).
//
// A POV-Ray string is a sequence of 16-bit character codes: chr accepts 0..65535, asc(chr(960))
// is 960 and strlen counts codes. Code 0 ends a string (chr(0) is the empty string), so no string
// holds one. Where POV-Ray hands a string to C (val, datetime's format) or writes it out (#write,
// #debug), codes 128 and above become spaces.
#pragma once
#include <span>
#include <string>
#include <string_view>

#include "rays/sdl/outcome.h"

namespace rays::sdl {

/// A POV-Ray string value: 16-bit character codes, none of them 0.
using PovString = std::u16string;

/// ASCII text as a string value: bytes 128..255 become spaces (as charset ascii, POV-Ray 3.7's
/// default, reads a string literal); the text ends at a NUL byte.
PovString povString(std::string_view ascii);
/// The bytes POV-Ray hands to C and to its output streams: codes 128 and above become spaces.
std::string povNarrow(const PovString& s);

// ---- numbers → text --------------------------------------------------------------------------

/// The longest string str() returns; longer results fall back to %g, then to "<invalid>".
constexpr int kStrMaxLength = 254;
/// The longest component vstr() formats; POV-Ray 3.7 aborts ("buffer overflow") beyond it.
constexpr int kVstrMaxComponentLength = 767;

/// str(A, L, P): printf "%*.*f" (zero padded when L < 0, width |L|; P < 0 is C's default, 6);
/// a result over 254 characters is formatted "%*.*g" instead, and if that is too long as well
/// the result is "<invalid>".
std::string povStr(double a, int minLen, int precision);
/// vstr(N, A, S, L, P): N is clamped to 2..5; `given` holds A's components (one for a float:
/// POV-Ray then fills the others with 0, not with A); missing ones are 0, extra ones ignored.
/// Each component is formatted as str formats without its fallbacks; an L that converted to
/// INT_MIN gives empty components. A component over 767 characters is an error (POV-Ray aborts).
Outcome<PovString> povVstr(int dims, std::span<const double> given, const PovString& separator,
                           int minLen, int precision);
/// How #write prints a float: printf "%g" (1e+06, 1e-05, -0, inf, nan).
std::string povWriteFloat(double v);
/// How #write prints a vector: "<" components as %g joined by "," "> " (with the trailing space).
std::string povWriteVector(std::span<const double> components);

// ---- text → numbers --------------------------------------------------------------------------

/// val(S): C's strtod in the "C" locale on povNarrow(S): leading white space skipped, trailing
/// text ignored, hexadecimal, inf and nan accepted, 0 when nothing parses; never an error.
double povVal(const PovString& s);
/// asc(S): the first character code, 0 for the empty string.
int povAsc(const PovString& s);
/// strlen(S): the number of character codes.
int povStrlen(const PovString& s);
/// strcmp(A, B): the difference of the first differing codes (a missing code counts as 0); 0 if equal.
int povStrcmp(const PovString& a, const PovString& b);

// ---- strings → strings -----------------------------------------------------------------------

/// chr(B): the one-code string B (0 gives the empty string); outside 0..65535
/// "Value B cannot be used in chr(...).".
Outcome<PovString> povChr(int code);
/// substr(S, P, L): L codes from the 1-based position P; P = 0 gives the empty string. P < 0,
/// L < 0 or P + L − 1 > strlen(S) is "Illegal parameters in substr.".
Outcome<PovString> povSubstr(const PovString& s, int pos, int len);
/// strupr(S): ASCII a–z to A–Z; other codes unchanged.
PovString povStrupr(PovString s);
/// strlwr(S): ASCII A–Z to a–z; other codes unchanged.
PovString povStrlwr(PovString s);
/// concat(S1, ...): the strings joined (POV-Ray accepts a single argument too).
PovString povConcat(std::span<const PovString> parts);

}  // namespace rays::sdl
