#include "rays/error.h"

namespace rays {

std::string formatError(const SourceLoc& loc, const std::string& msg) {
    std::string s = loc.file;
    if (loc.line > 0) s += ":" + std::to_string(loc.line) + ":" + std::to_string(loc.col);
    return s + ": error: " + msg;
}

void fail(const SourceLoc& loc, const std::string& msg) { throw Error(formatError(loc, msg)); }

void failFile(const std::string& file, const std::string& msg) {
    throw Error(formatError(SourceLoc{file, 0, 0}, msg));
}

}  // namespace rays
