// TokenReader: the token-level layer of the scene parser — token tests with line:col errors,
// warnings for valid POV-Ray that Rays skips, { } blocks, and scalar/vector expressions
// (+ - * / parentheses, <vectors>, x y z pi). scene_parser.cpp builds the Scene on top of it;
// mesh_blocks.cpp reads mesh and mesh2 bodies with it.
#pragma once
#include <array>
#include <map>
#include <string>
#include <string_view>

#include "rays/error.h"
#include "rays/io/lexer.h"
#include "rays/io/scene_parser.h"
#include "rays/math/vec3.h"

namespace rays::scenetext {

/// A parsed expression value: a scalar (n == 1) or a vector of n components (2..5).
struct Value {
    int n = 1;
    std::array<double, 5> c{};
    bool isScalar() const { return n == 1; }
};

/// The message of an error from a file the scene refers to ("tex.png: error: why"), to be put
/// after the scene's own location: "scene.pov:2:47: error: tex.png: why" (one "error:" per line).
std::string nestedMessage(const Error& e);

class TokenReader {
public:
    /// Reads the first token. text must outlive the reader; firstLine as for Lexer.
    TokenReader(std::string_view text, const std::string& file, const ParseOptions& opt, int firstLine = 1);

    // ---- tokens ----------------------------------------------------------------------------
    const Token& token() const { return tok_; }
    void advance() { lex_.next(tok_); }
    SourceLoc loc(const Token& t) const { return lex_.locOf(t); }
    SourceLoc loc() const { return loc(tok_); }
    bool isSymbol(char c) const { return tok_.kind == TokenKind::Symbol && tok_.text[0] == c; }
    bool isIdent(std::string_view s) const { return tok_.kind == TokenKind::Identifier && tok_.text == s; }
    [[noreturn]] void error(const std::string& msg) const { fail(loc(), msg); }
    void expectSymbol(char c, std::string_view context);
    void skipCommas() {
        while (isSymbol(',')) advance();
    }

    // ---- warnings and skipped POV-Ray ----------------------------------------------------------
    void warn(const SourceLoc& at, const std::string& msg);
    /// The first time a keyword is skipped it is named; flushWarnings() counts the repeats.
    void warnUnsupported(const Token& t);
    void flushWarnings();
    /// Skips what follows an unsupported keyword: a balanced { } block, or scalar/vector
    /// arguments (numbers, strings, <...>, commas and arithmetic).
    void skipUnsupported();
    void skipBlock();
    /// At a POV-Ray keyword Rays does not implement: skips it with a warning and returns true.
    bool unsupportedHere();
    [[noreturn]] void unknown(std::string_view where);

    /// Calls item() for each entry of a { } block until the closing brace.
    template <class F>
    void block(const Token& owner, F&& item) {
        const Token open = tok_;
        expectSymbol('{', "after '" + std::string(owner.text) + "'");
        for (;;) {
            if (isSymbol('}')) {
                advance();
                return;
            }
            if (tok_.kind == TokenKind::End)
                fail(loc(open), "'{' of '" + std::string(owner.text) + "' is never closed (end of file reached)");
            item();
        }
    }

    // ---- expressions -----------------------------------------------------------------------------
    Value expr();
    /// True when the current token can start an expression.
    bool atExpression() const;
    void expectExpression(std::string_view what);
    double number(std::string_view what);
    Vec3 vector3(std::string_view what, bool allowScalar = false);

protected:
    Lexer lex_;
    const ParseOptions& opt_;
    Token tok_;

private:
    Value term();
    Value combine(const Value& a, const Value& b, char op);
    Value factor();

    std::map<std::string, int> warnedCount_;
    static constexpr int kMaxNesting = 256;  ///< parentheses, vectors and signs inside one expression
    int nesting_ = 0;
};

}  // namespace rays::scenetext
