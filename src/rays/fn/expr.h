// The expression tree of one user function (`function(a, b) { ... }`), as the scene-language
// parser builds it and the compiler (fn/compile.h) reads it. Plain values: one vector of nodes,
// children referred to by index (always smaller than their parent's index, so a tree is built
// bottom-up and has no cycles), their indices listed in `kids`.
//
// Semantics are POV-Ray 3.7's for function bodies (reference 3.3.1.5 "Numeric Expressions",
// 3.3.1.8 "Function", and black-box runs of POV-Ray 3.7 where the manual is silent; the
// measured cases are noted below). Inside functions POV-Ray compares and tests truth exactly,
// without the parse-time epsilon: `(1 = 1+1e-12)` is 0 and `(1e-12 & 1)` is 1.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace rays::fn {

enum class Op : uint8_t {
    Const,     ///< `value`
    Param,     ///< the function's parameter number `id` (0-based: x y z are 0 1 2 by default)
    Local,     ///< the iteration variable of the innermost enclosing Sum/Prod whose slot is `id`
    // Unary: one child.
    Neg,       ///< -a
    Not,       ///< !a: 1 when a == 0 exactly, else 0 (POV-Ray 3.7 rejects `!` in functions)
    Abs, Acos, Acosh, Asin, Asinh, Atan, Atanh, Ceil, Cos, Cosh, Exp, Floor, Sin, Sinh, Sqrt,
    Tan, Tanh,  ///< the C library's functions of the same name (IEEE results: sqrt(-1) is NaN)
    Degrees,   ///< a·(180/π), the constant rounded first (measured)
    Radians,   ///< a·(π/180), the constant rounded first (measured)
    Int,       ///< a truncated toward zero through a 32-bit int: outside (-2^31-1, 2^31), and for
               ///< NaN, -2147483648 (measured: int(1e20) is -2147483648 in a POV-Ray function)
    Ln,        ///< natural logarithm
    Log,       ///< base-10 logarithm
    // Binary: two children.
    Add, Sub, Mul, Div,  ///< IEEE: 1/0 is inf, no error (measured)
    Lt, Le,    ///< (a < b), (a <= b): 1 or 0, false when either is NaN
    Gt, Ge,    ///< !(a <= b), !(a < b): true when either is NaN (measured: (1 > nan) is 1)
    Eq, Ne,    ///< (a == b), !(a == b), exact (measured)
    And, Or,   ///< (a != 0 && b != 0), (a != 0 || b != 0) as 1 or 0; NaN is true (measured)
    Atan2,     ///< atan2(a, b)
    Mod,       ///< fmod(a, b): sign of a, mod(-7, 3) = -1, mod(1, 0) = NaN (measured)
    Pow,       ///< pow(a, b)
    IntDiv,    ///< `div(a, b)`: Int(a / b) (measured: div(-7, 2) = -3)
    // Others.
    Cond,      ///< (a ? b : c): b when a != 0 (NaN counts as true); POV-Ray 3.7 rejects `?:` in functions
    Max, Min,  ///< two or more children, folded left: max(a,b) = a < b ? b : a, min(a,b) = a < b ? a : b
               ///< (measured with NaN: max(nan,1) = nan, max(1,nan) = 1, min(nan,1) = 1, min(1,nan) = nan)
    Select,    ///< 3 children: a < 0 ? b : c; 4 children: a < 0 ? b : a == 0 ? c : d (NaN gives c or d)
    Sum, Prod, ///< children from, to, body; the body sees Local `id` = from, from+1, ... while it is
               ///< <= to; Sum starts at 0, Prod at 1 (sum(i, 0.5, 3, i) = 4.5; sum(i, 3, 1, i) = 0)
    Call,      ///< function `id` of the same table (declared earlier), children = its arguments;
               ///< `member` picks a component of a host function's vector/colour result
    Internal,  ///< POV-Ray's internal(id) (fn/internal_functions.h), children = its arguments
};

/// A component of a vector or colour result (`.x` etc.). POV-Ray 3.7 accepts .x .y .z .t .u .v
/// .red .green .blue .filter .transmit .gray/.grey and .hf after a call of a vector or colour
/// function (measured): .x = .u = .red is component 0, .y = .v = .green 1, .z = .blue 2,
/// .t = .filter 3, .transmit 4. Components past a function's outputs read 0 (POV-Ray reads
/// whatever was there before).
enum class Member : uint8_t {
    None,
    X,         ///< component 0
    Y,         ///< component 1
    Z,         ///< component 2
    Filter,    ///< component 3 (`.t` as well)
    Transmit,  ///< component 4
    Gray,      ///< 0.297·c0 + 0.589·c1 + 0.114·c2 (reference 2.3 "Isosurface": pigment functions)
    Hf,        ///< (c0 + c1/255)·0.996093, POV-Ray's experimental height-field value
};

/// The member named by a dot item (without the dot): "x", "u", "red", "t", "gray", "grey", "hf", ...
std::optional<Member> memberFromName(std::string_view name);

/// One node. Which fields matter depends on `op` (see Op).
struct Node {
    Op op = Op::Const;
    Member member = Member::None;  ///< Call only
    int32_t id = 0;                ///< Param/Local/Sum/Prod slot, Call's function, Internal's number
    int32_t first = 0;             ///< first child's position in Expr::kids
    int32_t count = 0;             ///< number of children
    double value = 0;              ///< Const only
    int32_t loc = 0;               ///< the parser's tag for messages (opaque here)
};

/// A function body: nodes, their children's indices and the root. Build it bottom-up with the
/// helpers (each returns the new node's index).
struct Expr {
    std::vector<Node> nodes;
    std::vector<int32_t> kids;
    int32_t root = -1;

    /// The children of `n`, in order.
    std::span<const int32_t> children(const Node& n) const {
        return {kids.data() + n.first, static_cast<size_t>(n.count)};
    }
    /// A node of kind `op` with the given children (and id/member where the op uses them).
    int32_t add(Op op, std::span<const int32_t> children, int32_t id = 0, int32_t loc = 0,
                Member member = Member::None);
    int32_t add(Op op, std::initializer_list<int32_t> children, int32_t id = 0, int32_t loc = 0) {
        return add(op, std::span<const int32_t>(children.begin(), children.size()), id, loc);
    }
    /// A constant.
    int32_t constant(double v, int32_t loc = 0);
    /// Parameter number `slot`.
    int32_t param(int32_t slot, int32_t loc = 0) { return add(Op::Param, {}, slot, loc); }
    /// The iteration variable of the enclosing Sum/Prod with this slot.
    int32_t local(int32_t slot, int32_t loc = 0) { return add(Op::Local, {}, slot, loc); }
    /// sum(i, from, to, body) or prod(...) with i in `slot`.
    int32_t sequence(Op sumOrProd, int32_t slot, int32_t from, int32_t to, int32_t body, int32_t loc = 0) {
        return add(sumOrProd, {from, to, body}, slot, loc);
    }
    /// A call of function `fn` of the table, with an optional member of its result.
    int32_t call(int32_t fn, std::span<const int32_t> args, Member member = Member::None, int32_t loc = 0) {
        return add(Op::Call, args, fn, loc, member);
    }
    /// internal(number) applied to args.
    int32_t internal(int32_t number, std::span<const int32_t> args, int32_t loc = 0) {
        return add(Op::Internal, args, number, loc);
    }
};

/// Children an op takes: {min, max} (max -1 = any number from min up).
struct Arity {
    int min, max;
};
Arity opArity(Op op);

/// The op's name as written in POV-Ray ("sin", "+", "select", "sum"), for messages.
std::string_view opName(Op op);

/// The body `internal(number)` over parameters 0..params-1, as `function { internal(N) }` declares.
Expr internalBody(int32_t number, int32_t params);

}  // namespace rays::fn
