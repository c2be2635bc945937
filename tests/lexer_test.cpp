// The lexer's tokens and their line:col: positions are what every scene error message names.
#include "rays/io/lexer.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rays/error.h"
#include "support/error_text.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

struct Seen {
    TokenKind kind;
    std::string text;
    int line, col;
};

std::vector<Seen> lex(const std::string& text) {
    Lexer lexer(text, "t.pov");
    std::vector<Seen> out;
    for (Token t = lexer.next(); t.kind != TokenKind::End; t = lexer.next())
        out.push_back({t.kind, std::string(t.text), t.line, t.col});
    return out;
}

std::string errorOf(const std::string& text) {
    return rays::test::errorText([&] { lex(text); });
}

TEST(Lexer, PositionsAcrossCommentsTabsAndLineEnds) {
    const std::string text =
        "sphere {\n"                      // line 1
        "\t<1, 2.5e1>  // comment { }\n"  // line 2: a tab is one column
        "/* block\n"                      // line 3
        "   comment */ x_1\r\n"           // line 4: CRLF line end
        "  \"a b\" 7.\n"                  // line 5
        "\n"                              // line 6
        "}";                              // line 7
    const std::vector<Seen> tokens = lex(text);
    const std::vector<Seen> expected = {
        {TokenKind::Identifier, "sphere", 1, 1}, {TokenKind::Symbol, "{", 1, 8},
        {TokenKind::Symbol, "<", 2, 2},          {TokenKind::Number, "1", 2, 3},
        {TokenKind::Symbol, ",", 2, 4},          {TokenKind::Number, "2.5e1", 2, 6},
        {TokenKind::Symbol, ">", 2, 11},         {TokenKind::Identifier, "x_1", 4, 15},
        {TokenKind::String, "a b", 5, 3},        {TokenKind::Number, "7.", 5, 9},
        {TokenKind::Symbol, "}", 7, 1},
    };
    ASSERT_EQ(tokens.size(), expected.size());
    for (size_t i = 0; i < tokens.size(); ++i) {
        SCOPED_TRACE("token " + std::to_string(i) + " '" + tokens[i].text + "'");
        EXPECT_EQ(tokens[i].kind, expected[i].kind);
        EXPECT_EQ(tokens[i].text, expected[i].text);
        EXPECT_EQ(tokens[i].line, expected[i].line);
        EXPECT_EQ(tokens[i].col, expected[i].col);
    }
}

TEST(Lexer, NumberValues) {
    Lexer lexer("0.25 .5 12 3e2 1e-999", "t.pov");
    for (double want : {0.25, 0.5, 12.0, 300.0, 0.0}) {
        const Token t = lexer.next();
        ASSERT_EQ(t.kind, TokenKind::Number);
        EXPECT_EQ(t.number, want);
    }
    EXPECT_EQ(lexer.next().kind, TokenKind::End);
    EXPECT_EQ(lexer.next().kind, TokenKind::End);  // End forever
}

TEST(Lexer, ErrorsNameTheirPosition) {
    EXPECT_EQ(errorOf("a\n  /* x\n y"), "t.pov:2:3: error: unterminated /* comment");
    EXPECT_EQ(errorOf("a\n\tb 1.2.3"), "t.pov:2:4: error: malformed number '1.2.3'");
    EXPECT_EQ(errorOf("/*\n*/ 4x"), "t.pov:2:4: error: malformed number '4x'");
    EXPECT_EQ(errorOf("x\n 1e+"), "t.pov:2:2: error: malformed number '1e+'");
    EXPECT_EQ(errorOf("x\n\n   \"open"), "t.pov:3:4: error: unterminated string");
    EXPECT_EQ(errorOf("// c\n  @"), "t.pov:2:3: error: unexpected character '@'");
    EXPECT_EQ(errorOf(std::string("a ") + '\0'), "t.pov:1:3: error: unexpected character '\\x00'");
    EXPECT_EQ(errorOf("1e999"), "t.pov:1:1: error: number '1e999' is too large");
}

}}  // namespace RAYS_TEST_UNIT, namespace
