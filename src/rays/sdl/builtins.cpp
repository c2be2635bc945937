// Built-in float and vector functions (POV-Ray 3.7 reference, "Float Functions", "Vector
// Functions"), and calls of user functions and splines.
#include <cmath>

#include "rays/sdl/frames.h"
#include "rays/sdl/interpreter.h"
#include "rays/sdl/pov_int.h"
#include "rays/sdl/pov_random.h"
#include "rays/sdl/pure_builtins.h"
#include "rays/sdl/pov_datetime.h"
#include "rays/sdl/pov_strings.h"

namespace rays::sdl {

bool Interpreter::isBuiltinFunction(Kw k) const {
    switch (k) {
        case Kw::abs: case Kw::acos: case Kw::acosh: case Kw::asc: case Kw::asin: case Kw::asinh: case Kw::atan:
        case Kw::atan2: case Kw::atanh: case Kw::bitwise_and: case Kw::bitwise_or: case Kw::bitwise_xor:
        case Kw::ceil: case Kw::cos: case Kw::cosh: case Kw::defined: case Kw::degrees: case Kw::dimensions:
        case Kw::dimension_size: case Kw::div: case Kw::exp: case Kw::file_exists: case Kw::floor:
        case Kw::inside: case Kw::int_: case Kw::ln: case Kw::log: case Kw::max: case Kw::min: case Kw::mod:
        case Kw::pow: case Kw::radians: case Kw::rand: case Kw::seed: case Kw::select: case Kw::sin:
        case Kw::sinh: case Kw::sqrt: case Kw::strcmp: case Kw::strlen: case Kw::tan: case Kw::tanh:
        case Kw::val: case Kw::vdot: case Kw::vlength: case Kw::min_extent: case Kw::max_extent:
        case Kw::trace: case Kw::vaxis_rotate: case Kw::vcross: case Kw::vrotate: case Kw::vnormalize:
        case Kw::vturbulence: case Kw::now:
            return true;
        default:
            return false;
    }
}

// The arguments of a call: '(' value {',' value} ')', each a numeric expression or a string.
Interpreter::Args Interpreter::callArgs(const char* name, size_t minArgs, size_t maxArgs) {
    if (!isSym('(')) errorHere(std::string("expected '(' after ") + name + ", found " + describe());
    next();
    Args args;
    if (!isSym(')')) {
        for (;;) {
            if (atStringStart()) args.push_back(Value::string(parseString()));
            else args.push_back(fullExpression());
            if (!acceptSym(',')) break;
        }
    }
    if (!isSym(')')) errorHere(std::string("expected ',' or ')' in the arguments of ") + name + ", found " + describe());
    next();
    if (args.size() < minArgs || args.size() > maxArgs) {
        const std::string want = minArgs == maxArgs ? std::to_string(minArgs)
                                 : maxArgs == SIZE_MAX ? std::to_string(minArgs) + " or more"
                                                       : std::to_string(minArgs) + " to " + std::to_string(maxArgs);
        errorHere(std::string(name) + " takes " + want + " arguments, " + std::to_string(args.size()) + " given");
    }
    return args;
}

Value Interpreter::builtin(Kw k, const Loc& at) {
    const std::string_view name = keywordName(k);
    next();
    auto f = [&](const Value& v, int i) {
        if (v.type == VType::Float) return v.c[0];
        return toFloat(v, at, std::string(name) + " argument " + std::to_string(i + 1));
    };
    auto str = [&](const Value& v) -> const std::string& {
        if (v.type != VType::String) error(at, std::string(name) + " needs a string");
        return v.str();
    };
    // One float argument: read directly, without an argument list.
    auto oneFloat = [&]() {
        if (!isSym('(')) errorHere(std::string("expected '(' after ") + std::string(name) + ", found " + describe());
        next();
        const Loc argAt = loc();
        const Num a = fullNum();
        if (!isSym(')')) errorHere(std::string(name) + " takes 1 argument; expected ')', found " + describe());
        next();
        if (a.type == VType::Float) return a.c[0];  // the message below is built only when needed
        return toFloat(a, argAt, std::string(name) + " argument 1");
    };
    auto one = [&](double (*fn)(double)) { return Value::number(fn(oneFloat())); };
    if (double (*fn1)(double) = mathFunction1(k)) return one(fn1);
    switch (k) {
        case Kw::atan2:
        case Kw::pow:
        case Kw::mod:
        case Kw::div: {
            const auto a = callArgs(name.data(), 2, 2);
            double r = 0;
            mathFunction2(k, f(a[0], 0), f(a[1], 1), r);
            return Value::number(r);
        }
        case Kw::max: case Kw::min: {
            const auto a = callArgs(name.data(), 1, SIZE_MAX);
            double r = f(a[0], 0);
            for (size_t i = 1; i < a.size(); ++i) r = k == Kw::max ? std::max(r, f(a[i], int(i))) : std::min(r, f(a[i], int(i)));
            return Value::number(r);
        }
        case Kw::bitwise_and: case Kw::bitwise_or: case Kw::bitwise_xor: {
            // 32-bit ints as POV-Ray 3.7 converts them (pov_int.h): bitwise_or(2^40 + 3, 0) and
            // bitwise_or(1e300, 0) give -2147483648 there.
            const auto a = callArgs(name.data(), 2, SIZE_MAX);
            int r = povInt(f(a[0], 0));
            for (size_t i = 1; i < a.size(); ++i) {
                const int b = povInt(f(a[i], int(i)));
                r = k == Kw::bitwise_and ? (r & b) : k == Kw::bitwise_or ? (r | b) : (r ^ b);
            }
            return Value::number(double(r));
        }
        case Kw::select: {
            const auto a = callArgs("select", 3, 4);
            const double s = f(a[0], 0);
            if (a.size() == 3) return s < 0 ? a[1] : a[2];
            return s < 0 ? a[1] : s == 0 ? a[2] : a[3];
        }
        case Kw::seed: return Value::number(random_.seed(oneFloat()));
        case Kw::rand: {
            const Outcome<double> r = random_.rand(oneFloat());
            if (!r.ok()) error(at, r.error);
            return Value::number(r.value);
        }
        case Kw::asc: return Value::number(povAsc(povString(str(callArgs("asc", 1, 1)[0]))));
        case Kw::strlen: return Value::number(povStrlen(povString(str(callArgs("strlen", 1, 1)[0]))));
        case Kw::strcmp: {
            const auto a = callArgs("strcmp", 2, 2);
            return Value::number(povStrcmp(povString(str(a[0])), povString(str(a[1]))));
        }
        case Kw::val: return Value::number(povVal(povString(str(callArgs("val", 1, 1)[0]))));
        case Kw::file_exists: return Value::number(findFile(str(callArgs("file_exists", 1, 1)[0])).empty() ? 0.0 : 1.0);
        case Kw::vdot: case Kw::vlength: case Kw::vcross: case Kw::vnormalize: case Kw::vrotate: case Kw::vaxis_rotate: {
            const size_t n = k == Kw::vaxis_rotate ? 3 : (k == Kw::vlength || k == Kw::vnormalize) ? 1 : 2;
            const auto a = callArgs(name.data(), n, n);
            Num in[3];
            for (size_t i = 0; i < n; ++i) in[i] = numericOf(a[i], at);
            if (k == Kw::vaxis_rotate) f(a[2], 2);  // the angle must be a float
            Num out;
            if (!vectorFunction(k, in, int(n), out)) {
                if (k == Kw::vnormalize) error(at, "vnormalize of a zero vector");
                error(at, "vaxis_rotate about a zero axis");
            }
            return out.value();
        }
        case Kw::vturbulence: {  // vturbulence(Lambda, Omega, Octaves, <P>)
            const Args a = callArgs("vturbulence", 4, 4);
            const Value& v = a[3];
            if (!v.isNumeric()) error(at, "vturbulence argument 4 must be a vector");
            const bool scalar = v.type == VType::Float;  // a float stands for <f, f, f>
            const double p[3] = {v.c[0], scalar ? v.c[0] : v.c[1], scalar ? v.c[0] : v.c[2]};
            double out[3];
            if (!host_.turbulence(p, f(a[0], 0), f(a[1], 1), int(f(a[2], 2)), out)) {
                warning(at, "not rendered yet: vturbulence (gives <0,0,0>)");
                return Value::vec3(0, 0, 0);
            }
            return Value::vec3(out[0], out[1], out[2]);
        }
        case Kw::now: return Value::number(povNow());
        case Kw::defined: {
            expectSym('(', "after defined");
            const bool d = definedName();
            expectSym(')', "after the identifier in defined()");
            return Value::number(d ? 1 : 0);
        }
        case Kw::dimensions: case Kw::dimension_size: {
            expectSym('(', "after ", name);
            const Binding* b = identBinding();
            if (!b || b->value.type != VType::Array) errorHere(std::string(name) + " needs an array identifier, found " + describe());
            const Value arr = b->value;
            next();
            double r = double(arr.arr().sizes.size());
            if (k == Kw::dimension_size) {
                expectSym(',', "in dimension_size");
                const int d = parseInt("the dimension");
                if (d < 1 || size_t(d) > arr.arr().sizes.size()) error(at, "dimension_size: no dimension " + std::to_string(d));
                r = arr.arr().sizes[size_t(d - 1)];
            }
            expectSym(')', "to close ", name);
            return Value::number(r);
        }
        case Kw::inside: case Kw::trace: case Kw::min_extent: case Kw::max_extent:
            return geometryQuery(k, at);
        default:
            break;
    }
    error(at, "'" + std::string(name) + "' is not a function");
}

// defined(NAME) / defined(NAME[i]): the '(' is consumed, the name is current.
bool Interpreter::definedName() {
    const Token& t = tokNoMacro();
    if (t.kind != Tk::Name) errorHere("expected an identifier, found " + describe());
    if (Names::isKeyword(t.id)) {
        next();
        return true;
    }
    Binding* b = scopes_.find(t.id);
    next();
    if (b && b->value.type == VType::Array && isSym('[')) {
        return arrayElement(b->value, true, nullptr).defined();
    }
    return b != nullptr;
}

// inside(O, V), trace(O, A, B [, N]), min_extent(O), max_extent(O): answered by the host.
Value Interpreter::geometryQuery(Kw k, const Loc& at) {
    const std::string name(keywordName(k));
    expectSym('(', "after ", name);
    const Binding* ob = identBinding();
    if (!ob || ob->value.type != VType::Item) errorHere(name + " needs an object identifier, found " + describe());
    const ItemRef object = ob->value.itemRef();
    next();
    auto vec = [&]() {
        expectSym(',', "in ", name);
        const auto v = parseVector(3);
        return std::array<double, 3>{v[0], v[1], v[2]};
    };
    if (k == Kw::inside) {
        const auto p = vec();
        expectSym(')', "to close inside");
        const int r = host_.inside(object, p.data());
        if (r < 0) {
            warning(at, "not rendered yet: inside() of this object (gives 0)");
            return Value::number(0);
        }
        return Value::number(r);
    }
    if (k == Kw::trace) {
        const auto origin = vec();
        const auto dir = vec();
        uint32_t normalName = UINT32_MAX;
        if (acceptSym(',')) {
            const Token& t = tokNoMacro();
            if (t.kind != Tk::Name || Names::isKeyword(t.id)) errorHere("trace's fourth argument must be an identifier");
            normalName = t.id;
            next();
        }
        expectSym(')', "to close trace");
        const ItemHost::TraceResult r = host_.trace(object, origin.data(), dir.data());
        if (!r.supported) warning(at, "not rendered yet: trace() of this object (gives <0,0,0>)");
        if (normalName != UINT32_MAX) {
            const Value n = r.hit ? Value::vec3(r.normal[0], r.normal[1], r.normal[2]) : Value::vec3(0, 0, 0);
            scopes_.declare(normalName, n);
        }
        return r.hit ? Value::vec3(r.point[0], r.point[1], r.point[2]) : Value::vec3(0, 0, 0);
    }
    expectSym(')', "to close ", name);
    double lo[3]{}, hi[3]{};
    if (!host_.extent(object, lo, hi)) {
        warning(at, "not rendered yet: " + name + "() of this object (gives <0,0,0>)");
        return Value::vec3(0, 0, 0);
    }
    return k == Kw::min_extent ? Value::vec3(lo[0], lo[1], lo[2]) : Value::vec3(hi[0], hi[1], hi[2]);
}

// SPLINE(t [, type]).
Value Interpreter::callSpline(const Value& s, const Loc& at) {
    expectSym('(', "after a spline identifier");
    const double t = toFloat(fullExpression(), at, "the spline parameter");
    const Spline& sp = s.spline();
    Spline::Type type = sp.type;
    if (acceptSym(',')) {
        switch (kw()) {
            case Kw::linear_spline: type = Spline::Type::Linear; break;
            case Kw::quadratic_spline: type = Spline::Type::Quadratic; break;
            case Kw::cubic_spline: type = Spline::Type::Cubic; break;
            case Kw::natural_spline: type = Spline::Type::Natural; break;
            default: errorHere("expected a spline type, found " + describe());
        }
        next();
    }
    expectSym(')', "to close the spline call");
    const std::array<double, 5> p = evaluateSpline(sp, type, t);
    if (sp.dim == 5) return Value::color(p[0], p[1], p[2], p[3], p[4]);
    return Value::vector(sp.dim, p.data());
}

}  // namespace rays::sdl
