#include "rays/fn/expr.h"

#include <string>

namespace rays::fn {

std::optional<Member> memberFromName(std::string_view name) {
    if (name == "x" || name == "u" || name == "red") return Member::X;
    if (name == "y" || name == "v" || name == "green") return Member::Y;
    if (name == "z" || name == "blue") return Member::Z;
    if (name == "t" || name == "filter") return Member::Filter;
    if (name == "transmit") return Member::Transmit;
    if (name == "gray" || name == "grey") return Member::Gray;
    if (name == "hf") return Member::Hf;
    return std::nullopt;
}

int32_t Expr::add(Op op, std::span<const int32_t> children, int32_t id, int32_t loc, Member member) {
    Node n;
    n.op = op;
    n.member = member;
    n.id = id;
    n.first = static_cast<int32_t>(kids.size());
    n.count = static_cast<int32_t>(children.size());
    n.loc = loc;
    kids.insert(kids.end(), children.begin(), children.end());
    nodes.push_back(n);
    root = static_cast<int32_t>(nodes.size()) - 1;
    return root;
}

int32_t Expr::constant(double v, int32_t loc) {
    int32_t i = add(Op::Const, {}, 0, loc);
    nodes[i].value = v;
    return i;
}

Arity opArity(Op op) {
    switch (op) {
        case Op::Const:
        case Op::Param:
        case Op::Local: return {0, 0};
        case Op::Neg: case Op::Not: case Op::Abs: case Op::Acos: case Op::Acosh: case Op::Asin:
        case Op::Asinh: case Op::Atan: case Op::Atanh: case Op::Ceil: case Op::Cos: case Op::Cosh:
        case Op::Exp: case Op::Floor: case Op::Sin: case Op::Sinh: case Op::Sqrt: case Op::Tan:
        case Op::Tanh: case Op::Degrees: case Op::Radians: case Op::Int: case Op::Ln: case Op::Log:
            return {1, 1};
        case Op::Add: case Op::Sub: case Op::Mul: case Op::Div: case Op::Lt: case Op::Le:
        case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne: case Op::And: case Op::Or:
        case Op::Atan2: case Op::Mod: case Op::Pow: case Op::IntDiv:
            return {2, 2};
        case Op::Cond: return {3, 3};
        case Op::Max: case Op::Min: return {2, -1};
        case Op::Select: return {3, 4};
        case Op::Sum: case Op::Prod: return {3, 3};
        case Op::Call: case Op::Internal: return {0, -1};
    }
    return {0, -1};
}

std::string_view opName(Op op) {
    switch (op) {
        case Op::Const: return "constant";
        case Op::Param: return "parameter";
        case Op::Local: return "iteration variable";
        case Op::Neg: return "unary -";
        case Op::Not: return "!";
        case Op::Abs: return "abs";
        case Op::Acos: return "acos";
        case Op::Acosh: return "acosh";
        case Op::Asin: return "asin";
        case Op::Asinh: return "asinh";
        case Op::Atan: return "atan";
        case Op::Atanh: return "atanh";
        case Op::Ceil: return "ceil";
        case Op::Cos: return "cos";
        case Op::Cosh: return "cosh";
        case Op::Exp: return "exp";
        case Op::Floor: return "floor";
        case Op::Sin: return "sin";
        case Op::Sinh: return "sinh";
        case Op::Sqrt: return "sqrt";
        case Op::Tan: return "tan";
        case Op::Tanh: return "tanh";
        case Op::Degrees: return "degrees";
        case Op::Radians: return "radians";
        case Op::Int: return "int";
        case Op::Ln: return "ln";
        case Op::Log: return "log";
        case Op::Add: return "+";
        case Op::Sub: return "-";
        case Op::Mul: return "*";
        case Op::Div: return "/";
        case Op::Lt: return "<";
        case Op::Le: return "<=";
        case Op::Gt: return ">";
        case Op::Ge: return ">=";
        case Op::Eq: return "=";
        case Op::Ne: return "!=";
        case Op::And: return "&";
        case Op::Or: return "|";
        case Op::Atan2: return "atan2";
        case Op::Mod: return "mod";
        case Op::Pow: return "pow";
        case Op::IntDiv: return "div";
        case Op::Cond: return "?:";
        case Op::Max: return "max";
        case Op::Min: return "min";
        case Op::Select: return "select";
        case Op::Sum: return "sum";
        case Op::Prod: return "prod";
        case Op::Call: return "function call";
        case Op::Internal: return "internal";
    }
    return "?";
}

Expr internalBody(int32_t number, int32_t params) {
    Expr e;
    std::vector<int32_t> args;
    for (int32_t i = 0; i < params; ++i) args.push_back(e.param(i));
    e.internal(number, args);
    return e;
}

}  // namespace rays::fn
