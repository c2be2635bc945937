// The compiler of expr_code.h: the grammar of expressions.cpp (binary, unary, postfix, factor,
// vectorLiteral, fullNum) and of the built-in calls of builtins.cpp, over raw tokens.
#include "rays/sdl/expr_code.h"

#include <algorithm>

#include "rays/sdl/names.h"
#include "rays/sdl/pure_builtins.h"

namespace rays::sdl {

namespace {

constexpr int kMaxCompiledDepth = 64;   // nesting of the compiled grammar
constexpr int kMaxCompiledStack = 32;   // values on the run's stack (Interpreter::compiledOperand)

class ExprCompiler {
public:
    ExprCompiler(const Token* tokens, uint32_t start, ExprCode& out) : t_(tokens), pos_(start), out_(out) {}

    bool binary(int minPrec, bool full) {
        if (!enter()) return false;
        if (!unary()) return false;
        for (;;) {
            const Token& t = t_[pos_];
            if (t.kind != Tk::Symbol) break;
            const int prec = precedence(t.sym, full);
            if (prec == 0 || prec < minPrec) break;
            if (depth_ == 1) plainFactor = false;
            ++pos_;
            if (!binary(prec + 1, full)) return false;
            emit(ExprOp::Binary, t.sym);
        }
        --depth_;
        return true;
    }

    /// FULL_EXPRESSION: the operators of a parenthesised expression and `c ? a : b`.
    bool fullNum() {
        if (!enter()) return false;
        if (!binary(1, true)) return false;
        if (isSym('?')) {
            ++pos_;
            if (!fullNum()) return false;
            if (!isSym(':')) return false;
            ++pos_;
            if (!fullNum()) return false;
            emit(ExprOp::Cond, 0);
        }
        --depth_;
        return true;
    }

    uint32_t pos() const { return pos_; }
    int stack() const { return maxStack_; }
    /// The top-level operand was one factor with its components (no unary operator, no binary one).
    bool plainFactor = true;

private:
    static int precedence(uint8_t sym, bool full) {
        switch (sym) {
            case '*': case '/': return 4;
            case '+': case '-': return 3;
            case '<': case '>': case '=': case kLessEq: case kGreaterEq: case kNotEq: return full ? 2 : 0;
            case '&': case '|': return full ? 1 : 0;
            default: return 0;
        }
    }

    bool enter() { return ++depth_ <= kMaxCompiledDepth; }
    bool isSym(char c) const { return t_[pos_].kind == Tk::Symbol && t_[pos_].sym == uint8_t(c); }

    // Tracks the stack depth each op leaves.
    void emit(ExprOp::Code code, uint8_t aux, uint32_t arg = 0, uint32_t at = 0) {
        out_.ops.push_back(ExprOp{code, aux, arg, at});
        switch (code) {
            case ExprOp::Const: case ExprOp::Ident: case ExprOp::Env: ++height_; break;
            case ExprOp::Binary: case ExprOp::Math2: --height_; break;
            case ExprOp::Element: height_ -= aux - 1; break;
            case ExprOp::Cond: height_ -= 2; break;
            case ExprOp::Vector: case ExprOp::MinMax: case ExprOp::VecFn: case ExprOp::Select: height_ -= aux - 1; break;
            default: break;
        }
        maxStack_ = std::max(maxStack_, height_);
    }
    void constant(const Num& v) {
        out_.consts.push_back(v);
        emit(ExprOp::Const, 0, uint32_t(out_.consts.size() - 1));
    }

    bool unary() {
        if (isSym('-') || isSym('+') || isSym('!')) {
            const uint8_t op = t_[pos_].sym;
            if (depth_ == 1) plainFactor = false;
            ++pos_;
            if (!enter() || !unary()) return false;
            --depth_;
            if (op == '-') emit(ExprOp::Neg, 0);
            else if (op == '!') emit(ExprOp::Not, 0);
            return true;
        }
        if (!factor()) return false;
        return postfix();
    }

    bool postfix() {
        while (isSym('.')) {
            ++pos_;
            const Token& t = t_[pos_];
            if (t.kind != Tk::Name || !Names::isKeyword(t.id)) return false;
            const int i = componentIndex(Kw(t.id));
            if (i < 0) return false;
            ++pos_;
            emit(ExprOp::Dot, uint8_t(i));
        }
        return true;
    }

    bool factor() {
        const Token& t = t_[pos_];
        switch (t.kind) {
            case Tk::Number:
                ++pos_;
                constant(Num::number(t.number));
                return true;
            case Tk::Symbol:
                if (t.sym == '(') {
                    ++pos_;
                    if (!fullNum() || !isSym(')')) return false;
                    ++pos_;
                    return true;
                }
                if (t.sym == '<') return vectorLiteral();
                return false;
            case Tk::Name:
                if (!Names::isKeyword(t.id)) return identifier(t.id);
                return keyword(Kw(t.id));
            default:
                return false;
        }
    }

    // A value, or an array's element `A[i][j]...` (the indices are full expressions, as
    // arrayElement reads them).
    bool identifier(uint32_t id) {
        ++pos_;
        int n = 0;
        while (isSym('[')) {
            ++pos_;
            if (n == 5 || !fullNum() || !isSym(']')) return false;
            ++pos_;
            ++n;
        }
        out_.idents.push_back(id);
        out_.indexCount.push_back(uint8_t(n));
        if (n == 0) {
            emit(ExprOp::Ident, 0, id);
        } else {
            emit(ExprOp::Element, uint8_t(n), id);
            out_.hasElement = true;
        }
        return true;
    }

    bool keyword(Kw k) {
        const uint32_t at = pos_;
        ++pos_;
        if (Num c; keywordConstant(k, c)) {
            constant(c);
            return true;
        }
        if (isEnvironmentKeyword(k)) {
            emit(ExprOp::Env, 0, uint32_t(k));
            return true;
        }
        if (mathFunction1(k)) return oneFloat(ExprOp::Math1, k, at);
        switch (k) {
            case Kw::rand:
                out_.hasRand = true;
                return oneFloat(ExprOp::Rand, k, at);
            case Kw::atan2: case Kw::pow: case Kw::mod: case Kw::div: return call(ExprOp::Math2, k, at, 2, 2);
            case Kw::max: case Kw::min: return call(ExprOp::MinMax, k, at, 1, 255);
            case Kw::select: return call(ExprOp::Select, k, at, 3, 4);
            case Kw::vdot: case Kw::vcross: case Kw::vrotate: return call(ExprOp::VecFn, k, at, 2, 2);
            case Kw::vlength: case Kw::vnormalize: return call(ExprOp::VecFn, k, at, 1, 1);
            default: return false;
        }
    }

    // `( FULL_EXPRESSION )` as builtins.cpp's oneFloat reads it.
    bool oneFloat(ExprOp::Code code, Kw k, uint32_t at) {
        if (!isSym('(')) return false;
        ++pos_;
        if (!fullNum() || !isSym(')')) return false;
        ++pos_;
        emit(code, 1, uint32_t(k), at);
        return true;
    }

    // `( E {, E} )` as builtins.cpp's callArgs reads it, with minArgs..maxArgs values.
    bool call(ExprOp::Code code, Kw k, uint32_t at, int minArgs, int maxArgs) {
        if (!isSym('(')) return false;
        ++pos_;
        int n = 0;
        if (!isSym(')')) {
            for (;;) {
                if (!fullNum()) return false;
                ++n;
                if (!isSym(',')) break;
                ++pos_;
            }
        }
        if (!isSym(')') || n < minArgs || n > maxArgs) return false;
        ++pos_;
        emit(code, uint8_t(n), uint32_t(k), at);
        return true;
    }

    bool vectorLiteral() {
        ++pos_;  // '<'
        if (!enter()) return false;
        int n = 0;
        for (;;) {
            if (n == 5) return false;
            if (!binary(3, false)) return false;
            ++n;
            if (isSym(',')) ++pos_;
            if (isSym('>')) break;
        }
        ++pos_;
        --depth_;
        if (n < 2) return false;
        emit(ExprOp::Vector, uint8_t(n));
        return true;
    }

    const Token* t_;
    uint32_t pos_;
    ExprCode& out_;
    int depth_ = 0;
    int height_ = 0;
    int maxStack_ = 0;
};

struct TypeOf {
    VType type = VType::Float;
    int dim = 1;
    bool operator==(const TypeOf& o) const { return type == o.type && dim == o.dim; }
};

}  // namespace

bool mayGoOnElsewhere(const Token& t) {
    return t.kind == Tk::Directive || t.kind == Tk::End || (t.kind == Tk::Name && !Names::isKeyword(t.id));
}

bool compileExpression(const Token* tokens, uint32_t start, int minPrec, bool full, bool colorCtx, ExprCode& out) {
    out = ExprCode{};
    out.minPrec = minPrec;
    out.full = full;
    out.colorCtx = colorCtx;
    ExprCompiler c(tokens, start, out);
    if (!c.binary(minPrec, full)) return false;
    if (c.stack() > kMaxCompiledStack) return false;
    // Where a directive or the end of the text follows, the reader goes on after it (a directive
    // runs, a macro returns) and may find more of the expression there: the code may stop there
    // only when what it read is one operand that the reader's postfix and binary loops can carry
    // on from (Interpreter::compiledOperand).
    if (mayGoOnElsewhere(tokens[c.pos()]) && !c.plainFactor) return false;
    // A run that meets an element of another type stops and leaves the place to the reader, which
    // must then find rand()'s stream as it was.
    if (out.hasElement && out.hasRand) return false;
    out.end = c.pos();
    out.stack = c.stack();
    out.types.assign(out.idents.size(), ExprCode::kUnknownType);
    return true;
}

bool typeCheckExpression(const ExprCode& code, const uint8_t* identTypes) {
    TypeOf stack[kMaxCompiledStack + 1];
    int top = 0;
    size_t ident = 0;
    auto floats = [&](int n) {
        for (int i = 0; i < n; ++i)
            if (stack[top - 1 - i].type != VType::Float) return false;
        return true;
    };
    for (const ExprOp& op : code.ops) {
        switch (op.code) {
            case ExprOp::Const: {
                const Num& v = code.consts[op.arg];
                stack[top++] = {v.type, v.dim};
                break;
            }
            case ExprOp::Ident: {
                const uint8_t t = identTypes[ident++];
                stack[top++] = t == 0 ? TypeOf{} : TypeOf{VType::Vector, t};
                break;
            }
            case ExprOp::Element: {
                if (!floats(op.aux)) return false;  // the indices
                const uint8_t t = identTypes[ident++];
                top -= op.aux - 1;
                stack[top - 1] = t == 0 ? TypeOf{} : TypeOf{VType::Vector, t};
                break;
            }
            case ExprOp::Env: stack[top++] = TypeOf{}; break;
            case ExprOp::Neg: case ExprOp::Not: break;
            case ExprOp::Binary: {
                const TypeOf b = stack[--top], a = stack[top - 1];
                if (a.type == VType::Float && b.type == VType::Float) break;
                stack[top - 1] = {VType::Vector, std::max(a.type == VType::Vector ? a.dim : 0, b.type == VType::Vector ? b.dim : 0)};
                break;
            }
            case ExprOp::Dot: {
                const TypeOf v = stack[top - 1];
                if (v.type == VType::Float || (op.aux < 5 && op.aux >= v.dim)) return false;
                stack[top - 1] = TypeOf{};
                break;
            }
            case ExprOp::Vector:
                if (!floats(op.aux)) return false;
                top -= op.aux - 1;
                stack[top - 1] = {VType::Vector, op.aux};
                break;
            case ExprOp::Math1: case ExprOp::Rand:
                if (!floats(1)) return false;
                break;
            case ExprOp::Math2: case ExprOp::MinMax:
                if (!floats(op.aux)) return false;
                top -= op.aux - 1;
                break;
            case ExprOp::VecFn: {
                const Kw k = Kw(op.arg);
                top -= op.aux - 1;
                stack[top - 1] = (k == Kw::vdot || k == Kw::vlength) ? TypeOf{} : TypeOf{VType::Vector, 3};
                break;
            }
            case ExprOp::Select: {
                // The value picked depends on the selector: the choices must agree in type.
                const int n = op.aux;
                const TypeOf first = stack[top - n + 1];
                if (stack[top - n].type != VType::Float) return false;
                for (int i = 2; i < n; ++i)
                    if (!(stack[top - n + i] == first)) return false;
                top -= n - 1;
                stack[top - 1] = first;
                break;
            }
            case ExprOp::Cond: {
                const TypeOf b = stack[--top], a = stack[--top];
                if (stack[top - 1].type != VType::Float || !(a == b)) return false;
                stack[top - 1] = a;
                break;
            }
        }
    }
    return top == 1;
}

bool scalarExpression(const ExprCode& code, const uint8_t* identTypes) {
    for (size_t i = 0; i < code.idents.size(); ++i)
        if (identTypes[i] != 0) return false;
    for (const Num& c : code.consts)
        if (c.type != VType::Float) return false;
    for (const ExprOp& op : code.ops)
        if (op.code == ExprOp::Vector || op.code == ExprOp::Dot || op.code == ExprOp::VecFn) return false;
    return true;
}

}  // namespace rays::sdl
