// Expressions (POV-Ray 3.7 reference, "Numeric Expressions", "Vector Expressions", "Color
// Expressions"), evaluated as they are read. Floats, vectors (2–5 components) and colours (5)
// combine component by component: a float fills every component of the other operand, a
// shorter vector is padded with zeros, anything combined with a colour is a colour. Relational,
// logical and conditional operators are allowed only inside parentheses, where POV-Ray allows
// them (elsewhere '<' and '>' are vector brackets).
#include <cmath>
#include <cstdio>
#include <numbers>

#include "rays/sdl/frames.h"
#include "rays/sdl/interpreter.h"

namespace rays::sdl {

namespace {

constexpr double kEpsilon = 1e-10;

/// The operands as two vectors of the same width (POV-Ray's promotion rules).
int promote(const Num& a, const Num& b, std::array<double, 5>& x, std::array<double, 5>& y, VType& type) {
    int dim;
    if (a.type == VType::Color || b.type == VType::Color) {
        type = VType::Color;
        dim = 5;
    } else if (a.type == VType::Vector || b.type == VType::Vector) {
        type = VType::Vector;
        dim = std::max(a.type == VType::Vector ? a.dim : 0, b.type == VType::Vector ? b.dim : 0);
    } else {
        type = VType::Float;
        dim = 1;
    }
    auto widen = [dim](const Num& v, std::array<double, 5>& out) {
        if (v.type == VType::Float) {
            out.fill(v.c[0]);
        } else {
            out = {};
            for (int i = 0; i < v.dim && i < dim; ++i) out[i] = v.c[i];
        }
    };
    widen(a, x);
    widen(b, y);
    return dim;
}

Num make(VType type, int dim, const std::array<double, 5>& c) {
    Num v;
    v.type = type;
    v.dim = uint8_t(dim);
    v.c = c;
    return v;
}

}  // namespace

// One operator on two floats (on each component of promoted vectors and colours).
double combineFloats(char op, double x, double y) {
    switch (op) {
        case '+': return x + y;
        case '-': return x - y;
        case '*': return x * y;
        case '/': return y == 0 ? HUGE_VAL : x / y;  // POV-Ray: x/0 is +inf for every x
        case '<': return x < y;
        case '>': return x > y;
        case kLessEq: return x < y || std::fabs(x - y) < kEpsilon;
        case kGreaterEq: return x > y || std::fabs(x - y) < kEpsilon;
        case '=': return std::fabs(x - y) < kEpsilon;
        case kNotEq: return std::fabs(x - y) >= kEpsilon;
        case '&': return std::fabs(x) > kEpsilon && std::fabs(y) > kEpsilon;
        case '|': return std::fabs(x) > kEpsilon || std::fabs(y) > kEpsilon;
    }
    return 0;
}

double grayOf(const Num& v) { return 0.297 * v.c[0] + 0.589 * v.c[1] + 0.114 * v.c[2]; }

int componentIndex(Kw k) {
    switch (k) {
        case Kw::x: case Kw::u: case Kw::red: return 0;
        case Kw::y: case Kw::v: case Kw::green: return 1;
        case Kw::z: case Kw::blue: return 2;
        case Kw::t: case Kw::filter: return 3;
        case Kw::transmit: return 4;
        case Kw::gray: return 5;
        default: return -1;
    }
}

bool keywordConstant(Kw k, Num& out) {
    auto vec = [&](int dim, double a, double b, double c = 0, double d = 0) {
        out = Num{};
        out.type = VType::Vector;
        out.dim = uint8_t(dim);
        out.c = {a, b, c, d, 0};
    };
    switch (k) {
        case Kw::x: vec(3, 1, 0, 0); return true;
        case Kw::y: vec(3, 0, 1, 0); return true;
        case Kw::z: vec(3, 0, 0, 1); return true;
        case Kw::t: vec(4, 0, 0, 0, 1); return true;
        case Kw::u: vec(2, 1, 0); return true;
        case Kw::v: vec(2, 0, 1); return true;
        case Kw::pi: out = Num::number(std::numbers::pi); return true;
        case Kw::true_: case Kw::yes: case Kw::on: out = Num::number(1); return true;
        case Kw::false_: case Kw::no: case Kw::off: out = Num::number(0); return true;
        default: return false;
    }
}

bool isEnvironmentKeyword(Kw k) {
    switch (k) {
        case Kw::clock: case Kw::clock_delta: case Kw::clock_on: case Kw::initial_clock: case Kw::final_clock:
        case Kw::initial_frame: case Kw::final_frame: case Kw::frame_number: case Kw::image_width:
        case Kw::image_height: case Kw::version:
            return true;
        default: return false;
    }
}

Num combine(char op, const Num& a, const Num& b) {
    if (a.type == VType::Float && b.type == VType::Float) return Num::number(combineFloats(op, a.c[0], b.c[0]));
    std::array<double, 5> x, y, r{};
    VType type;
    const int dim = promote(a, b, x, y, type);
    for (int i = 0; i < dim; ++i) r[i] = combineFloats(op, x[i], y[i]);  // component by component
    return make(type, dim, r);
}

double Interpreter::toFloat(const Value& v, const Loc& at, std::string_view what) {
    if (v.type != VType::Float) error(at, std::string(what) + " must be a float, found a " + typeName(v.type));
    return v.c[0];
}

double Interpreter::toFloat(const Num& v, const Loc& at, std::string_view what) {
    if (v.type != VType::Float)
        error(at, std::string(what) + " must be a float, found a " + typeName(v.type));
    return v.c[0];
}

Num Interpreter::numericOf(const Value& v, const Loc& at) {
    if (!v.isNumeric()) error(at, std::string("expected a numeric expression, found a ") + typeName(v.type));
    return Num::of(v);
}

bool Interpreter::atNumericStart() {
    const Token& t = tok();
    switch (t.kind) {
        case Tk::Number: return true;
        case Tk::Symbol: return t.sym == '<' || t.sym == '(' || t.sym == '-' || t.sym == '+' || t.sym == '!';
        case Tk::Name: {
            if (!Names::isKeyword(t.id)) {
                const Binding* b = scopes_.find(t.id);
                if (!b) return false;
                switch (b->value.type) {
                    case VType::Float: case VType::Vector: case VType::Color: case VType::Function: case VType::Spline:
                        return true;
                    case VType::Array: return isNumericType(b->value.arr().elemType);
                    default: return false;
                }
            }
            if (Num c; keywordConstant(Kw(t.id), c) || isEnvironmentKeyword(Kw(t.id))) return true;
            switch (Kw(t.id)) {
                case Kw::color: case Kw::colour: case Kw::rgb: case Kw::rgbf: case Kw::rgbt: case Kw::rgbft:
                case Kw::srgb: case Kw::srgbf: case Kw::srgbt: case Kw::srgbft: case Kw::red: case Kw::green:
                case Kw::blue: case Kw::filter: case Kw::transmit:
                    return true;
                default:
                    return isBuiltinFunction(Kw(t.id));
            }
        }
        default: return false;
    }
}

Value Interpreter::parseNumeric(bool colorContext) {
    NestGuard guard(*this);
    Num v = additive(colorContext);
    if (colorContext && v.type == VType::Color) v = colorComponents(v);
    return v.value();
}

double Interpreter::parseFloat() {
    const Loc at = loc();
    const Value v = parseNumeric(false);
    if (v.type == VType::Float) return v.c[0];
    error(at, std::string("expected a float, found a ") + typeName(v.type));
}

int Interpreter::parseInt(std::string_view what) {
    const Loc at = loc();
    const double v = parseFloat();
    if (!(std::fabs(v) < 2147483647.0)) error(at, std::string(what) + " is out of range");
    return int(v);
}

std::array<double, 5> Interpreter::parseVector(int dim) {
    const Loc at = loc();
    const Value v = parseNumeric(false);
    std::array<double, 5> r{};
    if (v.type == VType::Float) {
        for (int i = 0; i < dim; ++i) r[i] = v.c[0];
    } else if (v.isNumeric()) {
        for (int i = 0; i < dim && i < v.dim; ++i) r[i] = v.c[i];
    } else {
        error(at, std::string("expected a vector, found a ") + typeName(v.type));
    }
    return r;
}

Value Interpreter::parseColor() {
    const Loc at = loc();
    if (isKw(Kw::color) || isKw(Kw::colour)) next();
    Value v = parseNumeric(true);
    if (v.type == VType::Color) return v;
    if (v.type == VType::Float) return Value::color(v.c[0], v.c[0], v.c[0], v.c[0], v.c[0]);
    if (v.type == VType::Vector) {
        Value c = Value::color(0, 0, 0);
        for (int i = 0; i < v.dim; ++i) c.c[i] = v.c[i];
        return c;
    }
    error(at, std::string("expected a colour, found a ") + typeName(v.type));
}

bool Interpreter::parseOptionalBool() {
    if (!atNumericStart()) return true;
    const Loc at = loc();
    return truth(parseNumeric(false), at);
}

// FULL_EXPRESSION: LOGICAL [? FULL_EXPRESSION : FULL_EXPRESSION]; both branches are evaluated.
Num Interpreter::fullNum() {
    NestGuard guard(*this);
    Num c = logical();
    if (!isSym('?')) return c;
    const Loc at = loc();
    next();
    const bool pick = truth(c, at);
    Num a = fullNum();
    expectSym(':', "in a conditional expression");
    Num b = fullNum();
    return pick ? a : b;
}

// Binary operators by precedence, left-associative (one loop instead of a function per level):
// 1 `&` `|` and 2 the comparisons (full expressions only: inside parentheses), 3 `+` `-`, 4 `*` `/`.
Num Interpreter::binary(int minPrec, bool full, bool colorCtx) {
    Num quick;
    if (quickOperand(full, quick)) return quick;
    if (compiledOperand(minPrec, full, colorCtx, quick)) return binaryAfter(quick, minPrec, full, colorCtx);
    return binaryAfter(full && minPrec <= 2 && atStringStart() ? stringComparison() : unary(colorCtx), minPrec, full,
                       colorCtx);
}

// A number, or an identifier holding a float or vector, that the file's next token ends (`,` `)`
// `}` `]` `;`, and `>` outside parentheses where it closes a vector): the whole operand, read
// without the descent through unary, factor and postfix (most values in scenes are like this).
bool Interpreter::quickOperand(bool full, Num& out) {
    const Token& t = tok();
    const Token& after = *cursor_;  // the token after the current one in its array (not yet fetched)
    if (after.kind != Tk::Symbol) return false;
    switch (after.sym) {
        case ',': case ')': case '}': case ']': case ';': break;
        case '>': if (full) return false; break;
        default: return false;
    }
    if (t.kind == Tk::Number) {
        out = Num::number(t.number);
    } else if (t.kind == Tk::Name && !Names::isKeyword(t.id)) {
        const Binding* b = scopes_.find(t.id);
        if (!b || b->deprecated || (b->value.type != VType::Float && b->value.type != VType::Vector)) return false;
        out = Num::of(b->value);
    } else {
        return false;
    }
    next();
    return true;
}

// The operators after a first operand already read (a), as binary's loop.
Num Interpreter::binaryAfter(Num a, int minPrec, bool full, bool colorCtx) {
    for (;;) {
        const Token& t = tok();
        if (t.kind != Tk::Symbol) return a;
        int prec;
        switch (t.sym) {
            case '*': case '/': prec = 4; break;
            case '+': case '-': prec = 3; break;
            case '<': case '>': case '=': case kLessEq: case kGreaterEq: case kNotEq: prec = full ? 2 : 0; break;
            case '&': case '|': prec = full ? 1 : 0; break;
            default: prec = 0; break;
        }
        if (prec == 0 || prec < minPrec) return a;
        const char op = char(t.sym);
        next();
        a = combine(op, a, binary(prec + 1, full, colorCtx));
    }
}

// A comparison of two strings: `S1 < S2` and the other relational operators (strcmp order).
Num Interpreter::stringComparison() {
    const std::string a = parseString();
    const Loc at = loc();
    const Token t = tok();
    if (t.kind != Tk::Symbol) error(at, "expected a comparison after a string, found " + describe());
    next();
    const std::string b = parseString();
    const int c = a.compare(b);
    double r = 0;
    switch (t.sym) {
        case '<': r = c < 0; break;
        case '>': r = c > 0; break;
        case kLessEq: r = c <= 0; break;
        case kGreaterEq: r = c >= 0; break;
        case '=': r = c == 0; break;
        case kNotEq: r = c != 0; break;
        default: error(at, "expected a comparison after a string, found " + describe());
    }
    return Num::number(r);
}

Num unaryOperator(char op, Num v) {
    for (int i = 0; i < v.dim; ++i) {
        if (op == '-') v.c[i] = -v.c[i];
        else if (op == '!') v.c[i] = std::fabs(v.c[i]) > kEpsilon ? 0.0 : 1.0;
    }
    return v;
}

Num Interpreter::unary(bool colorCtx) {
    if (isSym('-') || isSym('+') || isSym('!')) {
        const char op = char(cur_->sym);
        NestGuard guard(*this);
        next();
        return unaryOperator(op, unary(colorCtx));
    }
    return postfix(factor(colorCtx));
}

// `.x .y .z .t .u .v .red .green .blue .filter .transmit .gray` after a vector or colour.
Num Interpreter::postfix(Num v) {
    while (isSym('.')) {
        next();
        const Loc at = loc();
        const int i = componentIndex(kw());
        if (i < 0) error(at, "expected x, y, z, t, u, v, red, green, blue, filter, transmit or gray after '.', found " + describe());
        next();
        if (v.type == VType::Float) error(at, "'.' needs a vector or colour, found a float");
        // Gray is POV-Ray's grey value of a colour (weights measured with POV-Ray 3.7).
        const double r = i == 5 ? grayOf(v) : (i < v.dim ? v.c[i] : 0.0);
        if (i < 5 && i >= v.dim) error(at, "the vector has only " + std::to_string(v.dim) + " components");
        v = Num::number(r);
    }
    return v;
}

Num Interpreter::factor(bool colorCtx) {
    const Token t = tok();
    const Loc at{curFile_, cur_->line, cur_->col};
    switch (t.kind) {
        case Tk::Number:
            next();
            return Num::number(t.number);
        case Tk::Symbol:
            if (t.sym == '(') {
                next();
                Num v = fullNum();
                expectSym(')', "to close '('");
                return v;
            }
            if (t.sym == '<') return vectorLiteral();
            break;
        case Tk::Name:
            if (!Names::isKeyword(t.id)) return identifierValue(colorCtx);
            if (Num c; keywordConstant(Kw(t.id), c)) {
                next();
                return c;
            }
            if (isEnvironmentKeyword(Kw(t.id))) {
                next();
                return Num::number(environmentValue(Kw(t.id)));
            }
            switch (Kw(t.id)) {
                case Kw::color: case Kw::colour: {
                    next();
                    NestGuard guard(*this);
                    Num c = additive(true);
                    return c.type == VType::Color ? colorComponents(c) : c;
                }
                case Kw::rgb: case Kw::rgbf: case Kw::rgbt: case Kw::rgbft: case Kw::srgb: case Kw::srgbf:
                case Kw::srgbt: case Kw::srgbft: case Kw::red: case Kw::green: case Kw::blue: case Kw::filter:
                case Kw::transmit:
                    return colorKeyword();
                default:
                    if (isBuiltinFunction(Kw(t.id))) return numericOf(builtin(Kw(t.id), at), at);
                    break;
            }
            break;
        default:
            break;
    }
    error(at, "expected a numeric expression, found " + describe());
}

// The keywords whose values come from the options and the #version in force.
double Interpreter::environmentValue(Kw k) const {
    switch (k) {
        case Kw::clock: return options_.animation.clock;
        case Kw::clock_delta: return options_.animation.clockDelta;
        case Kw::clock_on: return options_.animation.clockOn ? 1 : 0;
        case Kw::initial_clock: return options_.animation.initialClock;
        case Kw::final_clock: return options_.animation.finalClock;
        case Kw::initial_frame: return options_.animation.initialFrame;
        case Kw::final_frame: return options_.animation.finalFrame;
        case Kw::frame_number: return options_.animation.frameNumber;
        case Kw::image_width: return options_.imageWidth;
        case Kw::image_height: return options_.imageHeight;
        case Kw::version: return version_;
        default: return 0;
    }
}

Num Interpreter::vectorLiteral() {
    NestGuard guard(*this);  // vectors nest without parentheses: <<<1, 2>, 3>, 4>
    const Loc at = loc();
    next();  // '<'
    std::array<double, 5> c{};
    int n = 0;
    for (;;) {
        if (n == 5) error(at, "a vector has at most 5 components");
        const Loc compAt = loc();
        const Num v = additive(false);
        if (v.type != VType::Float) error(compAt, std::string("a vector component must be a float, found a ") + typeName(v.type));
        c[n++] = v.c[0];
        // Commas between components are optional and a trailing one is allowed (as in POV-Ray:
        // `< -1 0 0 >`, `<0.2, 0.1, 0.5,>`).
        acceptSym(',');
        if (isSym('>')) break;
    }
    next();
    if (n < 2) error(at, "a vector needs at least 2 components");
    Num r;
    r.type = VType::Vector;
    r.dim = uint8_t(n);
    r.c = c;
    return r;
}

Num Interpreter::identifierValue(bool colorCtx) {
    const Loc at = loc();
    const uint32_t id = cur_->id;
    Binding* b = scopes_.find(id);
    if (!b) error(at, "undeclared identifier '" + std::string(names_.name(id)) + "'");
    if (b->deprecated) {
        const std::string msg = b->deprecatedMessage != UINT32_MAX
                                    ? deprecatedMessages_[b->deprecatedMessage]
                                    : "identifier " + std::string(names_.name(id)) + " was declared deprecated";
        if (b->deprecatedOnce) b->deprecated = false;
        warning(at, msg);
    }
    if (b->value.type == VType::Float || b->value.type == VType::Vector) {  // the common case: no shared part copied
        const Num n = Num::of(b->value);
        next();
        return n;
    }
    const Value v = b->value;
    next();
    switch (v.type) {
        case VType::Color:
            return colorCtx ? colorComponents(Num::of(v)) : Num::of(v);
        case VType::Array: {
            if (!isSym('[')) error(at, "array '" + std::string(names_.name(id)) + "' needs an index here");
            Value e = arrayElement(v, false, nullptr);
            if (!e.isNumeric())
                error(at, "element of array '" + std::string(names_.name(id)) + "' is a " + typeName(e.type) + ", not a number");
            return Num::of(e);
        }
        case VType::Function: return Num::of(callFunction(v, at));
        case VType::Spline: return Num::of(callSpline(v, at));
        default:
            error(at, std::string("expected a numeric expression, found ") + typeName(v.type) + " identifier '" +
                          std::string(names_.name(id)) + "'");
    }
}

// `A[i][j]` with the array value given and '[' current: the element (Undefined when unset and
// forAssign; an error otherwise).
Value Interpreter::arrayElement(const Value& arr, bool forAssign, std::vector<size_t>* pathOut) {
    const ArrayData* a = &arr.arr();
    for (;;) {
        size_t flat = 0;
        for (size_t d = 0; d < a->sizes.size(); ++d) {
            const Loc at = loc();
            expectSym('[', "for the next array dimension");
            const double i = toFloat(fullExpression(), at, "an array index");
            expectSym(']', "after an array index");
            if (!(i > -1 && i < double(a->sizes[d]))) {  // checked as a float: 1e300 or NaN has no int
                char shown[32];
                std::snprintf(shown, sizeof shown, "%.10g", std::trunc(i));
                error(at, "array index " + std::string(shown) + " is out of range 0.." + std::to_string(a->sizes[d] - 1));
            }
            flat = flat * size_t(a->sizes[d]) + size_t(int(i));
        }
        if (pathOut) pathOut->push_back(flat);
        const Value& e = a->elems[flat];
        if (!e.defined() && !forAssign) errorHere("array element is used before it was given a value");
        // An element that is an array is indexed further: G[0][1] of an array of arrays.
        if (e.type != VType::Array || !isSym('[')) return e;
        a = &e.arr();
    }
}

// `rgb E` and its kin, and `red F` ... starting a colour.
Num Interpreter::colorKeyword() {
    NestGuard guard(*this);  // rgb rgb rgb 1 nests too
    const Kw k = kw();
    const Loc at = loc();
    next();
    if (k == Kw::red || k == Kw::green || k == Kw::blue || k == Kw::filter || k == Kw::transmit) {
        Num c = Num::of(Value::color(0, 0, 0));
        const int i = k == Kw::red ? 0 : k == Kw::green ? 1 : k == Kw::blue ? 2 : k == Kw::filter ? 3 : 4;
        c.c[i] = toFloat(additive(false), at, keywordName(k));
        return colorComponents(c);
    }
    const Num v = additive(false);
    const bool srgb = k == Kw::srgb || k == Kw::srgbf || k == Kw::srgbt || k == Kw::srgbft;
    const bool hasF = k == Kw::rgbf || k == Kw::rgbft || k == Kw::srgbf || k == Kw::srgbft;
    const bool hasT = k == Kw::rgbt || k == Kw::rgbft || k == Kw::srgbt || k == Kw::srgbft;
    const int want = 3 + hasF + hasT;
    // A float fills the components the keyword names; a vector gives them in order (measured
    // with POV-Ray 3.7: `rgb <1,2,3,4>` keeps the 4th as filter, with a warning).
    std::array<double, 5> in{};
    if (v.type == VType::Float) {
        in.fill(v.c[0]);
    } else {
        for (int i = 0; i < v.dim; ++i) in[i] = v.c[i];
        if (v.dim > want && v.type == VType::Vector) warning(at, "suspicious expression after " + std::string(keywordName(k)) + ": more components than it takes");
    }
    Num c = Num::of(Value::color(in[0], in[1], in[2]));
    if (k == Kw::rgb || k == Kw::srgb) {
        if (v.type == VType::Vector && v.dim > 3) c.c[3] = in[3];
        if (v.type == VType::Vector && v.dim > 4) c.c[4] = in[4];
    } else if (hasF && hasT) {
        c.c[3] = in[3];
        c.c[4] = in[4];
    } else if (hasF) {
        c.c[3] = in[3];
    } else if (hasT) {
        c.c[4] = in[3];
    }
    if (srgb) {
        // sRGB-encoded components decoded to linear, then to the working gamma (assumed_gamma).
        const double gamma = assumedGamma_ > 0 ? assumedGamma_ : 1.0;
        for (int i = 0; i < 3; ++i) {
            const double s = c.c[i];
            const double a = std::fabs(s);
            const double lin = a <= 0.04045 ? a / 12.92 : std::pow((a + 0.055) / 1.055, 2.4);
            c.c[i] = std::copysign(std::pow(lin, 1.0 / gamma), s);
        }
    }
    return colorComponents(c);
}

// `red F green F ...` after a colour: each replaces one component.
Num Interpreter::colorComponents(Num c) {
    for (;;) {
        const Kw k = kw();
        int i;
        switch (k) {
            case Kw::red: i = 0; break;
            case Kw::green: i = 1; break;
            case Kw::blue: i = 2; break;
            case Kw::filter: i = 3; break;
            case Kw::transmit: i = 4; break;
            default: return c;
        }
        const Loc at = loc();
        next();
        c.c[i] = toFloat(additive(false), at, keywordName(k));
    }
}

}  // namespace rays::sdl
