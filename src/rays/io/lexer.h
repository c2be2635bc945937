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
    /// text must outlive the lexer and every token it returns.
    Lexer(std::string_view text, std::string fileName) : s_(text), file_(std::move(fileName)) {}

    /// The next token; `//` and `/* */` comments and whitespace are skipped. Returns End forever at
    /// the end. Throws Error for malformed numbers, unterminated comments or strings and characters
    /// that are not part of the language.
    Token next();

    const std::string& fileName() const { return file_; }
    SourceLoc locOf(const Token& t) const { return SourceLoc{file_, t.line, t.col}; }

private:
    void advance();
    void skipSpaceAndComments();
    void lexNumber(Token& t);
    void lexString(Token& t);

    std::string_view s_;
    std::string file_;
    size_t i_ = 0;
    int line_ = 1, col_ = 1;
};

/// Human-readable description of a token for error messages, e.g. "'{'" or "number 3.5".
std::string describe(const Token& t);

}  // namespace rays
