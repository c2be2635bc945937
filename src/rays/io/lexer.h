// Lexer for POV-Ray-style scene text: a pull lexer over the whole file held in memory.
// Every token carries its line:col; identifier and number text are views into the source.
#pragma once
#include <string>
#include <string_view>

#include "rays/error.h"

namespace rays {

enum class TokenKind { Identifier, Number, String, Symbol, End };

struct Token {
    TokenKind kind = TokenKind::End;
    std::string_view text;  ///< identifier name, symbol character, string contents, number spelling
    double number = 0;      ///< value when kind == Number
    int line = 0, col = 0;  ///< 1-based position of the first character
};

class Lexer {
public:
    /// text must outlive the lexer and every token it returns. firstLine: the line number of text's
    /// first line (text cut from a file at a line start).
    Lexer(std::string_view text, std::string fileName, int firstLine = 1)
        : s_(text), file_(std::move(fileName)), line_(firstLine) {}

    /// The next token; `//` and `/* */` comments and whitespace are skipped. Returns End forever at
    /// the end. Throws Error for malformed numbers, unterminated comments or strings and characters
    /// that are not part of the language.
    Token next() {
        Token t;
        next(t);
        return t;
    }
    /// The same, written over t (the parser's current token: no copy through the stack).
    void next(Token& t);

    const std::string& fileName() const { return file_; }
    SourceLoc locOf(const Token& t) const { return SourceLoc{file_, t.line, t.col}; }

private:
    void skipSpaceAndComments();
    void lexNumber(Token& t);
    void lexString(Token& t);
    /// Steps over the newline at i_ (the caller has checked it is one).
    void newline() {
        ++line_;
        lineStart_ = ++i_;
    }
    int col() const { return int(i_ - lineStart_) + 1; }

    std::string_view s_;
    std::string file_;
    size_t i_ = 0;
    size_t lineStart_ = 0;  ///< index of the first character of the current line
    int line_ = 1;
};

/// Human-readable description of a token for error messages, e.g. "'{'" or "number 3.5".
std::string describe(const Token& t);

}  // namespace rays
