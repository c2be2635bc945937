// What the host tells the scene language before a parse: where include files are found,
// identifiers declared on the command line, the animation clock, the image size, the dialect
// and --strict. Plain values; the language reads them, never changes them. (Warnings and Ctrl-C
// reach the language through interpreter.h's Diagnostics.)
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace rays::sdl {

/// A `Declare=NAME=VALUE` INI key or `Declare=` switch: VALUE is a float literal, or a string in
/// double quotes.
struct Declare {
    std::string name;
    std::string value;
};

/// POV-Ray's animation identifiers for one frame (POV-Ray 3.7 reference, "Animation Options"):
/// clock = initialClock + (finalClock − initialClock)·(frame − initialFrame)/(finalFrame − initialFrame).
struct AnimationClock {
    double clock = 0;         ///< `clock`
    double clockDelta = 0;    ///< `clock_delta`: clock difference between two frames (0 for a still)
    int frameNumber = 0;      ///< `frame_number`
    int initialFrame = 1, finalFrame = 1;      ///< `initial_frame`, `final_frame`
    double initialClock = 0, finalClock = 1;   ///< `initial_clock`, `final_clock`
    bool clockOn = false;     ///< `clock_on`: true when rendering an animation
};

/// Which rules a scene file follows: the course dialect or POV-Ray 3.7.
enum class Dialect { Auto, Course, Povray };

struct LanguageOptions {
    /// Folders searched for `#include` files after the scene's own folder, in order
    /// (`+L` switches and `Library_Path` INI keys), then `installedIncludeDir`.
    std::vector<std::string> libraryPaths;
    /// POV-Ray's include files (Debian's povray-includes); searched last.
    std::string installedIncludeDir = "/usr/share/povray-3.7/include";
    std::vector<Declare> declares;
    /// Include_Header / +HI: a file read as if `#include` stood before the scene's first line
    /// (found as an #include file is); empty: none.
    std::string includeHeader;
    AnimationClock animation;
    int imageWidth = 640, imageHeight = 480;  ///< `image_width`, `image_height`
    Dialect dialect = Dialect::Auto;
    /// Version= / +MV: the language version in force from the start, as if the scene began with
    /// #version (0: none given: `version` reads 3.7, POV-Ray's own, and the scene gets pre-3.7
    /// compatibility until a #version directive).
    double version = 0;
    bool strict = false;  ///< a feature that is parsed but not rendered yet is an error, not a warning
    /// The files the run writes besides what the scene writes (the image, the edge mask; relative
    /// to the working folder): `#fopen ... write` may not name one of them.
    std::vector<std::string> outputFiles;
};

}  // namespace rays::sdl
