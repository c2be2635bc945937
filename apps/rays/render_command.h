// The render pipeline behind `rays render`, `rays raycast` and the positional form:
// load scene (+ optional OBJ), build the BVH, render with progress, write the image atomically.
#pragma once
#include <string>

#include "rays/io/scene_parser.h"
#include "rays/render/settings.h"

namespace rays::cli {

struct RenderJob {
    std::string scenePath;
    std::string outputPath = "output.png";
    std::string objPath;  ///< optional OBJ mesh added with a default material
    RenderSettings settings;
    RotationOrder rotation = RotationOrder::Course;
    int jpegQuality = 90;
    bool quiet = false;   ///< no progress bar, no summary line
    bool stats = false;   ///< extra counters on stderr
};

/// Runs the job; throws Error on bad input. Returns the process exit status (0).
int runRender(const RenderJob& job);

/// Loads the scene and, when objPath is set, appends its triangles.
Scene loadSceneWithObj(const std::string& scenePath, const std::string& objPath, RotationOrder rotation);

/// Throws Error when w×h is not a sensible image size.
void checkImageSize(int width, int height);

}  // namespace rays::cli
