// Numeric expressions compiled once per place in a file, for loops and macros that read the same
// text again and again (issue 23's parse speed). The compiler reads the file's tokens as the
// expression reader (expressions.cpp) would, for the part of the language that has no side effect
// on what is read next: numbers, identifiers, the constant keywords, `+ - * /`, the comparisons
// and `& |` inside parentheses, unary `- + !`, `?:` inside parentheses, vector literals, `.x`-style
// components, and the pure built-in functions (pure_builtins.h) plus rand(). Anything else (a
// string, a colour keyword, a directive or a call of another function where an operand is due)
// makes the place uncompilable, and the reader reads it as before.
//
// What the tokens cannot tell (an identifier may hold a macro, an array or a colour when the code
// runs) is checked at each run: every identifier must hold a float or a vector, and the types of
// the last run that type-checked are kept so that a run with the same types needs no check. The
// interpreter runs the code (Interpreter::compiledOperand) and computes with the reader's own
// functions (combine, pure_builtins), so the values are the same bit for bit.
#pragma once
#include <cstdint>
#include <vector>

#include "rays/sdl/keywords.h"
#include "rays/sdl/token.h"
#include "rays/sdl/value.h"

namespace rays::sdl {

struct ExprOp {
    enum Code : uint8_t {
        Const,   ///< push consts[arg]
        Ident,   ///< push the value of name arg
        Element, ///< pop aux indices, push that element of the array named arg
        Env,     ///< push the value of keyword arg (clock, frame_number, image_width, version, ...)
        Neg,     ///< unary minus on every component
        Not,     ///< unary '!' on every component
        Binary,  ///< pop b, pop a, push combine(aux, a, b)
        Dot,     ///< a component (aux: 0..4, 5 for gray) of the vector on top
        Vector,  ///< pop aux floats, push the vector of them
        Math1,   ///< a function of one float (arg: the keyword)
        Math2,   ///< atan2, pow, mod, div (arg: the keyword)
        MinMax,  ///< min or max of aux floats (arg: the keyword)
        VecFn,   ///< vdot, vlength, vcross, vnormalize, vrotate of aux values (arg: the keyword)
        Select,  ///< select of aux (3 or 4) values
        Cond,    ///< pop b, pop a, pop c: c ? a : b (both read, as the reader does)
        Rand,    ///< rand of the float on top
    };
    Code code = Const;
    uint8_t aux = 0;
    uint32_t arg = 0;
    uint32_t at = 0;  ///< index of the op's token (a built-in's keyword: its error messages name it)
};

/// The compiled form of one place's expression, and what the runs learned of its identifiers.
struct ExprCode {
    std::vector<ExprOp> ops;
    std::vector<Num> consts;
    std::vector<uint32_t> idents;  ///< name ids of the Ident and Element ops, in their order
    /// For each of idents: 0 for a value, or the number of indices of an array element read.
    std::vector<uint8_t> indexCount;
    bool hasElement = false;  ///< an array element is read (the code is not compiled with rand())
    /// Type of each identifier (of an array's elements) in the last run that type-checked: 0 float,
    /// d (2..5) a vector of d components, 0xFF none yet. A run stops (and leaves the place to the
    /// reader) when an element read has another type.
    std::vector<uint8_t> types;
    static constexpr uint8_t kUnknownType = 0xFF;
    uint32_t end = 0;        ///< index of the token after the expression
    int minPrec = 0;         ///< the reader's context the code was compiled for
    bool full = false;
    bool colorCtx = false;
    bool hasRand = false;
    /// Every value the code makes is a float for the types last checked (no vector constant,
    /// identifier or function): it runs on plain numbers.
    bool scalar = false;
    uint8_t misses = 0;      ///< runs in a row that found an identifier of another kind
    int stack = 0;           ///< deepest stack the code needs
};

// The reader's operators (expressions.cpp), which the runs of compiled code share.
/// `a op b` for + - * / and the comparisons and `& |` (op: a Sym code), with POV-Ray's promotion.
Num combine(char op, const Num& a, const Num& b);
/// The same on two floats (each component's operation).
double combineFloats(char op, double x, double y);
/// Unary `-`, `+` or `!` on every component.
Num unaryOperator(char op, Num v);
/// `.gray` of a vector or colour.
double grayOf(const Num& v);
/// The component `.k` reads: 0 for x, u, red … 4 for transmit, 5 for gray; −1 for another keyword.
int componentIndex(Kw k);
/// The value of x, y, z, t, u, v, pi, true, yes, on, false, no, off; false for another keyword.
bool keywordConstant(Kw k, Num& out);
/// clock … version: keywords whose value comes from the options and the #version in force
/// (Interpreter::environmentValue).
bool isEnvironmentKeyword(Kw k);

/// True when the reader, fetching token t after an expression, may find more of the expression
/// than the text shows: t is a directive (it runs, and a macro's #end returns to the caller's
/// text), the end of a text (a macro or include ends), or an identifier (it may name a macro).
bool mayGoOnElsewhere(const Token& t);

/// Compiles the expression the reader's binary(minPrec, full, colorCtx) would read from
/// tokens[start] (tokens end with a Tk::End token). False when it uses anything not compiled.
bool compileExpression(const Token* tokens, uint32_t start, int minPrec, bool full, bool colorCtx, ExprCode& out);

/// Checks the code's types for identifiers of the given types (as ExprCode::types); false when the
/// reader would stop with an error (a component of a float, a vector in a condition, ...).
bool typeCheckExpression(const ExprCode& code, const uint8_t* identTypes);

/// Whether the code makes floats only for identifiers of the given types (ExprCode::scalar).
bool scalarExpression(const ExprCode& code, const uint8_t* identTypes);

}  // namespace rays::sdl
