#include "rays/io/lexer.h"

#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstring>

namespace rays {
namespace {

// ASCII only (scene files are ASCII; std::isalpha would consult the locale on every character).
bool isIdentStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isIdentChar(char c) { return isIdentStart(c) || (c >= '0' && c <= '9'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

std::string printable(char c) {
    if (std::isprint(static_cast<unsigned char>(c))) return std::string(1, c);
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(c));
    return buf;
}

}  // namespace

Token Lexer::next() {
    skipSpaceAndComments();
    Token t;
    t.line = line_;
    t.col = col_;
    if (i_ >= s_.size()) return t;
    const char c = s_[i_];
    if (isIdentStart(c)) {
        const size_t b = i_;
        while (i_ < s_.size() && isIdentChar(s_[i_])) advance();
        t.kind = TokenKind::Identifier;
        t.text = s_.substr(b, i_ - b);
    } else if (isDigit(c) || (c == '.' && i_ + 1 < s_.size() && isDigit(s_[i_ + 1]))) {
        lexNumber(t);
    } else if (c == '"') {
        lexString(t);
    } else if (c != '\0' && std::strchr("{}<>,-+*/()[]=#;", c) != nullptr) {  // strchr finds the NUL too
        t.kind = TokenKind::Symbol;
        t.text = s_.substr(i_, 1);
        advance();
    } else {
        fail(locOf(t), std::string("unexpected character '") + printable(c) + "'");
    }
    return t;
}

void Lexer::advance() {
    if (s_[i_] == '\n') {
        ++line_;
        col_ = 1;
    } else {
        ++col_;
    }
    ++i_;
}

void Lexer::skipSpaceAndComments() {
    while (i_ < s_.size()) {
        const char c = s_[i_];
        if (c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            advance();
        } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '/') {
            while (i_ < s_.size() && s_[i_] != '\n') advance();
        } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '*') {
            const SourceLoc start{file_, line_, col_};
            advance();
            advance();
            while (i_ + 1 < s_.size() && !(s_[i_] == '*' && s_[i_ + 1] == '/')) advance();
            if (i_ + 1 >= s_.size()) fail(start, "unterminated /* comment");
            advance();
            advance();
        } else {
            return;
        }
    }
}

// Digits [. digits] [e[+-]digits]; a second '.' or a letter glued on is malformed.
void Lexer::lexNumber(Token& t) {
    const size_t b = i_;
    while (i_ < s_.size() && isDigit(s_[i_])) advance();
    if (i_ < s_.size() && s_[i_] == '.') {
        advance();
        while (i_ < s_.size() && isDigit(s_[i_])) advance();
    }
    if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
        size_t j = i_ + 1;
        if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
        if (j < s_.size() && isDigit(s_[j])) {
            while (i_ < j) advance();
            while (i_ < s_.size() && isDigit(s_[i_])) advance();
        } else {
            fail(locOf(t), "malformed number '" + std::string(s_.substr(b, j - b)) + "'");
        }
    }
    if (i_ < s_.size() && (s_[i_] == '.' || isIdentChar(s_[i_]))) {
        size_t e = i_;
        while (e < s_.size() && (s_[e] == '.' || isIdentChar(s_[e]))) ++e;
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
    advance();  // opening quote
    const size_t b = i_;
    while (i_ < s_.size() && s_[i_] != '"' && s_[i_] != '\n') advance();
    if (i_ >= s_.size() || s_[i_] != '"') fail(locOf(t), "unterminated string");
    t.kind = TokenKind::String;
    t.text = s_.substr(b, i_ - b);
    advance();
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
