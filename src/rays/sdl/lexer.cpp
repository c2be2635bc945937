#include "rays/sdl/lexer.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "rays/error.h"

namespace rays::sdl {
namespace {

bool isIdentStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isIdentChar(char c) { return isIdentStart(c) || (c >= '0' && c <= '9'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

std::string charName(char c) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u >= 0x21 && u < 0x7f) return std::string("'") + c + "'";
    char buf[16];
    std::snprintf(buf, sizeof buf, "'\\x%02x'", u);
    return buf;
}

class Lexer {
public:
    Lexer(std::string_view text, SourceFile& file, Names& names) : s_(text), file_(file), names_(names) {}

    void run() {
        file_.tokens.reserve(s_.size() / 5 + 16);
        for (;;) {
            skipSpace();
            Token t;
            t.line = uint32_t(line_);
            t.col = colOf(i_);
            if (i_ >= s_.size()) {
                t.kind = Tk::End;
                file_.tokens.push_back(t);
                return;
            }
            if (file_.tokens.size() >= kMaxTokensPerFile)
                fail(t, "file has more than " + std::to_string(kMaxTokensPerFile) + " tokens");
            lexToken(t);
            file_.tokens.push_back(t);
        }
    }

private:
    uint16_t colOf(size_t i) const {
        const size_t c = i - lineStart_ + 1;
        return c > 65535 ? uint16_t(65535) : uint16_t(c);
    }
    [[noreturn]] void fail(const Token& at, const std::string& msg) const {
        rays::fail(SourceLoc{file_.shownName, int(at.line), int(at.col)}, msg);
    }
    [[noreturn]] void failHere(const std::string& msg) const {
        rays::fail(SourceLoc{file_.shownName, line_, int(colOf(i_))}, msg);
    }

    void newline() {
        ++line_;
        lineStart_ = ++i_;
    }

    void skipSpace() {
        while (i_ < s_.size()) {
            const char c = s_[i_];
            if (c == '\n') {
                newline();
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
                ++i_;
            } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '/') {
                while (i_ < s_.size() && s_[i_] != '\n') ++i_;
            } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '*') {
                blockComment();
            } else {
                return;
            }
        }
    }

    // Block comments nest, as in POV-Ray.
    void blockComment() {
        const int startLine = line_;
        const uint16_t startCol = colOf(i_);
        int depth = 0;
        while (i_ < s_.size()) {
            if (s_[i_] == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '*') {
                ++depth;
                i_ += 2;
            } else if (s_[i_] == '*' && i_ + 1 < s_.size() && s_[i_ + 1] == '/') {
                i_ += 2;
                if (--depth == 0) return;
            } else if (s_[i_] == '\n') {
                newline();
            } else {
                ++i_;
            }
        }
        rays::fail(SourceLoc{file_.shownName, startLine, int(startCol)}, "unterminated /* comment");
    }

    void lexToken(Token& t) {
        const char c = s_[i_];
        if (isIdentStart(c)) {
            t.kind = Tk::Name;
            t.id = names_.intern(word());
            return;
        }
        if (isDigit(c) || (c == '.' && i_ + 1 < s_.size() && isDigit(s_[i_ + 1]))) return number(t);
        if (c == '"') return string(t);
        if (c == '#') {
            if (directive(t)) return;
            return lexToken(t);  // a lone '#' is ignored, as POV-Ray does
        }
        t.kind = Tk::Symbol;
        const char n = i_ + 1 < s_.size() ? s_[i_ + 1] : '\0';
        switch (c) {
            case '<':
                if (n == '=') { t.sym = kLessEq; i_ += 2; return; }
                break;
            case '>':
                if (n == '=') { t.sym = kGreaterEq; i_ += 2; return; }
                break;
            case '!':
                if (n == '=') { t.sym = kNotEq; i_ += 2; return; }
                break;
            case '{': case '}': case '(': case ')': case '[': case ']': case ',': case ';': case '+':
            case '-': case '*': case '/': case '=': case '?': case ':': case '&': case '|': case '.':
                break;
            default:
                failHere("unexpected character " + charName(c));
        }
        t.sym = uint8_t(c);
        ++i_;
    }

    std::string_view word() {
        const size_t b = i_;
        while (i_ < s_.size() && isIdentChar(s_[i_])) ++i_;
        return s_.substr(b, i_ - b);
    }

    void number(Token& t) {
        const size_t b = i_;
        while (i_ < s_.size() && isDigit(s_[i_])) ++i_;
        if (i_ < s_.size() && s_[i_] == '.') {
            ++i_;
            while (i_ < s_.size() && isDigit(s_[i_])) ++i_;
        }
        if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
            size_t j = i_ + 1;
            if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
            if (j < s_.size() && isDigit(s_[j])) {
                i_ = j;
                while (i_ < s_.size() && isDigit(s_[i_])) ++i_;
            } else {
                failHere("malformed number '" + std::string(s_.substr(b, j - b)) + "'");
            }
        }
        if (i_ < s_.size() && s_[i_] == '.' && i_ + 1 < s_.size() && isDigit(s_[i_ + 1]))
            failHere("malformed number: a second decimal point");
        const std::string spelled(s_.substr(b, i_ - b));
        errno = 0;
        const double v = std::strtod(spelled.c_str(), nullptr);
        if (!std::isfinite(v)) {
            Token at = t;
            fail(at, "number '" + spelled + "' is too large");
        }
        t.kind = Tk::Number;
        t.number = v;
    }

    void string(Token& t) {
        ++i_;  // opening quote
        std::string out;
        for (;;) {
            if (i_ >= s_.size()) fail(t, "unterminated string");
            const char c = s_[i_];
            if (c == '"') {
                ++i_;
                break;
            }
            if (c == '\n') {  // POV-Ray 3.7 reads a string across lines (shapes3.inc's #warning texts)
                out += c;
                newline();
                continue;
            }
            if (c == '\\' && i_ + 1 < s_.size()) {
                escape(out);
            } else {
                out += c;
                ++i_;
            }
            if (out.size() > kMaxStringLength) fail(t, "string longer than " + std::to_string(kMaxStringLength) + " characters");
        }
        t.kind = Tk::String;
        t.id = uint32_t(file_.strings.size());
        file_.strings.push_back(std::move(out));
    }

    // POV-Ray 3.7 reference, "Text Formatting": \a \b \f \n \r \t \v \0 \\ \' \" \uNNNN.
    // An unknown escape keeps the character after the backslash.
    void escape(std::string& out) {
        const char e = s_[i_ + 1];
        i_ += 2;
        switch (e) {
            case 'a': out += '\a'; return;
            case 'b': out += '\b'; return;
            case 'f': out += '\f'; return;
            case 'n': out += '\n'; return;
            case 'r': out += '\r'; return;
            case 't': out += '\t'; return;
            case 'v': out += '\v'; return;
            case '0': out += '\0'; return;
            case 'u': {
                unsigned code = 0;
                int digits = 0;
                while (digits < 4 && i_ < s_.size() && std::isxdigit(static_cast<unsigned char>(s_[i_]))) {
                    const char h = s_[i_++];
                    code = code * 16 + unsigned(isDigit(h) ? h - '0' : (h | 0x20) - 'a' + 10);
                    ++digits;
                }
                appendUtf8(out, code);
                return;
            }
            case '\n':  // a backslash before the end of the line keeps the newline
                --i_;
                out += '\\';
                return;
            default: out += e; return;
        }
    }

    static void appendUtf8(std::string& out, unsigned code) {
        if (code < 0x80) {
            out += char(code);
        } else if (code < 0x800) {
            out += char(0xC0 | (code >> 6));
            out += char(0x80 | (code & 0x3F));
        } else {
            out += char(0xE0 | (code >> 12));
            out += char(0x80 | ((code >> 6) & 0x3F));
            out += char(0x80 | (code & 0x3F));
        }
    }

    // '#' and its word; false for a '#' with no word after it on its line (skipped).
    bool directive(Token& t) {
        ++i_;  // '#'
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t')) ++i_;
        if (i_ >= s_.size() || !isIdentStart(s_[i_])) {
            skipSpace();
            t.line = uint32_t(line_);
            t.col = colOf(i_);
            if (i_ >= s_.size()) {
                t.kind = Tk::End;
                return true;
            }
            return false;
        }
        t.id = names_.intern(word());
        // POV-Ray 3.7 reads '#' before a keyword that is no directive as the keyword alone
        // (measured: `#sphere { … }` draws the sphere; the templates write `#union {`); before any
        // other word it is an unknown directive.
        t.kind = Names::isKeyword(t.id) && !directiveWord(Kw(t.id)) ? Tk::Name : Tk::Directive;
        return true;
    }

    static bool directiveWord(Kw k) {
        switch (k) {
            case Kw::include: case Kw::declare: case Kw::local: case Kw::undef: case Kw::if_: case Kw::ifdef:
            case Kw::ifndef: case Kw::else_: case Kw::elseif: case Kw::end: case Kw::switch_: case Kw::case_:
            case Kw::range: case Kw::break_: case Kw::while_: case Kw::for_: case Kw::macro: case Kw::version:
            case Kw::default_: case Kw::debug: case Kw::warning: case Kw::error: case Kw::render:
            case Kw::statistics: case Kw::fopen: case Kw::fclose: case Kw::read: case Kw::write:
            case Kw::max_trace_level: case Kw::max_intersections:
                return true;
            default:
                return false;
        }
    }

    std::string_view s_;
    SourceFile& file_;
    Names& names_;
    size_t i_ = 0;
    size_t lineStart_ = 0;
    int line_ = 1;
};

}  // namespace

void lexFile(std::string_view text, SourceFile& file, Names& names) { Lexer(text, file, names).run(); }

}  // namespace rays::sdl
