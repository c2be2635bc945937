// Reading a subcommand's words (`rays compare ...`, `rays filter ...`) with CLI11, with the same
// help and error behaviour for every subcommand.
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace rays::cli {

/// Parses `args` (the words after the subcommand's name) into `app`. Returns true when -h/--help
/// printed the help on stdout (the caller then returns 0). A bad option throws rays::Error with one
/// line: "rays: error: NAME: what CLI11 says (usage: USAGE)".
bool parseSubcommandArgs(CLI::App& app, const std::vector<std::string>& args, const std::string& name,
                         const std::string& usage);

}  // namespace rays::cli
