#include "rays/io/lexer.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstring>

namespace rays {
namespace {

// Character classes, ASCII only (scene files are ASCII; std::isalpha would consult the locale on
// every character). One table lookup per character instead of a chain of comparisons.
enum : uint8_t { kIdentStart = 1, kDigit = 2, kSpace = 4, kSymbol = 8 };
constexpr std::array<uint8_t, 256> makeClasses() {
    std::array<uint8_t, 256> c{};
    for (int ch = 'a'; ch <= 'z'; ++ch) c[size_t(ch)] = kIdentStart;
    for (int ch = 'A'; ch <= 'Z'; ++ch) c[size_t(ch)] = kIdentStart;
    c['_'] = kIdentStart;
    for (int ch = '0'; ch <= '9'; ++ch) c[size_t(ch)] = kDigit;
    for (char ch : {' ', '\n', '\t', '\r', '\f', '\v'}) c[size_t(uint8_t(ch))] = kSpace;
    for (char ch : std::string_view("{}<>,-+*/()[]=#;")) c[size_t(uint8_t(ch))] = kSymbol;
    return c;
}
constexpr std::array<uint8_t, 256> kClasses = makeClasses();

uint8_t classOf(char c) { return kClasses[static_cast<unsigned char>(c)]; }
bool isIdentChar(char c) { return classOf(c) & (kIdentStart | kDigit); }
bool isDigit(char c) { return classOf(c) & kDigit; }

std::string printable(char c) {
    if (std::isprint(static_cast<unsigned char>(c))) return std::string(1, c);
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(c));
    return buf;
}

}  // namespace

// Identifiers, numbers and symbols never contain a newline: only whitespace, comments and strings
// move to the next line, so the column is the distance from the line's start.
void Lexer::next(Token& t) {
    skipSpaceAndComments();
    t.kind = TokenKind::End;
    t.text = {};
    t.number = 0;
    t.line = line_;
    t.col = col();
    if (i_ >= s_.size()) return;
    const char c = s_[i_];
    const uint8_t cls = classOf(c);
    if (cls & kIdentStart) {
        const size_t b = i_;
        while (++i_ < s_.size() && isIdentChar(s_[i_])) {
        }
        t.kind = TokenKind::Identifier;
        t.text = s_.substr(b, i_ - b);
    } else if ((cls & kDigit) || (c == '.' && i_ + 1 < s_.size() && isDigit(s_[i_ + 1]))) {
        lexNumber(t);
    } else if (c == '"') {
        lexString(t);
    } else if (cls & kSymbol) {
        t.kind = TokenKind::Symbol;
        t.text = s_.substr(i_, 1);
        ++i_;
    } else {
        fail(locOf(t), std::string("unexpected character '") + printable(c) + "'");
    }
}

void Lexer::skipSpaceAndComments() {
    while (i_ < s_.size()) {
        const char c = s_[i_];
        if (c == '\n') {
            newline();
        } else if (classOf(c) & kSpace) {
            ++i_;
        } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '/') {
            while (i_ < s_.size() && s_[i_] != '\n') ++i_;
        } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '*') {
            const SourceLoc start{file_, line_, col()};
            i_ += 2;
            while (i_ + 1 < s_.size() && !(s_[i_] == '*' && s_[i_ + 1] == '/')) {
                if (s_[i_] == '\n') newline();
                else ++i_;
            }
            if (i_ + 1 >= s_.size()) fail(start, "unterminated /* comment");
            i_ += 2;
        } else {
            return;
        }
    }
}

// Digits [. digits] [e[+-]digits]; a second '.' or a letter glued on is malformed.
void Lexer::lexNumber(Token& t) {
    const size_t b = i_;
    const size_t n = s_.size();
    while (i_ < n && isDigit(s_[i_])) ++i_;
    if (i_ < n && s_[i_] == '.') {
        ++i_;
        while (i_ < n && isDigit(s_[i_])) ++i_;
    }
    if (i_ < n && (s_[i_] == 'e' || s_[i_] == 'E')) {
        size_t j = i_ + 1;
        if (j < n && (s_[j] == '+' || s_[j] == '-')) ++j;
        if (j < n && isDigit(s_[j])) {
            i_ = j;
            while (i_ < n && isDigit(s_[i_])) ++i_;
        } else {
            fail(locOf(t), "malformed number '" + std::string(s_.substr(b, j - b)) + "'");
        }
    }
    if (i_ < n && (s_[i_] == '.' || isIdentChar(s_[i_]))) {
        size_t e = i_;
        while (e < n && (s_[e] == '.' || isIdentChar(s_[e]))) ++e;
        fail(locOf(t), "malformed number '" + std::string(s_.substr(b, e - b)) + "'");
    }
    t.kind = TokenKind::Number;
    t.text = s_.substr(b, i_ - b);
    const char* first = s_.data() + b;
    const char* last = s_.data() + i_;
    auto [ptr, ec] = std::from_chars(first, last, t.number);
    if (ec == std::errc::result_out_of_range && ptr == last) {
        // Too large for a double (1e999) is an error; too small (1e-999) is 0, as in POV-Ray.
        const size_t e = t.text.find_first_of("eE");
        const bool negativeExponent = e != std::string_view::npos && e + 1 < t.text.size() && t.text[e + 1] == '-';
        if (!negativeExponent) fail(locOf(t), "number '" + std::string(t.text) + "' is too large");
        t.number = 0;
        return;
    }
    if (ec != std::errc() || ptr != last) fail(locOf(t), "malformed number '" + std::string(t.text) + "'");
}

void Lexer::lexString(Token& t) {
    ++i_;  // opening quote
    const size_t b = i_;
    while (i_ < s_.size() && s_[i_] != '"' && s_[i_] != '\n') ++i_;
    if (i_ >= s_.size() || s_[i_] != '"') fail(locOf(t), "unterminated string");
    t.kind = TokenKind::String;
    t.text = s_.substr(b, i_ - b);
    ++i_;
}

std::string describe(const Token& t) {
    switch (t.kind) {
        case TokenKind::Identifier: return "'" + std::string(t.text) + "'";
        case TokenKind::Number: return "number " + std::string(t.text);
        case TokenKind::String: return "string \"" + std::string(t.text) + "\"";
        case TokenKind::Symbol: return "'" + std::string(t.text) + "'";
        case TokenKind::End: return "end of file";
    }
    return "token";
}

}  // namespace rays
