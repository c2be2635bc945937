#include "paths.h"

#include <filesystem>

#include "rays/error.h"

namespace rays::cli {

bool fileExists(const std::string& path) {
    std::error_code ec;
    return std::filesystem::exists(path, ec);
}

void checkOutputIsNotInput(const std::string& output, const std::string& input) {
    std::error_code ec;
    if (!input.empty() && fileExists(output) && fileExists(input) && std::filesystem::equivalent(output, input, ec))
        failFile(output, "output would overwrite the input file '" + input + "'");
}

size_t extensionDot(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    const size_t nameStart = slash == std::string::npos ? 0 : slash + 1;
    if (dot == std::string::npos || dot <= nameStart) return std::string::npos;  // a leading dot: a hidden file
    return dot;
}

}  // namespace rays::cli
