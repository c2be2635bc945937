// `function { ... }` values: the body is read through the interpreter's token stream (so macros
// in it run once, as POV-Ray does) into an fn::Expr, compiled into the parse's function table;
// and calls of functions while parsing. Function bodies follow POV-Ray 3.7 reference 3.3.1.8:
// x y z (or the named parameters), floats and their operators (comparisons need no
// parentheses here), the float functions, sum/prod, calls of functions declared earlier with an
// optional .member, and internal(N).
#include <cmath>

#include "rays/fn/compile.h"
#include "rays/fn/internal_functions.h"
#include "rays/fn/machine.h"
#include "rays/sdl/frames.h"
#include "rays/sdl/function_value.h"
#include "rays/sdl/interpreter.h"
#include "rays/sdl/pov_int.h"

namespace rays::sdl {

// The stand-in for a pattern or pigment function the host cannot evaluate: it gives 0.
void evalZero(const void*, const double*, double* out) {
    for (int i = 0; i < 5; ++i) out[i] = 0;
}

bool isPatternStub(const fn::HostFunction& h) { return h.fn == evalZero; }

namespace {

struct TransformData {
    double m[3][4];
};
// A transform function: its three outputs are the transformed point.
void evalTransform(const void* data, const double* in, double* out) {
    const auto& t = *static_cast<const TransformData*>(data);
    for (int r = 0; r < 3; ++r) out[r] = t.m[r][0] * in[0] + t.m[r][1] * in[1] + t.m[r][2] * in[2] + t.m[r][3];
}
// A spline function: the spline at in[0].
void evalSpline(const void* data, const double* in, double* out) {
    const auto& s = *static_cast<const Spline*>(data);
    const std::array<double, 5> p = evaluateSpline(s, s.type, in[0]);
    for (int i = 0; i < s.dim; ++i) out[i] = p[size_t(i)];
}

class BodyReader {
public:
    BodyReader(Interpreter& in, const FunctionValue& f) : in_(in), f_(f) {}

    fn::Expr read() {
        e_.root = cond();
        return std::move(e_);
    }
    const std::vector<Loc>& locs() const { return locs_; }

private:
    int32_t tag() {
        locs_.push_back(in_.loc());
        return int32_t(locs_.size() - 1);
    }

    int32_t cond() {
        const int32_t c = orTerm();
        if (!in_.isSym('?')) return c;
        const int32_t t = tag();
        in_.next();
        const int32_t a = cond();
        in_.expectSym(':', "in a conditional expression");
        const int32_t b = cond();
        return e_.add(fn::Op::Cond, {c, a, b}, 0, t);
    }
    int32_t orTerm() {
        int32_t a = andTerm();
        while (in_.isSym('|')) {
            const int32_t t = tag();
            in_.next();
            a = e_.add(fn::Op::Or, {a, andTerm()}, 0, t);
        }
        return a;
    }
    int32_t andTerm() {
        int32_t a = relTerm();
        while (in_.isSym('&')) {
            const int32_t t = tag();
            in_.next();
            a = e_.add(fn::Op::And, {a, relTerm()}, 0, t);
        }
        return a;
    }
    int32_t relTerm() {
        int32_t a = sum();
        for (;;) {
            const Token& tk = in_.tok();
            if (tk.kind != Tk::Symbol) return a;
            fn::Op op;
            switch (tk.sym) {
                case '<': op = fn::Op::Lt; break;
                case '>': op = fn::Op::Gt; break;
                case '=': op = fn::Op::Eq; break;
                case kLessEq: op = fn::Op::Le; break;
                case kGreaterEq: op = fn::Op::Ge; break;
                case kNotEq: op = fn::Op::Ne; break;
                default: return a;
            }
            const int32_t t = tag();
            in_.next();
            a = e_.add(op, {a, sum()}, 0, t);
        }
    }
    int32_t sum() {
        int32_t a = product();
        while (in_.isSym('+') || in_.isSym('-')) {
            const fn::Op op = in_.isSym('+') ? fn::Op::Add : fn::Op::Sub;
            const int32_t t = tag();
            in_.next();
            a = e_.add(op, {a, product()}, 0, t);
        }
        return a;
    }
    int32_t product() {
        int32_t a = unary();
        while (in_.isSym('*') || in_.isSym('/')) {
            const fn::Op op = in_.isSym('*') ? fn::Op::Mul : fn::Op::Div;
            const int32_t t = tag();
            in_.next();
            a = e_.add(op, {a, unary()}, 0, t);
        }
        return a;
    }
    int32_t unary() {
        if (in_.isSym('+')) {
            in_.next();
            return unary();
        }
        if (in_.isSym('-') || in_.isSym('!')) {
            const fn::Op op = in_.isSym('-') ? fn::Op::Neg : fn::Op::Not;
            const int32_t t = tag();
            in_.next();
            Interpreter::NestGuard guard(in_);
            return e_.add(op, {unary()}, 0, t);
        }
        return primary();
    }

    // '(' a, b, ... ')' of a call: the children's node indices.
    std::vector<int32_t> args(const char* what) {
        in_.expectSym('(', "after ", what);
        std::vector<int32_t> out;
        if (!in_.isSym(')')) {
            for (;;) {
                out.push_back(cond());
                if (!in_.acceptSym(',')) break;
            }
        }
        in_.expectSym(')', "to close the arguments of ", what);
        return out;
    }

    int32_t param(uint32_t name) {
        // x and u, y and v name the same parameter (POV-Ray 3.7 reference, "Declaring User-Defined Float Functions").
        auto alias = [](uint32_t n) -> uint32_t {
            if (n == uint32_t(Kw::u)) return uint32_t(Kw::x);
            if (n == uint32_t(Kw::v)) return uint32_t(Kw::y);
            return n;
        };
        for (size_t i = 0; i < f_.params.size(); ++i)
            if (alias(f_.params[i]) == alias(name)) return int32_t(i);
        return -1;
    }

    int32_t primary() {
        Interpreter::NestGuard guard(in_);
        const Token t = in_.tok();
        const int32_t at = tag();
        if (t.kind == Tk::Number) {
            in_.next();
            return e_.constant(t.number, at);
        }
        if (t.kind == Tk::Symbol && t.sym == '(') {
            in_.next();
            const int32_t v = cond();
            in_.expectSym(')', "to close '('");
            return v;
        }
        if (t.kind != Tk::Name) in_.errorHere("expected a number, a parameter or a function in the function body, found " + in_.describe());
        // Sum/prod variables, then parameters, hide everything else.
        for (size_t i = locals_.size(); i-- > 0;)
            if (locals_[i].first == t.id) {
                in_.next();
                return e_.local(locals_[i].second, at);
            }
        if (const int32_t p = param(t.id); p >= 0) {
            in_.next();
            return e_.param(p, at);
        }
        if (Names::isKeyword(t.id)) return keyword(Kw(t.id), at);
        return identifier(t, at);
    }

    double builtinIdentifier(Kw k) const {
        const AnimationClock& a = in_.options().animation;
        switch (k) {
            case Kw::clock: return a.clock;
            case Kw::clock_delta: return a.clockDelta;
            case Kw::clock_on: return a.clockOn ? 1 : 0;
            case Kw::initial_clock: return a.initialClock;
            case Kw::final_clock: return a.finalClock;
            case Kw::initial_frame: return a.initialFrame;
            case Kw::final_frame: return a.finalFrame;
            case Kw::frame_number: return a.frameNumber;
            case Kw::image_width: return in_.options().imageWidth;
            case Kw::image_height: return in_.options().imageHeight;
            default: return in_.version();
        }
    }

    int32_t keyword(Kw k, int32_t at) {
        const std::string name(keywordName(k));
        auto unary = [&](fn::Op op) {
            in_.next();
            const std::vector<int32_t> a = args(name.c_str());
            if (a.size() != 1) in_.error(locs_[size_t(at)], name + " takes one argument");
            return e_.add(op, {a[0]}, 0, at);
        };
        auto binary = [&](fn::Op op) {
            in_.next();
            const std::vector<int32_t> a = args(name.c_str());
            if (a.size() != 2) in_.error(locs_[size_t(at)], name + " takes two arguments");
            return e_.add(op, {a[0], a[1]}, 0, at);
        };
        switch (k) {
            case Kw::abs: return unary(fn::Op::Abs);
            case Kw::acos: return unary(fn::Op::Acos);
            case Kw::acosh: return unary(fn::Op::Acosh);
            case Kw::asin: return unary(fn::Op::Asin);
            case Kw::asinh: return unary(fn::Op::Asinh);
            case Kw::atan: return unary(fn::Op::Atan);
            case Kw::atanh: return unary(fn::Op::Atanh);
            case Kw::ceil: return unary(fn::Op::Ceil);
            case Kw::cos: return unary(fn::Op::Cos);
            case Kw::cosh: return unary(fn::Op::Cosh);
            case Kw::degrees: return unary(fn::Op::Degrees);
            case Kw::exp: return unary(fn::Op::Exp);
            case Kw::floor: return unary(fn::Op::Floor);
            case Kw::int_: return unary(fn::Op::Int);
            case Kw::ln: return unary(fn::Op::Ln);
            case Kw::log: return unary(fn::Op::Log);
            case Kw::radians: return unary(fn::Op::Radians);
            case Kw::sin: return unary(fn::Op::Sin);
            case Kw::sinh: return unary(fn::Op::Sinh);
            case Kw::sqrt: return unary(fn::Op::Sqrt);
            case Kw::tan: return unary(fn::Op::Tan);
            case Kw::tanh: return unary(fn::Op::Tanh);
            case Kw::atan2: return binary(fn::Op::Atan2);
            case Kw::mod: return binary(fn::Op::Mod);
            case Kw::pow: return binary(fn::Op::Pow);
            case Kw::div: return binary(fn::Op::IntDiv);
            case Kw::max: case Kw::min: {
                in_.next();
                const std::vector<int32_t> a = args(name.c_str());
                if (a.size() < 2) in_.error(locs_[size_t(at)], name + " takes two or more arguments");
                return e_.add(k == Kw::max ? fn::Op::Max : fn::Op::Min, std::span<const int32_t>(a), 0, at);
            }
            case Kw::select: {
                in_.next();
                const std::vector<int32_t> a = args("select");
                if (a.size() != 3 && a.size() != 4) in_.error(locs_[size_t(at)], "select takes three or four arguments");
                return e_.add(fn::Op::Select, std::span<const int32_t>(a), 0, at);
            }
            case Kw::sum: case Kw::prod: return sequence(k, at);
            case Kw::pi: in_.next(); return e_.constant(3.1415926535897932384626, at);
            case Kw::true_: case Kw::yes: case Kw::on: in_.next(); return e_.constant(1, at);
            case Kw::false_: case Kw::no: case Kw::off: in_.next(); return e_.constant(0, at);
            case Kw::clock: case Kw::clock_delta: case Kw::clock_on: case Kw::initial_clock: case Kw::final_clock:
            case Kw::initial_frame: case Kw::final_frame: case Kw::frame_number: case Kw::image_width:
            case Kw::image_height: case Kw::version: {
                in_.next();
                return e_.constant(builtinIdentifier(k), at);
            }
            case Kw::internal: {
                in_.next();
                in_.expectSym('(', "after internal");
                const int n = in_.parseInt("the internal function number");
                in_.expectSym(')', "to close internal(...)");
                const fn::InternalFunction* f = fn::internalFunction(n);
                if (!f) in_.error(locs_[size_t(at)], "there is no internal function " + std::to_string(n));
                std::vector<int32_t> a;
                for (int i = 0; i < f->params; ++i) a.push_back(i < int(f_.params.size()) ? e_.param(i, at) : e_.constant(0, at));
                return e_.internal(n, a, at);
            }
            case Kw::x: case Kw::y: case Kw::z: case Kw::u: case Kw::v: {
                // Not a parameter of this function (param() found none): POV-Ray 3.7 reads it as
                // 0 (measured: function(a, b) { x + 10*y + 100*z } gives 0 for (2, 3), and
                // function(u, v) { x + 10*y + 100*z } 32; meshmaker.inc's templates use z so).
                in_.next();
                return e_.constant(0, at);
            }
            default:
                in_.errorHere("'" + name + "' cannot be used in a function body");
        }
    }

    // sum(i, from, to, body) and prod(...).
    int32_t sequence(Kw k, int32_t at) {
        const char* name = k == Kw::sum ? "sum" : "prod";
        in_.next();
        in_.expectSym('(', "after ", name);
        const Token& v = in_.tokNoMacro();
        if (v.kind != Tk::Name) in_.errorHere(std::string("expected the iteration variable of ") + name + ", found " + in_.describe());
        const uint32_t var = v.id;
        in_.next();
        in_.expectSym(',', "after the variable of ", name);
        const int32_t from = cond();
        in_.expectSym(',', "in ", name);
        // The variable is seen from `to` on (holding `from` there), as in POV-Ray 3.7:
        // sum(i, 1, 3, sum(i, 1, i, i)) is 3.
        const int32_t slot = int32_t(locals_.size());
        if (slot >= fn::kMaxLocals)
            in_.error(locs_[size_t(at)], "sum and prod nested deeper than " + std::to_string(fn::kMaxLocals) + " levels");
        locals_.emplace_back(var, slot);
        const int32_t to = cond();
        in_.expectSym(',', "in ", name);
        const int32_t body = cond();
        locals_.pop_back();
        in_.expectSym(')', "to close ", name);
        return e_.sequence(k == Kw::sum ? fn::Op::Sum : fn::Op::Prod, slot, from, to, body, at);
    }

    int32_t identifier(const Token& t, int32_t at) {
        Binding* b = in_.identBinding();
        const std::string name(in_.spelling(t.id));
        if (!b) in_.errorHere("undeclared identifier '" + name + "' in a function body");
        const Value v = b->value;
        if (v.type == VType::Float) {
            in_.next();
            return e_.constant(v.c[0], at);
        }
        if (v.type == VType::Function) {
            in_.next();
            const FunctionValue& callee = v.fn();
            if (callee.table.get() != f_.table.get()) in_.errorHere("function '" + name + "' belongs to another parse");
            const std::vector<int32_t> a = args(name.c_str());
            fn::Member member = fn::Member::None;
            if (in_.isSym('.')) {
                in_.next();
                const Token& m = in_.tok();
                const std::optional<fn::Member> mm =
                    m.kind == Tk::Name ? fn::memberFromName(in_.spelling(m.id)) : std::nullopt;
                if (!mm) in_.errorHere("expected x, y, z, t, u, v, red, green, blue, filter, transmit, gray or hf after '.'");
                member = *mm;
                in_.next();
            }
            return e_.call(callee.index, a, member, at);
        }
        if (v.isNumeric() || v.type == VType::Array) {
            // An array element, or a vector or colour component: a constant operand of the body
            // (the rest of the expression is the body's: `A[1] * x`).
            return e_.constant(in_.parseIdentifierOperand("a value in a function body"), at);
        }
        in_.errorHere(std::string("a ") + typeName(v.type) + " identifier ('" + name + "') cannot be used in a function body");
    }

    Interpreter& in_;
    const FunctionValue& f_;
    fn::Expr e_;
    std::vector<Loc> locs_;
    std::vector<std::pair<uint32_t, int32_t>> locals_;
};

}  // namespace

Value Interpreter::parseFunction() {
    const Loc at = loc();
    next();  // function
    std::vector<uint32_t> params;
    if (isSym('(')) {
        next();
        for (;;) {
            const Token& t = tokNoMacro();
            if (t.kind != Tk::Name) errorHere("expected a parameter name, found " + describe());
            for (uint32_t p : params)
                if (p == t.id) errorHere("function parameter '" + std::string(names_.name(t.id)) + "' is named twice");
            params.push_back(t.id);  // x y z u v are keywords and allowed here
            next();
            if (acceptSym(',')) continue;
            break;
        }
        expectSym(')', "after the function's parameters");
        if (params.size() > size_t(fn::kMaxParams))
            error(at, "a function takes at most " + std::to_string(fn::kMaxParams) + " parameters");
    } else {
        params = {uint32_t(Kw::x), uint32_t(Kw::y), uint32_t(Kw::z)};
    }
    return parseFunctionBody(std::move(params), at);
}

Value Interpreter::parseFunctionBody(std::vector<uint32_t> params, const Loc& at) {
    auto fv = std::make_shared<FunctionValue>();
    fv->loc = at;
    fv->params = std::move(params);
    fv->table = functions_;
    expectSym('{', "to start the function body");
    const Kw k = kw();
    fn::HostFunction host;
    if (k == Kw::pattern || k == Kw::pigment) {
        fv->kind = k == Kw::pattern ? FunctionValue::Kind::Pattern : FunctionValue::Kind::Pigment;
        fv->item = host_.readItem(*this);
        // The host compiles the pattern (its value) or the pigment (its colour) once; the same
        // host function runs while parsing and in the render.
        host = host_.patternFunction(*fv->item, k == Kw::pigment);
        if (!host.fn) host = fn::HostFunction{evalZero, nullptr, 3, k == Kw::pattern ? 1 : 5};
    } else if (k == Kw::transform) {
        fv->kind = FunctionValue::Kind::Transform;
        fv->item = host_.readItem(*this);
        auto data = std::make_shared<TransformData>();
        const std::array<double, 12> m = host_.transformMatrix(*fv->item);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) data->m[r][c] = m[size_t(r * 4 + c)];
        host = fn::HostFunction{evalTransform, data.get(), 3, 3, data};
    } else if (k == Kw::spline) {
        fv->kind = FunctionValue::Kind::Spline;
        fv->spline = parseSplineBlock();
        host = fn::HostFunction{evalSpline, &fv->spline.spline(), 1, fv->spline.spline().dim, fv->spline.ref};
    } else {
        if (k == Kw::internal) {
            // `function { internal(N) }` (functions.inc) takes the internal function's own parameters.
            const Token* t = peekRaw();
            if (t[1].kind == Tk::Symbol && t[1].sym == '(' && t[2].kind == Tk::Number && t[3].kind == Tk::Symbol &&
                t[3].sym == ')' && t[4].kind == Tk::Symbol && t[4].sym == '}')
                if (const fn::InternalFunction* f = fn::internalFunction(povInt(t[2].number))) {
                    // x, y, z, then unnamed parameters (only internal(N) reads them).
                    fv->params.resize(3);
                    for (int i = 3; i < f->params; ++i) fv->params.push_back(UINT32_MAX - uint32_t(i));
                }
        }
        BodyReader reader(*this, *fv);
        const fn::Expr body = reader.read();
        if (!isSym('}')) errorHere("expected '}' to end the function body, found " + describe());
        next();
        try {
            fv->index = functions_->addFloat(body, int(fv->params.size()));
        } catch (const fn::CompileError& e) {
            const Loc where = e.loc() >= 0 && size_t(e.loc()) < reader.locs().size() ? reader.locs()[size_t(e.loc())] : at;
            error(where, e.what());
        }
        return Value::function(std::move(fv));
    }
    expectSym('}', "to close the function");
    fv->index = functions_->addHost(host);
    return Value::function(std::move(fv));
}

Value Interpreter::callFunction(const Value& fnValue, const Loc& at) {
    const FunctionValue& fv = fnValue.fn();
    const Args a = callArgs("a function call", 0, fn::kMaxParams);
    const int want = fv.table->params(fv.index);
    if (int(a.size()) != want)
        error(at, "the function takes " + std::to_string(want) + " arguments, " + std::to_string(a.size()) + " given");
    std::vector<double> args;
    for (size_t i = 0; i < a.size(); ++i) args.push_back(toFloat(a[i], at, "a function argument"));
    if ((fv.kind == FunctionValue::Kind::Pattern || fv.kind == FunctionValue::Kind::Pigment) &&
        isPatternStub(fv.table->program(fv.index).hosts[0]))
        warning(at, "not rendered yet: pattern and pigment functions called while parsing (they give 0)");
    fn::Scratch scratch(fv.table->program(fv.index));
    // sum/prod repetitions and calls of other functions count against the parse's loop limit, as
    // #while and #for iterations do.
    fn::LoopBudget budget(iterations_ < limits_.loopIterations ? limits_.loopIterations - iterations_ : 0);
    double out[5] = {};
    int n = 1;
    try {
        if (fv.table->outputs(fv.index) == 1) out[0] = fv.table->call(fv.index, args.data(), scratch);
        else n = fv.table->callVector(fv.index, args.data(), out, scratch);
    } catch (const fn::LoopBudgetExceeded&) {
        error(at, "loops ran more than " + std::to_string(limits_.loopIterations) +
                      " iterations (sum, prod or calls of other functions in a function called while parsing)");
    }
    iterations_ += budget.used();
    if (fv.table->outputs(fv.index) == 1) return Value::number(out[0]);
    if (fv.kind == FunctionValue::Kind::Pigment) return Value::color(out[0], out[1], out[2], out[3], out[4]);
    return Value::vector(n, out);
}

}  // namespace rays::sdl
