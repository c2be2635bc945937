// Reader for the course scene dialect (a POV-Ray subset) producing a Scene.
#pragma once
#include <functional>
#include <string>

#include "rays/scene/scene.h"

namespace rays {

enum class RotationOrder {
    Course,  ///< R = Rx·Ry·Rz on column vectors (z applied first), the course convention
    Povray,  ///< x applied first, as POV-Ray does
};

struct ParseOptions {
    RotationOrder rotation = RotationOrder::Course;
    /// Receives each warning line ("FILE:LINE:COL: warning: ..."); default prints to stderr.
    std::function<void(const std::string&)> warn;
};

/// Parses scene text. fileName is used in messages only. Throws Error "FILE:LINE:COL: error: ..."
/// on any invalid input; valid POV-Ray keywords Rays does not support produce warnings and are skipped.
Scene parseScene(const std::string& text, const std::string& fileName, const ParseOptions& options = {});

/// Reads and parses a scene file; a missing or unreadable file is an Error naming the path.
Scene loadScene(const std::string& path, const ParseOptions& options = {});

}  // namespace rays
