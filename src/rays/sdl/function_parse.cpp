// `function { ... }` values. Float bodies are remembered by their tokens for the function
// machine; `function { pattern {...} }`, `function { pigment {...} }`, `function { transform
// {...} }` and `function { spline {...} }` wrap what they contain.
#include "rays/sdl/frames.h"
#include "rays/sdl/function_value.h"
#include "rays/sdl/interpreter.h"

namespace rays::sdl {

Value Interpreter::parseFunction() {
    const Loc at = loc();
    next();  // function
    std::vector<uint32_t> params;
    if (isSym('(')) {
        next();
        for (;;) {
            const Token& t = tokNoMacro();
            if (t.kind != Tk::Name) errorHere("expected a parameter name, found " + describe());
            params.push_back(t.id);  // x y z u v are keywords and allowed here
            next();
            if (acceptSym(',')) continue;
            break;
        }
        expectSym(')', "after the function's parameters");
    } else {
        params = {uint32_t(Kw::x), uint32_t(Kw::y), uint32_t(Kw::z)};
    }
    return parseFunctionBody(std::move(params), at);
}

Value Interpreter::parseFunctionBody(std::vector<uint32_t> params, const Loc& at) {
    auto fv = std::make_shared<FunctionValue>();
    fv->loc = at;
    fv->params = std::move(params);
    expectSym('{', "to start the function body");
    const Kw k = kw();
    if (k == Kw::pattern || k == Kw::pigment || k == Kw::transform) {
        fv->kind = k == Kw::pattern ? FunctionValue::Kind::Pattern
                   : k == Kw::pigment ? FunctionValue::Kind::Pigment
                                      : FunctionValue::Kind::Transform;
        fv->item = host_.readItem(*this);
        expectSym('}', "to close the function");
        return Value::function(std::move(fv));
    }
    if (k == Kw::spline) {
        fv->kind = FunctionValue::Kind::Spline;
        fv->spline = parseSplineBlock();
        expectSym('}', "to close the function");
        return Value::function(std::move(fv));
    }
    // A float function: its body is kept as tokens of this file (the '{' is consumed and the
    // first body token may be fetched: it is in the same frame).
    Frame& f = frames_.back();
    fv->file = f.file->id;
    fv->bodyStart = have_ ? f.pos - 1 : f.pos;
    have_ = false;
    f.pos = fv->bodyStart;
    int depth = 0;
    for (;;) {
        const Token& t = f.file->tokens[f.pos];
        if (t.kind == Tk::End) error(fv->loc, "the function body is never closed by '}'");
        if (t.kind == Tk::Symbol && t.sym == '{') ++depth;
        if (t.kind == Tk::Symbol && t.sym == '}') {
            if (depth == 0) break;
            --depth;
        }
        ++f.pos;
    }
    fv->bodyEnd = f.pos;
    ++f.pos;  // '}'
    return Value::function(std::move(fv));
}

Value Interpreter::callFunction(const Value& fnValue, const Loc& at) {
    const FunctionValue& fv = fnValue.fn();
    (void)fv;
    error(at, "calling user functions while parsing is not available yet");
}

}  // namespace rays::sdl
