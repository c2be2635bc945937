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

/// The value of a one-child op.
inline double unary(Op op, double a) {
    switch (op) {
        case Op::Neg: return -a;
        case Op::Not: return truth(a == 0);
        case Op::Abs: return std::fabs(a);
        case Op::Acos: return std::acos(a);
        case Op::Acosh: return std::acosh(a);
        case Op::Asin: return std::asin(a);
        case Op::Asinh: return std::asinh(a);
        case Op::Atan: return std::atan(a);
        case Op::Atanh: return std::atanh(a);
        case Op::Ceil: return std::ceil(a);
        case Op::Cos: return std::cos(a);
        case Op::Cosh: return std::cosh(a);
        case Op::Exp: return std::exp(a);
        case Op::Floor: return std::floor(a);
        case Op::Sin: return std::sin(a);
        case Op::Sinh: return std::sinh(a);
        case Op::Sqrt: return std::sqrt(a);
        case Op::Tan: return std::tan(a);
        case Op::Tanh: return std::tanh(a);
        case Op::Degrees: return a * kDegreesPerRadian;
        case Op::Radians: return a * kRadiansPerDegree;
        case Op::Int: return toInt(a);
        case Op::Ln: return std::log(a);
        case Op::Log: return std::log10(a);
        default: return std::nan("");
    }
}

/// The value of a two-child op (Max/Min: of two values).
inline double binary(Op op, double a, double b) {
    switch (op) {
        case Op::Add: return a + b;
        case Op::Sub: return a - b;
        case Op::Mul: return a * b;
        case Op::Div: return a / b;
        case Op::Lt: return truth(a < b);
        case Op::Le: return truth(a <= b);
        case Op::Gt: return truth(!(a <= b));
        case Op::Ge: return truth(!(a < b));
        case Op::Eq: return truth(a == b);
        case Op::Ne: return truth(!(a == b));
        case Op::And: return truth(a != 0 && b != 0);
        case Op::Or: return truth(a != 0 || b != 0);
        case Op::Atan2: return std::atan2(a, b);
        case Op::Mod: return std::fmod(a, b);
        case Op::Pow: return std::pow(a, b);
        case Op::IntDiv: return toInt(a / b);
        case Op::Max: return maxOf(a, b);
        case Op::Min: return minOf(a, b);
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
