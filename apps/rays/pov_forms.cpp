#include "pov_forms.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "arg_text.h"
#include "rays/error.h"
#include "scene_library.h"

namespace rays::cli {
namespace {

// A POV-Ray switch written with '+' ("+W640"): in `rays render` always POV-Ray's.
bool isPlusSwitch(const std::string& arg) { return isPovSwitch(arg) && arg[0] == '+'; }

// True when the option named by arg ("--spp", "-o", "--spp=4", "-o5") is one of render's and
// takes its value from the next argument.
bool takesNextArgument(const std::string& arg, const CLI::App& render) {
    if (arg.find('=') != std::string::npos) return false;
    const bool isLong = arg.rfind("--", 0) == 0;
    if (!isLong && arg.size() != 2) return false;  // "-o5": the value is attached
    const CLI::Option* opt = render.get_option_no_throw(arg);
    return opt && opt->get_type_size_max() > 0 && opt->get_expected_min() > 0;
}

bool isRenderPovArgument(const std::string& arg) {
    if (isPlusSwitch(arg)) return true;
    if (arg.size() >= 2 && arg[0] == '-' && std::isupper(static_cast<unsigned char>(arg[1])) && arg[1] != 'W' && arg[1] != 'H')
        return true;
    return (arg.empty() || arg[0] != '-') && (isPovSetting(arg) || isIniArgument(arg));
}

int toInt(const std::string& text) {
    try {
        return std::stoi(text);
    } catch (const std::exception&) {
        throw Error("rays: error: expected a whole number, got '" + text + "'");
    }
}

}  // namespace

bool isPovForm(const std::vector<std::string>& args, const std::vector<std::string>& commands) {
    if (args.empty() || args[0].rfind("--", 0) == 0) return false;
    if (std::find(commands.begin(), commands.end(), args[0]) != commands.end()) return false;
    if (isSceneArgument(args[0])) return true;  // povray scene.pov
    return std::any_of(args.begin(), args.end(), [](const std::string& a) {
        return isPlusSwitch(a) || isPovSetting(a) || isIniArgument(a);
    });
}

std::vector<std::string> markPovArguments(const std::vector<std::string>& args, const CLI::App& render, bool povForm) {
    std::vector<std::string> out;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        // A short option of render's alone (-q, -o FILE, -W N, -H N, -h) is render's in both forms: a
        // POV-Ray switch with those letters carries its value (-Q9, -Oout.png, -W640).
        const bool shortAlone = a.size() == 2 && a[0] == '-' && render.get_option_no_throw(a) != nullptr;
        const bool renderOption = a.rfind("--", 0) == 0 || shortAlone ||
                                  (!povForm && a.size() >= 2 && a[0] == '-' && !isRenderPovArgument(a));
        if (renderOption) {
            out.push_back(a);
            if (takesNextArgument(a, render) && i + 1 < args.size()) out.push_back(args[++i]);
        } else if (povForm || isRenderPovArgument(a)) {
            out.push_back("--pov=" + a);
        } else {
            out.push_back(a);
        }
    }
    return out;
}

void readInOrder(const CLI::App& render, const SharedOptions& shared, PovOptionReader& reader) {
    // The positionals in order decide their roles: SCENE W H, or W H when the first is a number.
    std::vector<std::string> positionals;
    std::map<const CLI::Option*, size_t> seen;
    for (const CLI::Option* opt : render.parse_order())
        if (opt == shared.scene || opt == shared.width || opt == shared.height) positionals.push_back(opt->results()[seen[opt]++]);
    const bool sizeFirst = !positionals.empty() && isDigits(positionals[0]) && positionals[0].size() <= 9;
    if (positionals.size() > (sizeFirst ? 2u : 3u))
        throw Error("rays: error: too many positional arguments: '" + positionals.back() +
                    "' (render takes SCENE W H; see rays render --help)");

    seen.clear();
    size_t positional = 0;
    for (const CLI::Option* opt : render.parse_order()) {
        if (opt == shared.scene || opt == shared.width || opt == shared.height) {
            const size_t role = sizeFirst ? positional + 1 : positional;  // 0 scene, 1 W, 2 H
            const std::string& v = positionals[positional++];
            if (role == 0) reader.setScene(v);
            else if (role == 1) reader.setWidth(toInt(v));
            else reader.setHeight(toInt(v));
            continue;
        }
        const size_t k = seen[opt]++;
        if (k >= opt->results().size()) continue;
        const std::string& v = opt->results()[k];
        if (opt == shared.pov) reader.readArgument(v);
        else if (opt == shared.output) reader.setOutputExact(v);
        else if (opt == shared.widthFlag) reader.setWidth(toInt(v));
        else if (opt == shared.heightFlag) reader.setHeight(toInt(v));
        else if (opt == shared.threads) reader.setThreads(toInt(v));
        else if (opt == shared.library) reader.addLibraryPath(v);
        else if (opt == shared.resume) reader.setResume(true);
        else if (opt == shared.jpegQuality) reader.setJpegQuality(toInt(v));
        else if (opt == shared.libraryScene) reader.setScene(findScene(v));
        else if (std::find(shared.antialias.begin(), shared.antialias.end(), opt) != shared.antialias.end())
            reader.renderChoseAntialias();
    }
}

}  // namespace rays::cli
