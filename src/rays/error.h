// Error: the one exception type Rays throws for user-facing failures (bad input, unreadable or
// unwritable files). what() is the complete one-line message, e.g. "scene.pov:3:7: error: ...",
// made printable and bounded in length by printableMessage.
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace rays {

/// A position in a source file; line and col are 1-based, 0 when unknown.
struct SourceLoc {
    std::string file;
    int line = 0;
    int col = 0;
};

/// Longest message printableMessage returns (bytes, the cut marker included).
inline constexpr size_t kMaxMessageBytes = 2048;

/// text as one safe terminal line: control bytes (and DEL, the C1 controls, bytes that are not
/// UTF-8) are written as escapes (\n \r \t, else \xNN; a backslash is left as it is), and a text
/// longer than kMaxMessageBytes keeps its start and its end around " ... [N bytes left out] ... ".
/// With keepLineBreaks, '\n' and '\t' pass unchanged (for #debug text, which is the scene's own
/// output) and no length bound applies.
std::string printableMessage(std::string_view text, bool keepLineBreaks = false);

class Error : public std::runtime_error {
public:
    /// Message without a location: "error: msg" is NOT prepended; pass the full line. It is made
    /// printable and bounded (printableMessage).
    explicit Error(const std::string& fullMessage) : std::runtime_error(printableMessage(fullMessage)) {}
};

/// "FILE:LINE:COL: error: msg" (or "FILE: error: msg" when line is 0).
std::string formatError(const SourceLoc& loc, const std::string& msg);
/// "FILE:LINE:COL: warning: msg" (or "FILE: warning: msg"), made printable and bounded.
std::string formatWarning(const SourceLoc& loc, const std::string& msg);
/// Throws Error(formatError(loc, msg)).
[[noreturn]] void fail(const SourceLoc& loc, const std::string& msg);
/// Throws Error("FILE: error: msg").
[[noreturn]] void failFile(const std::string& file, const std::string& msg);

}  // namespace rays
