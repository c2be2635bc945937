// The render pipeline behind `rays render`, `rays raycast` and the positional form:
// load scene (+ optional OBJ), build the BVH, render with progress, write the image atomically.
#pragma once
#include <string>

#include "rays/io/scene_parser.h"
#include "rays/image/kernels.h"
#include "rays/npr/edge_settings.h"
#include "rays/render/settings.h"

namespace rays::cli {

/// Feature-line options given on the command line; unset ones keep the scene's `edges { }` values.
struct EdgeOptions {
    std::string types;        ///< --edges LIST
    std::string method;       ///< --edge-method
    std::string width;        ///< --edge-width (checked by resolveEdges, as every value here)
    std::string color;        ///< --edge-color R,G,B
    std::string creaseAngle;  ///< --crease-angle
    bool linesOnly = false;   ///< --lines-only
    std::string maskPath;     ///< --edge-mask FILE
};

/// The scene's edge settings with the command line's overrides applied; throws Error on bad values.
EdgeSettings resolveEdges(const EdgeSettings& fromScene, const EdgeOptions& o);

/// What one render took (for the MPI summary, apps/rays/mpi): phase times and rays traced.
struct RenderFigures {
    double parseBuildMs = 0;  ///< loading the scene and building the BVH
    double renderMs = 0;      ///< rendering (with the post filters and feature lines)
    double writeMs = 0;       ///< encoding and writing the files
    double rays = 0;          ///< rays traced by this process
};

struct RenderJob {
    std::string scenePath;
    std::string outputPath = "output.png";
    std::string objPath;  ///< optional OBJ mesh added with a default material
    RenderSettings settings;
    EdgeOptions edges;
    std::vector<KernelSpec> post;  ///< --post: filters applied to the rendered image (before lines)
    RotationOrder rotation = RotationOrder::Course;
    int jpegQuality = 90;
    std::string aovs;      ///< --aov LIST: depth,normal,albedo,objectid,materialid,coverage (docs/aov.md)
    bool exrHalf = false;  ///< --exr-half: the EXR's colour channels as 16-bit half floats
    bool quiet = false;   ///< no progress bar, no summary line
    bool stats = false;   ///< extra counters on stderr
    bool savePartial = false;  ///< --save-partial: on Ctrl-C, keep what was rendered as OUTPUT.partial.png
    bool summary = true;  ///< the "rays: wrote ..." line (an animation prints its own line per frame)
    /// false (POV-Ray's Output_to_File=off, -F): the image is rendered and no image file is written
    /// (neither the image nor the AOV files named after it; an edge mask asked for by name is).
    bool outputToFile = true;
    /// POV-Ray's Bits_Per_Color (+FN16): above 8 a PNG image has 16 bits per channel (other
    /// formats keep 8, with a warning).
    int bitsPerColor = 8;
    /// Under MPI: this process renders and writes the job by itself (a frame handed out whole,
    /// apps/rays/mpi/mpi_frames.h) instead of sharing it with the other ranks.
    bool alone = false;
    RenderFigures* figures = nullptr;  ///< when set, receives what the render took
    /// For the scene language: library paths, declarations, the frame's clock, dialect; the image
    /// size is filled in from settings when the scene is loaded.
    sdl::LanguageOptions language;
};

/// Runs the job; throws Error on bad input and Interrupted (interrupt.h) after Ctrl-C or SIGTERM.
/// Returns the process exit status (0).
int runRender(const RenderJob& job);

/// Loads the job's scene as every command does: the scene language sees job.language with the
/// image size set from job.settings (`image_width`, `image_height`); big files are parsed on two
/// threads unless settings.threads is 1 (ParseOptions::threads); objPath's triangles are appended.
/// outputs: the files the run will write, which the scene's `#fopen ... write` may not name.
Scene loadJobScene(const RenderJob& job, const std::vector<std::string>& outputs = {});

/// Throws Error when w×h is not a sensible image size.
void checkImageSize(int width, int height);

}  // namespace rays::cli
