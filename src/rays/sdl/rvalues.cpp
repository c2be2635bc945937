// Values that may follow `=` in #declare and #local (and macro arguments): numbers, strings,
// scene items, arrays with their initialisers, functions and splines.
#include <cmath>

#include "rays/sdl/frames.h"
#include "rays/sdl/function_value.h"
#include "rays/sdl/interpreter.h"

namespace rays::sdl {

bool Interpreter::peekRawSym(char c) {
    const Token* t = peekRaw();
    return t->kind == Tk::Symbol && t->sym == uint8_t(c);
}

Value Interpreter::parseRValue() {
    NestGuard guard(*this);
    const Token& t = tok();
    if (t.kind == Tk::String) return Value::string(parseString());
    if (t.kind == Tk::Name && Names::isKeyword(t.id)) {
        const Kw k = Kw(t.id);
        switch (k) {
            case Kw::array: return parseArray();
            case Kw::function: return parseFunction();
            case Kw::spline: return parseSplineBlock();
            case Kw::color: case Kw::colour: return parseColor();
            default: break;
        }
        if (host_.startsItem(k)) return Value::item(host_.readItem(*this));
        if (atStringStart()) return Value::string(parseString());
        if (atNumericStart()) return parseNumeric(k == Kw::rgb || k == Kw::rgbf || k == Kw::rgbt || k == Kw::rgbft ||
                                                  k == Kw::srgb || k == Kw::srgbf || k == Kw::srgbt || k == Kw::srgbft ||
                                                  k == Kw::red || k == Kw::green || k == Kw::blue ||
                                                  k == Kw::filter || k == Kw::transmit);
        errorHere("expected a value, found " + describe());
    }
    if (t.kind == Tk::Name) {
        Binding* b = scopes_.find(t.id);
        if (!b) errorHere("undeclared identifier '" + std::string(names_.name(t.id)) + "'");
        switch (b->value.type) {
            case VType::Float: case VType::Vector: return parseNumeric(false);
            case VType::Color: return parseNumeric(true);
            case VType::String: return Value::string(parseString());
            case VType::Array: {
                const Value arr = b->value;
                if (!peekRawSymAfterName('[')) {
                    next();
                    return arr;  // the whole array (copied when assigned)
                }
                const VType e = arr.arr().elemType;
                if (isNumericType(e)) return parseNumeric(e == VType::Color);
                if (e == VType::String) return Value::string(parseString());
                next();
                const Value el = arrayElement(arr, false, nullptr);
                if (!el.isNumeric()) return el;
                // A number of an array of arrays (G[0][1]) starts the expression that follows it,
                // as an identifier would: G[0][1] + 1.
                const bool color = el.type == VType::Color;
                const Num first = postfix(color ? colorComponents(Num::of(el)) : Num::of(el));
                Num v = binaryAfter(first, 3, false, color);
                if (color && v.type == VType::Color) v = colorComponents(v);
                return v.value();
            }
            case VType::Function: case VType::Spline: {
                if (peekRawSymAfterName('(')) return parseNumeric(false);
                Value v = b->value;
                next();
                return v;
            }
            default: {
                Value v = b->value;
                next();
                return v;
            }
        }
    }
    if (atNumericStart()) return parseNumeric(false);
    errorHere("expected a value, found " + describe());
}

// The raw token after the current (an identifier fetched from the current frame).
bool Interpreter::peekRawSymAfterName(char c) {
    return cursor_->kind == Tk::Symbol && cursor_->sym == uint8_t(c);
}

// `array[N1][N2]... [{ items }]` (POV-Ray 3.7 reference, "Array"): up to 5 dimensions.
Value Interpreter::parseArray() {
    const Loc at = loc();
    next();  // array
    auto data = std::make_shared<ArrayData>();
    size_t total = 1;
    do {
        if (data->sizes.size() == 5) error(at, "an array has at most 5 dimensions");
        expectSym('[', "after 'array'");
        const Loc nAt = loc();
        const double n = toFloat(fullExpression(), nAt, "an array size");
        if (!(n >= 1) || n > 1e8) error(nAt, "an array size must be from 1 to 100000000");
        data->sizes.push_back(int(n));
        if (!isSym(']')) errorHere("expected ']' after the array size, found " + describe());
        next();
        total *= size_t(n);
        if (total > (size_t(1) << 27)) error(at, "an array may hold at most 134217728 elements");
    } while (peekRawSym('['));
    spend(arrayElements_, total, limits_.arrayElements, at, "array elements and spline points made (new and copied)");
    data->elems.resize(total);
    if (peekRawSym('{')) {
        size_t flat = 0;
        arrayInitializer(*data, 0, flat);
    }
    return Value::array(std::move(data));
}

void Interpreter::spend(uint64_t& total, uint64_t n, uint64_t limit, const Loc& at, const char* what) {
    total += n;
    if (total > limit) error(at, "more than " + std::to_string(limit) + " " + what + " in this parse (runaway loop?)");
}

Value Interpreter::adoptArray(Value v, const Loc& at) {
    for (Value& e : v.arr().elems)
        if (e.type == VType::Array) e = e.ref.use_count() == 1 ? adoptArray(std::move(e), at) : copyCharged(e, at);
    return v;
}

Value Interpreter::copyCharged(const Value& v, const Loc& at) {
    if (v.type != VType::Array) return v;  // only arrays are copied deeply
    spend(arrayElements_, arrayElementCount(v), limits_.arrayElements, at, "array elements and spline points made (new and copied)");
    return copyValue(v);
}

void Interpreter::arrayInitializer(ArrayData& a, size_t dim, size_t& flat) {
    const Loc at = loc();
    expectSym('{', "to start an array initialiser");
    for (int i = 0; i < a.sizes[dim]; ++i) {
        if (dim + 1 < a.sizes.size()) {
            arrayInitializer(a, dim + 1, flat);
        } else {
            const Loc vAt = loc();
            Value v = parseRValue();
            if (a.elemType == VType::Undefined) a.elemType = v.type;
            else if (v.isNumeric() != isNumericType(a.elemType))
                error(vAt, std::string("array elements must all be of one type; this one is a ") + typeName(v.type));
            a.elems[flat++] = std::move(v);
        }
        acceptSym(',');  // commas between elements are optional, as in POV-Ray
        if (i + 1 < a.sizes[dim] && isSym('}'))
            errorHere("the array initialiser has fewer elements than the array size " + std::to_string(a.sizes[dim]));
    }
    if (!isSym('}'))
        error(at, "the array initialiser has more elements than the array size " + std::to_string(a.sizes[dim]));
    next();
}

}  // namespace rays::sdl
