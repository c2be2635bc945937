// Reader for the course scene dialect (a POV-Ray subset) producing a Scene.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "rays/scene/scene.h"
#include "rays/sdl/options.h"

namespace rays {

enum class RotationOrder {
    Course,  ///< R = Rx·Ry·Rz on column vectors (z applied first), the course convention
    Povray,  ///< x applied first, as POV-Ray does
};

struct ParseOptions {
    RotationOrder rotation = RotationOrder::Course;
    /// Receives each warning line ("FILE:LINE:COL: warning: ..."); default prints to stderr.
    std::function<void(const std::string&)> warn;
    /// POV-Ray dialect only: called now and then while the scene language runs; throws to stop it
    /// (Ctrl-C). A course-dialect file is read without calling it.
    std::function<void()> checkInterrupt;
    /// Threads for a big file (256 KiB or more): with 0 (all hardware threads) or 2 and more, it is
    /// parsed in two pieces at once when it can be cut between two top-level items; the scene,
    /// warnings and errors are those of parsing it whole.
    int threads = 0;
    /// Include paths, command-line declarations, the animation clock, the image size and the
    /// dialect (POV-Ray scene language); the course dialect reads none of them.
    sdl::LanguageOptions language;
};

/// Parses scene text in the course dialect. fileName is used in messages only. Throws Error "FILE:LINE:COL: error: ..."
/// on any invalid input; valid POV-Ray keywords Rays does not support produce warnings and are skipped.
Scene parseScene(const std::string& text, const std::string& fileName, const ParseOptions& options = {});

/// Reads and parses a scene file; a missing or unreadable file is an Error naming the path. The
/// file is read as POV-Ray 3.7 (src/rays/pov) when options.language.dialect says so, or, with
/// Dialect::Auto, when it holds a '#' directive or global_settings (pov::looksLikePovray);
/// otherwise as the course dialect.
Scene loadScene(const std::string& path, const ParseOptions& options = {});

/// The scene of text parsed in two pieces on two threads (ParseOptions::threads), or nothing when
/// the text is below 256 KiB, only one thread is allowed, no cut between two top-level items is
/// found after its middle, or a piece fails, warns, or holds textures, meshes or an `edges` block;
/// parseScene and loadScene then read it whole. A scene it returns is the one parseScene would.
std::optional<Scene> parseInPieces(std::string_view text, const std::string& fileName, const ParseOptions& options);

}  // namespace rays
