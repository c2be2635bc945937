// String expressions: literals, identifiers, array elements and the string functions
// (POV-Ray 3.7 reference, "String Functions"). POV-Ray has no string operators; comparisons
// of strings are read in expressions.cpp.
#include <cmath>
#include <cstdio>

#include "rays/sdl/frames.h"
#include "rays/sdl/interpreter.h"
#include "rays/sdl/pov_int.h"
#include "rays/sdl/pov_datetime.h"
#include "rays/sdl/pov_strings.h"

namespace rays::sdl {

bool Interpreter::atStringStart() {
    const Token& t = tok();
    if (t.kind == Tk::String) return true;
    if (t.kind != Tk::Name) return false;
    if (!Names::isKeyword(t.id)) {
        const Binding* b = scopes_.find(t.id);
        if (!b) return false;
        return b->value.type == VType::String ||
               (b->value.type == VType::Array && b->value.arr().elemType == VType::String);
    }
    switch (Kw(t.id)) {
        case Kw::str: case Kw::concat: case Kw::chr: case Kw::substr: case Kw::strupr: case Kw::strlwr:
        case Kw::vstr: case Kw::datetime: case Kw::input_file_name:
            return true;
        default:
            return false;
    }
}

std::string Interpreter::parseString() {
    const Token t = tok();
    const Loc at{curFile_, cur_->line, cur_->col};
    if (t.kind == Tk::String) {
        std::string s = files_[at.file]->strings[t.id];
        next();
        return s;
    }
    if (t.kind == Tk::Name && !Names::isKeyword(t.id)) {
        Binding* b = scopes_.find(t.id);
        if (b && b->value.type == VType::String) {
            std::string s = b->value.str();
            next();
            return s;
        }
        if (b && b->value.type == VType::Array) {
            const Value arr = b->value;
            next();
            const Value e = arrayElement(arr, false, nullptr);
            if (e.type != VType::String) error(at, std::string("expected a string, found a ") + typeName(e.type) + " array element");
            return e.str();
        }
        error(at, "expected a string, found " + describe());
    }
    if (t.kind == Tk::Name) {
        const Kw k = Kw(t.id);
        switch (k) {
            case Kw::str: case Kw::concat: case Kw::chr: case Kw::substr: case Kw::strupr: case Kw::strlwr:
            case Kw::vstr: case Kw::datetime:
            {
                next();
                std::string s = stringFunction(k, at);
                spend(stringBytes_, s.size(), limits_.stringBytes, at, "bytes of strings made by string functions");
                return s;
            }
            case Kw::input_file_name:
                next();
                return files_.empty() ? std::string() : files_[0]->shownName;
            default:
                break;
        }
    }
    error(at, "expected a string, found " + describe());
}

// String values are held as bytes (UTF-8 where a scene writes non-ASCII text); the functions
// below follow POV-Ray's 16-bit string rules (pov_strings.h) and convert at this boundary.
std::string Interpreter::stringFunction(Kw k, const Loc& at) {
    NestGuard guard(*this);  // concat(concat(concat(...)))
    const std::string name(keywordName(k));
    auto check = [&](Outcome<PovString> r) {
        if (!r.ok()) error(at, r.error);
        return povNarrow(r.value);
    };
    expectSym('(', "after ", name);
    auto comma = [&] { expectSym(',', "between the arguments of ", name); };
    auto close = [&] { expectSym(')', "to close ", name); };
    switch (k) {
        case Kw::str: {
            const double v = parseFloat();
            comma();
            const double l = parseFloat();
            comma();
            const double p = parseFloat();
            close();
            return povStr(v, povInt(l), povInt(p));
        }
        case Kw::vstr: {
            const double n = parseFloat();
            comma();
            const Loc vAt = loc();
            const Value v = parseNumeric(false);
            if (!v.isNumeric()) error(vAt, "vstr needs a vector");
            comma();
            const PovString sep = povString(parseString());
            comma();
            const double l = parseFloat();
            comma();
            const double p = parseFloat();
            close();
            const size_t dim = v.type == VType::Float ? 1 : v.dim;
            return check(povVstr(povInt(n), std::span<const double>(v.c.data(), dim), sep, povInt(l), povInt(p)));
        }
        case Kw::concat: {
            std::string s = parseString();
            while (acceptSym(',')) {  // checked as it grows: concat(S, S, S, ...) of long strings
                s += parseString();
                if (s.size() > (size_t(1) << 24)) error(at, "concat made a string longer than 16 MiB");
            }
            close();
            return s;
        }
        case Kw::chr: {
            const double c = parseFloat();
            close();
            return check(povChr(povInt(c)));
        }
        case Kw::substr: {
            const PovString s = povString(parseString());
            comma();
            const double p = parseFloat();
            comma();
            const double l = parseFloat();
            close();
            return check(povSubstr(s, povInt(p), povInt(l)));
        }
        case Kw::strupr: case Kw::strlwr: {
            const PovString s = povString(parseString());
            close();
            return povNarrow(k == Kw::strupr ? povStrupr(s) : povStrlwr(s));
        }
        case Kw::datetime: {
            const double days = parseFloat();
            PovString fmt = povString(kDatetimeDefaultFormat);
            if (acceptSym(',')) fmt = povString(parseString());
            close();
            return check(povDatetime(days, fmt));
        }
        default:
            break;
    }
    error(at, name + " is not a string function");
}

}  // namespace rays::sdl
