// The lexer of POV-Ray's scene language: file text → tokens (token.h). Comments (`//`, nested
// `/* */`) and white space are skipped; `#` and the word after it become one Directive token;
// string escapes (\n \t \" \\ \uNNNN ...) are decoded here.
#pragma once
#include <string_view>

#include "rays/sdl/names.h"
#include "rays/sdl/source_file.h"

namespace rays::sdl {

/// Limits of one file: tokens (and so memory: 24 bytes a token) and string literal length.
inline constexpr size_t kMaxTokensPerFile = size_t(1) << 26;  // 64 Mi tokens, 1.5 GiB
inline constexpr size_t kMaxStringLength = 65536;

/// Lexes text into file.tokens and file.strings. Throws Error "NAME:LINE:COL: error: ..." (NAME =
/// file.shownName) for a malformed number, an unterminated comment or string, or a character
/// that is not part of the language.
void lexFile(std::string_view text, SourceFile& file, Names& names);

}  // namespace rays::sdl
