// The value of a `Declare=NAME=VALUE` option (options.h, Declare): a float literal or a string in
// double quotes. One reading for the option reader, which refuses anything else, and the scene
// loader, which declares NAME with it.
#pragma once
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

namespace rays::sdl {

struct DeclareValue {
    bool isString = false;
    double number = 0;  ///< the float, when !isString
    std::string text;   ///< the string without its quotes, when isString
};

/// The value written as `value`: a string in double quotes, or a finite float literal with nothing
/// before or after it; nullopt for anything else.
inline std::optional<DeclareValue> parseDeclareValue(const std::string& value) {
    DeclareValue v;
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"') {
        v.isString = true;
        v.text = value.substr(1, value.size() - 2);
        return v;
    }
    if (value.empty() || value[0] == ' ' || value[0] == '\t' || value[0] == '\n' || value[0] == '\r' ||
        value[0] == '\v' || value[0] == '\f')
        return std::nullopt;
    char* end = nullptr;
    errno = 0;
    v.number = std::strtod(value.c_str(), &end);
    if (*end != '\0' || errno != 0 || !std::isfinite(v.number)) return std::nullopt;
    return v;
}

}  // namespace rays::sdl
