// The scene parser's entry for one piece of a file (io/scene_pieces.cpp parses big files in two
// pieces at once; parseInPieces in scene_parser.h).
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

#include "rays/io/scene_parser.h"

namespace rays {

/// A piece's top-level items, without the whole file's checks (a camera, say).
struct ScenePiece {
    Scene scene;
    bool sawEdges = false;  ///< the piece holds an `edges` block
};

/// Parses text, a piece of fileName starting at line firstLine, as parseScene does (same errors
/// and warnings); reserveBytes: the length of the text whose objects the scene will end up holding.
ScenePiece parseScenePiece(std::string_view text, const std::string& fileName, const ParseOptions& options,
                           int firstLine, size_t reserveBytes);

}  // namespace rays
