#include "subcommand_args.h"

#include <iostream>

#include "rays/error.h"

namespace rays::cli {

bool parseSubcommandArgs(CLI::App& app, const std::vector<std::string>& args, const std::string& name,
                         const std::string& usage) {
    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them reversed
        app.parse(reversed);
    } catch (const CLI::CallForHelp&) {
        std::cout << app.help();
        return true;
    } catch (const CLI::ParseError& e) {
        throw Error("rays: error: " + name + ": " + e.what() + " (usage: " + usage + ")");
    }
    return false;
}

}  // namespace rays::cli
