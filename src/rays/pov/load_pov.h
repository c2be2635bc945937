// Reading a POV-Ray 3.7 scene file into Rays' Scene: the scene language (src/rays/sdl) with the
// POV-Ray grammar and host (this folder), then the scene builder. Also the rule that decides
// whether a file is read as POV-Ray or as the course dialect.
#pragma once
#include <string>
#include <string_view>

#include "rays/io/scene_parser.h"
#include "rays/scene/scene.h"

namespace rays::sdl {
struct Limits;
}

namespace rays::pov {

/// Parses and builds a POV-Ray scene held in memory (shownName names it in messages; folder is
/// where its includes are looked up first). Warnings (language warnings, "not rendered yet"
/// notes) go to options.warn (stderr when unset), #debug text to stderr. Throws Error.
Scene parsePovText(std::string_view text, const std::string& shownName, const std::string& folder,
                   const ParseOptions& options);
/// The same with the scene language's limits (sdl::Limits: loop iterations, macro and include
/// depth, nesting, tokens) instead of the defaults; fuzz/ lowers them to keep each input short.
Scene parsePovText(std::string_view text, const std::string& shownName, const std::string& folder,
                   const ParseOptions& options, const sdl::Limits& limits);

/// True when text is read as POV-Ray 3.7: it holds a `#` directive or `global_settings` outside
/// comments and strings. The course dialect has neither.
bool looksLikePovray(std::string_view text);

}  // namespace rays::pov
