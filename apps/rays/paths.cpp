#include "paths.h"

#include <filesystem>

#include "rays/error.h"

namespace rays::cli {

bool fileExists(const std::string& path) {
    std::error_code ec;
    return std::filesystem::exists(path, ec);
}

bool sameFile(const std::string& a, const std::string& b) {
    if (a.empty() || b.empty()) return false;
    std::error_code ec;
    if (fileExists(a) && fileExists(b)) return std::filesystem::equivalent(a, b, ec);
    // One is still to be written: the same name once links and ".." are resolved.
    const std::filesystem::path ca = std::filesystem::weakly_canonical(std::filesystem::absolute(a, ec), ec);
    if (ec) return false;
    const std::filesystem::path cb = std::filesystem::weakly_canonical(std::filesystem::absolute(b, ec), ec);
    return !ec && ca == cb;
}

void checkOutputIsNotInput(const std::string& output, const std::string& input) {
    if (sameFile(output, input)) failFile(output, "output would overwrite the input file '" + input + "'");
}

void checkOutputsDiffer(const std::vector<NamedOutput>& outputs) {
    for (size_t j = 1; j < outputs.size(); ++j)
        for (size_t i = 0; i < j; ++i)
            if (sameFile(outputs[i].path, outputs[j].path))
                failFile(outputs[j].path, std::string("the ") + outputs[j].what + " would overwrite the " +
                                              outputs[i].what + " '" + outputs[i].path + "' of the same run");
}

size_t extensionDot(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    const size_t nameStart = slash == std::string::npos ? 0 : slash + 1;
    if (dot == std::string::npos || dot <= nameStart) return std::string::npos;  // a leading dot: a hidden file
    return dot;
}

}  // namespace rays::cli
