// Error: the one exception type Rays throws for user-facing failures (bad input, unreadable or
// unwritable files). what() is the complete one-line message, e.g. "scene.pov:3:7: error: ...".
#pragma once
#include <stdexcept>
#include <string>

namespace rays {

/// A position in a source file; line and col are 1-based, 0 when unknown.
struct SourceLoc {
    std::string file;
    int line = 0;
    int col = 0;
};

class Error : public std::runtime_error {
public:
    /// Message without a location: "error: msg" is NOT prepended; pass the full line.
    explicit Error(const std::string& fullMessage) : std::runtime_error(fullMessage) {}
};

/// "FILE:LINE:COL: error: msg" (or "FILE: error: msg" when line is 0).
std::string formatError(const SourceLoc& loc, const std::string& msg);
/// Throws Error(formatError(loc, msg)).
[[noreturn]] void fail(const SourceLoc& loc, const std::string& msg);
/// Throws Error("FILE: error: msg").
[[noreturn]] void failFile(const std::string& file, const std::string& msg);

}  // namespace rays
