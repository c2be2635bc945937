// The POV-Ray forms of the command line (docs/cli.md "POV-Ray switches and INI files"): telling
// `rays +Iscene.pov +W640 ...` and `rays scene.ini` from Rays' own commands, marking the POV-Ray
// arguments among render's so CLI11 keeps their place, and reading POV-Ray options and render's
// own options for the same settings in command-line order (a later one wins).
#pragma once
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "pov_options.h"

namespace rays::cli {

/// True when the arguments (without the program name) are POV-Ray's form: the first is not one
/// of `commands` and does not start with "--", and it is a scene (NAME.pov) or some argument is a
/// '+' switch, KEY=VALUE or an INI file (NAME.ini, NAME[Section]). (`rays typo scene.pov` stays
/// an unknown command.)
bool isPovForm(const std::vector<std::string>& args, const std::vector<std::string>& commands);

/// render's arguments with each POV-Ray one rewritten as "--pov=ARG" (an option of render's that
/// keeps its place). Long options (--name), render's short options standing alone (-q, -o FILE,
/// -W N, -H N, -h) and their values are render's. In POV-Ray's form (povForm) every other argument
/// is POV-Ray's (a single dash starts a POV-Ray switch, as in povray: -D, -Q9); in `rays render` a POV-Ray argument is a '+' switch, a '-' switch with an upper-case
/// letter other than W and H (-D, -A, -UA; -W and -H are render's own, with the same meaning),
/// KEY=VALUE or an INI file, and everything else is render's.
std::vector<std::string> markPovArguments(const std::vector<std::string>& args, const CLI::App& render, bool povForm);

/// The options of render that carry POV-Ray arguments or set what POV-Ray options also set.
struct SharedOptions {
    CLI::Option* pov = nullptr;          ///< --pov=ARG (markPovArguments)
    CLI::Option* scene = nullptr;        ///< positional SCENE
    CLI::Option* width = nullptr;        ///< positional W
    CLI::Option* height = nullptr;       ///< positional H
    CLI::Option* widthFlag = nullptr;    ///< -W
    CLI::Option* heightFlag = nullptr;   ///< -H
    CLI::Option* output = nullptr;       ///< -o
    CLI::Option* threads = nullptr;      ///< --threads
    CLI::Option* library = nullptr;      ///< --library
    CLI::Option* resume = nullptr;       ///< --resume
    CLI::Option* jpegQuality = nullptr;  ///< --jpeg-quality
    CLI::Option* libraryScene = nullptr; ///< --scene N
    std::vector<CLI::Option*> antialias; ///< --spp, --aa, --ss
};

/// Reads render's parsed arguments in command-line order into reader. The positionals are SCENE W H,
/// or W H when the first is a whole number (the scene then comes from +I, an INI file or --scene).
/// Throws Error for a fourth positional or an unknown --scene.
void readInOrder(const CLI::App& render, const SharedOptions& shared, PovOptionReader& reader);

}  // namespace rays::cli
