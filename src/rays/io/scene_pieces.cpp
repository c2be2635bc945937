// Big scene files parsed in two pieces on two threads (parseInPieces, declared in scene_parser.h).
#include "rays/io/scene_pieces.h"

#include <algorithm>
#include <optional>
#include <thread>

#include "rays/io/scene_parser.h"
#include "rays/util/worker_pool.h"

namespace rays {
namespace {

// A big file is cut at the start of a line, after its middle, where a top-level item seems to
// begin (an object or light keyword at the line's start), and the two pieces are parsed on two
// threads. Parsing the first piece checks the cut: it ends inside a comment or a block exactly
// when the cut is not between two top-level items, and then fails. Nothing a piece parses changes
// how the other is read except what the second piece is not allowed to hold: textures and meshes
// (indices into the first piece's lists), transforms of textures and an `edges` block. A piece
// that fails, warns or holds those sends the file to one parser, so errors, warnings and their
// order are always those of the whole file.

constexpr size_t kPiecesMin = 256 * 1024;

// Where the second piece starts, or 0 for no cut.
size_t cutPoint(std::string_view text) {
    static constexpr std::string_view kStarts[] = {"sphere", "triangle", "box", "cone", "plane", "light_source"};
    for (size_t nl = text.find('\n', text.size() / 2); nl != std::string_view::npos; nl = text.find('\n', nl + 1)) {
        const std::string_view line = text.substr(nl + 1);
        for (std::string_view k : kStarts)
            if (line.size() > k.size() && line.substr(0, k.size()) == k &&
                (line[k.size()] == ' ' || line[k.size()] == '{' || line[k.size()] == '\t'))
                return nl + 1;
    }
    return 0;
}

struct Piece {
    std::optional<Scene> scene;
    bool clean = false;  ///< parsed without error or warning
    bool sawEdges = false;
};

void parsePiece(std::string_view text, const std::string& file, const ParseOptions& base, int firstLine,
                size_t reserveBytes, Piece& out) {
    bool warned = false;
    ParseOptions opt = base;
    opt.warn = [&warned](const std::string&) { warned = true; };
    try {
        ScenePiece piece = parseScenePiece(text, file, opt, firstLine, reserveBytes);
        out.scene = std::move(piece.scene);
        out.sawEdges = piece.sawEdges;
        out.clean = !warned;
    } catch (...) {
        out.clean = false;  // one parser will say what is wrong
    }
}

}  // namespace

std::optional<Scene> parseInPieces(std::string_view text, const std::string& file, const ParseOptions& options) {
    if (text.size() < kPiecesMin) return std::nullopt;
    if (options.threads == 1 || (options.threads <= 0 && std::thread::hardware_concurrency() < 2))
        return std::nullopt;
    const size_t cut = cutPoint(text);
    if (cut == 0) return std::nullopt;
    const int secondLine = 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(cut), '\n'));
    Piece first, second;
    runAlongside(0, 1, [&](int) { parsePiece(text.substr(cut), file, options, secondLine, 0, second); },
                 [&] { parsePiece(text.substr(0, cut), file, options, 1, text.size(), first); });
    if (!first.clean || !second.clean) return std::nullopt;
    Scene& a = *first.scene;
    Scene& b = *second.scene;
    if (!b.textures.empty() || !b.meshes.empty() || !b.textureTransforms.empty() || second.sawEdges)
        return std::nullopt;
    if (a.cameras.empty() && b.cameras.empty()) return std::nullopt;  // one parser gives the error
    a.cameras.insert(a.cameras.end(), b.cameras.begin(), b.cameras.end());
    a.lights.insert(a.lights.end(), b.lights.begin(), b.lights.end());
    a.objects.insert(a.objects.end(), b.objects.begin(), b.objects.end());
    return std::move(a);
}

}  // namespace rays
