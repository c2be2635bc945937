// A token of POV-Ray's scene language as the lexer stores it: 24 bytes, no pointers, so a file's
// tokens sit in one array that loops and macros replay by index.
#pragma once
#include <cstdint>

namespace rays::sdl {

enum class Tk : uint8_t {
    End,        ///< end of the file
    Number,     ///< number: value in `number`
    String,     ///< string literal: `id` indexes the file's string table (escapes already decoded)
    Name,       ///< keyword or identifier: `id` is the name id (below kKeywordCount: a keyword)
    Directive,  ///< `#` and the word after it: `id` is the word's name id
    Symbol,     ///< punctuation: `sym`
};

/// Two-character operators get codes of their own.
enum Sym : uint8_t { kLessEq = 'l', kGreaterEq = 'g', kNotEq = 'n' };

struct Token {
    double number = 0;
    uint32_t id = 0;
    uint32_t line = 0;
    uint16_t col = 0;  ///< 1-based column, 65535 for any column beyond
    Tk kind = Tk::End;
    uint8_t sym = 0;   ///< Symbol: one of { } ( ) [ ] < > , ; + - * / = ! ? : & | . or kLessEq kGreaterEq kNotEq
};

}  // namespace rays::sdl
