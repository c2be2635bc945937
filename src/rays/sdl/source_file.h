// One scene or include file, read once per parse and lexed whole: loops and macros replay its
// tokens by index instead of reading the text again (POV-Ray re-reads the file).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "rays/sdl/token.h"

namespace rays::sdl {

struct SourceFile {
    uint32_t id = 0;             ///< index in the parse's file list (Loc::file)
    std::string path;            ///< the path it was opened by
    std::string shownName;       ///< how messages name it (the name as the scene wrote it)
    std::vector<Token> tokens;   ///< ends with one Tk::End token
    std::vector<std::string> strings;  ///< string literals, escapes decoded
};

/// A position in one of the parse's files: compact, for tokens, values and scene items.
struct Loc {
    uint32_t file = 0;
    uint32_t line = 0;
    uint32_t col = 0;
};

}  // namespace rays::sdl
