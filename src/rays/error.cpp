#include "rays/error.h"

#include <cstdint>

namespace rays {
namespace {

// Length of the well-formed UTF-8 sequence at s[i] that is not a control character, or 0.
size_t printableUtf8Length(std::string_view s, size_t i) {
    const auto byte = [&](size_t k) { return k < s.size() ? unsigned(uint8_t(s[k])) : 0u; };
    const unsigned b0 = byte(i);
    auto cont = [&](size_t k) { return (byte(k) & 0xC0u) == 0x80u; };
    if (b0 >= 0xC2 && b0 <= 0xDF) return cont(i + 1) && !(b0 == 0xC2 && byte(i + 1) < 0xA0) ? 2 : 0;  // not C1
    if (b0 >= 0xE0 && b0 <= 0xEF) {
        const unsigned b1 = byte(i + 1);
        if (!cont(i + 1) || !cont(i + 2) || (b0 == 0xE0 && b1 < 0xA0) || (b0 == 0xED && b1 >= 0xA0)) return 0;
        return 3;
    }
    if (b0 >= 0xF0 && b0 <= 0xF4) {
        const unsigned b1 = byte(i + 1);
        if (!cont(i + 1) || !cont(i + 2) || !cont(i + 3) || (b0 == 0xF0 && b1 < 0x90) || (b0 == 0xF4 && b1 >= 0x90))
            return 0;
        return 4;
    }
    return 0;
}

std::string escaped(std::string_view text, bool keepLineBreaks) {
    static const char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        const unsigned char c = uint8_t(text[i]);
        if (c >= 0x20 && c < 0x7F) {
            out += char(c);
            ++i;
        } else if (keepLineBreaks && (c == '\n' || c == '\t')) {
            out += char(c);
            ++i;
        } else if (const size_t n = c >= 0x80 ? printableUtf8Length(text, i) : 0; n > 0) {
            out.append(text.substr(i, n));
            i += n;
        } else {
            if (c == '\n') out += "\\n";
            else if (c == '\r') out += "\\r";
            else if (c == '\t') out += "\\t";
            else out += {'\\', 'x', kHex[c >> 4], kHex[c & 15]};
            ++i;
        }
    }
    return out;
}

// Moves a cut position back to the start of a UTF-8 sequence.
size_t utf8Boundary(const std::string& s, size_t pos) {
    while (pos > 0 && pos < s.size() && (uint8_t(s[pos]) & 0xC0) == 0x80) --pos;
    return pos;
}

}  // namespace

std::string printableMessage(std::string_view text, bool keepLineBreaks) {
    std::string s = escaped(text, keepLineBreaks);
    if (keepLineBreaks || s.size() <= kMaxMessageBytes) return s;
    // The start names the place and the problem; the end holds the include and macro context.
    const size_t tailBytes = kMaxMessageBytes / 4;
    const size_t headEnd = utf8Boundary(s, kMaxMessageBytes - tailBytes - 48);
    const size_t tailStart = utf8Boundary(s, s.size() - tailBytes);
    return s.substr(0, headEnd) + " ... [" + std::to_string(tailStart - headEnd) + " bytes left out] ... " +
           s.substr(tailStart);
}

std::string formatError(const SourceLoc& loc, const std::string& msg) {
    std::string s = loc.file;
    if (loc.line > 0) s += ":" + std::to_string(loc.line) + ":" + std::to_string(loc.col);
    return s + ": error: " + msg;
}

std::string formatWarning(const SourceLoc& loc, const std::string& msg) {
    std::string s = loc.file;
    if (loc.line > 0) s += ":" + std::to_string(loc.line) + ":" + std::to_string(loc.col);
    return printableMessage(s + ": warning: " + msg);
}

void fail(const SourceLoc& loc, const std::string& msg) { throw Error(formatError(loc, msg)); }

void failFile(const std::string& file, const std::string& msg) {
    throw Error(formatError(SourceLoc{file, 0, 0}, msg));
}

}  // namespace rays
