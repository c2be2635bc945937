#include "rays/sdl/value.h"

#include "rays/sdl/item.h"

namespace rays::sdl {

const char* typeName(VType t) {
    switch (t) {
        case VType::Undefined: return "undefined";
        case VType::Float: return "float";
        case VType::Vector: return "vector";
        case VType::Color: return "colour";
        case VType::String: return "string";
        case VType::Array: return "array";
        case VType::Item: return "scene item";
        case VType::Function: return "function";
        case VType::Spline: return "spline";
        case VType::Macro: return "macro";
        case VType::File: return "file handle";
    }
    return "?";
}

namespace {
Value withRef(VType t, std::shared_ptr<void> p) {
    Value v;
    v.type = t;
    v.ref = std::move(p);
    return v;
}
}  // namespace

Value Value::string(std::string s) { return withRef(VType::String, std::make_shared<std::string>(std::move(s))); }
Value Value::array(std::shared_ptr<ArrayData> a) { return withRef(VType::Array, std::move(a)); }
Value Value::item(std::shared_ptr<const Item> i) { return withRef(VType::Item, std::const_pointer_cast<Item>(i)); }
Value Value::function(std::shared_ptr<const FunctionValue> f) {
    return withRef(VType::Function, std::const_pointer_cast<FunctionValue>(f));
}
Value Value::spline(std::shared_ptr<const Spline> s) { return withRef(VType::Spline, std::const_pointer_cast<Spline>(s)); }
Value Value::macro(std::shared_ptr<const MacroDef> m) { return withRef(VType::Macro, std::const_pointer_cast<MacroDef>(m)); }
Value Value::file(std::shared_ptr<FileHandle> f) { return withRef(VType::File, std::move(f)); }

uint64_t arrayElementCount(const Value& v) {
    if (v.type != VType::Array) return 0;
    uint64_t n = v.arr().elems.size();
    for (const Value& e : v.arr().elems) n += arrayElementCount(e);
    return n;
}

Value copyValue(const Value& v) {
    if (v.type != VType::Array) return v;
    auto a = std::make_shared<ArrayData>(v.arr());
    for (Value& e : a->elems) e = copyValue(e);
    return Value::array(std::move(a));
}

}  // namespace rays::sdl
