// The arithmetic of each function op (fn/expr.h documents the semantics), written once and used
// by both the machine and the constant folder, so folded and evaluated values are bit-identical.
#pragma once
#include <cmath>
#include <numbers>

#include "rays/fn/expr.h"

namespace rays::fn::ops {

/// POV-Ray's int(): truncation through a 32-bit int; out of range (and NaN) gives INT_MIN.
inline double toInt(double a) {
    if (a > -2147483649.0 && a < 2147483648.0) return static_cast<double>(static_cast<int>(a));
    return -2147483648.0;
}
inline double truth(bool b) { return b ? 1.0 : 0.0; }
inline double maxOf(double a, double b) { return a < b ? b : a; }
inline double minOf(double a, double b) { return a < b ? a : b; }
inline double select3(double a, double b, double c) { return a < 0 ? b : c; }
inline double select4(double a, double b, double c, double d) { return a < 0 ? b : (a == 0 ? c : d); }
inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

// The ops that run as one machine instruction of the same name (Code::Neg, ...), each with its
// arithmetic on A (and B), listed once: unary() and binary() below, the machine's loops
// (fn/machine.cpp), the opcodes (fn/program.h) and the emitter's op → code maps (fn/emit.cpp)
// expand these lists.
#define RAYS_FN_UNARY_OPS(X)                                                                       \
    X(Neg, -A) X(Not, truth(A == 0)) X(Abs, std::fabs(A)) X(Acos, std::acos(A))                    \
    X(Acosh, std::acosh(A)) X(Asin, std::asin(A)) X(Asinh, std::asinh(A)) X(Atan, std::atan(A))    \
    X(Atanh, std::atanh(A)) X(Ceil, std::ceil(A)) X(Cos, std::cos(A)) X(Cosh, std::cosh(A))        \
    X(Exp, std::exp(A)) X(Floor, std::floor(A)) X(Sin, std::sin(A)) X(Sinh, std::sinh(A))          \
    X(Sqrt, std::sqrt(A)) X(Tan, std::tan(A)) X(Tanh, std::tanh(A)) X(Int, toInt(A))               \
    X(Ln, std::log(A)) X(Log, std::log10(A))
#define RAYS_FN_BINARY_OPS(X)                                                                      \
    X(Add, A + B) X(Sub, A - B) X(Mul, A * B) X(Div, A / B) X(Lt, truth(A < B))                    \
    X(Le, truth(A <= B)) X(Gt, truth(!(A <= B))) X(Ge, truth(!(A < B))) X(Eq, truth(A == B))       \
    X(Ne, truth(!(A == B))) X(And, truth(A != 0 && B != 0)) X(Or, truth(A != 0 || B != 0))         \
    X(Atan2, std::atan2(A, B)) X(Mod, std::fmod(A, B)) X(Pow, std::pow(A, B))                      \
    X(IntDiv, toInt(A / B)) X(Max, maxOf(A, B)) X(Min, minOf(A, B))

/// The value of a one-child op.
inline double unary(Op op, double A) {
    switch (op) {
#define RAYS_FN_UNARY_CASE(name, expr) \
    case Op::name: return (expr);
        RAYS_FN_UNARY_OPS(RAYS_FN_UNARY_CASE)
#undef RAYS_FN_UNARY_CASE
        case Op::Degrees: return A * kDegreesPerRadian;
        case Op::Radians: return A * kRadiansPerDegree;
        default: return std::nan("");
    }
}

/// The value of a two-child op (Max/Min: of two values).
inline double binary(Op op, double A, double B) {
    switch (op) {
#define RAYS_FN_BINARY_CASE(name, expr) \
    case Op::name: return (expr);
        RAYS_FN_BINARY_OPS(RAYS_FN_BINARY_CASE)
#undef RAYS_FN_BINARY_CASE
        default: return std::nan("");
    }
}

/// Member `m` of a result with `outputs` components in c[0..4] (missing ones read 0).
inline double member(Member m, const double* c, int outputs) {
    auto at = [&](int i) { return i < outputs ? c[i] : 0.0; };
    switch (m) {
        case Member::None:
        case Member::X: return at(0);
        case Member::Y: return at(1);
        case Member::Z: return at(2);
        case Member::Filter: return at(3);
        case Member::Transmit: return at(4);
        case Member::Gray: return 0.297 * at(0) + 0.589 * at(1) + 0.114 * at(2);
        case Member::Hf: return (at(0) + at(1) / 255) * 0.996093;
    }
    return 0;
}

}  // namespace rays::fn::ops
