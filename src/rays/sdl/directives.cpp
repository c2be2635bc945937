// The directives: conditionals and loops (control blocks kept per frame), declarations, macros
// defined, include files, #version, #default and the message streams. File I/O is in file_io.cpp.
#include <cmath>
#include <filesystem>

#include "rays/error.h"
#include "rays/sdl/frames.h"
#include "rays/sdl/interpreter.h"

namespace rays::sdl {

namespace {
constexpr double kEpsilon = 1e-10;  // POV-Ray's: smaller magnitudes are false, closer values equal
bool opensBlock(uint32_t id) {
    switch (Kw(id)) {
        case Kw::if_: case Kw::ifdef: case Kw::ifndef: case Kw::while_: case Kw::for_: case Kw::switch_:
        case Kw::macro:
            return true;
        default:
            return false;
    }
}
}  // namespace

void Interpreter::directive(const Token& t) {
    const Loc at{topFile_, t.line, t.col};
    if (!Names::isKeyword(t.id)) error(at, "unknown directive '#" + std::string(names_.name(t.id)) + "'");
    switch (Kw(t.id)) {
        case Kw::include: return dirInclude(at);
        case Kw::declare: return dirDeclare(at, false);
        case Kw::local: return dirDeclare(at, true);
        case Kw::undef: return dirUndef();
        case Kw::if_: return dirIf(at);
        case Kw::ifdef: return dirIfdef(at, true);
        case Kw::ifndef: return dirIfdef(at, false);
        case Kw::else_: return dirElse(at, false);
        case Kw::elseif: return dirElse(at, true);
        case Kw::end: return dirEnd(at);
        case Kw::switch_: return dirSwitch(at);
        case Kw::case_: return dirCase(at, false);
        case Kw::range: return dirCase(at, true);
        case Kw::break_: return dirBreak(at);
        case Kw::while_: return dirWhile(at, topPos() - 1);  // the loop returns to its #while
        case Kw::for_: return dirFor(at);
        case Kw::macro: return dirMacro(at);
        case Kw::version: return dirVersion();
        case Kw::default_: return dirDefault();
        case Kw::debug: case Kw::warning: case Kw::error: case Kw::render: case Kw::statistics:
            return dirMessage(at, Kw(t.id));
        case Kw::fopen: return dirFopen(at);
        case Kw::fclose: return dirFclose();
        case Kw::read: return dirRead(at);
        case Kw::write: return dirWrite(at);
        case Kw::max_trace_level: case Kw::max_intersections:
            warning(at, "#" + std::string(names_.name(t.id)) + " as a directive is obsolete; put it in global_settings (ignored)");
            parseFloat();
            return;
        default:
            error(at, "unknown directive '#" + std::string(names_.name(t.id)) + "'");
    }
}

// ---- conditions ----------------------------------------------------------------------------------

// `( FULL_EXPRESSION )`: nothing after the ')' is looked at, so the directive's body is not read
// before the condition is known.
bool Interpreter::condition(const char* directiveName) {
    expectSym('(', "after #", directiveName);
    const Loc at = loc();
    const Value v = fullExpression();
    if (!isSym(')')) errorHere(std::string("expected ')' after the condition of #") + directiveName + ", found " + describe());
    next();
    return truth(v, at);
}

bool Interpreter::truth(const Num& v, const Loc& at) {
    if (v.type != VType::Float) error(at, std::string("a condition must be a float, found a ") + typeName(v.type));
    return std::fabs(v.c[0]) > kEpsilon;
}

Interpreter::SkipStop Interpreter::skip(bool stopAtElse, bool stopAtCase, const Loc& opener, const char* openerName) {
    int depth = 0;
    for (;;) {
        const Token& t = *cursor_;
        if (t.kind == Tk::End)
            error(opener, std::string("#") + openerName + " is never closed by #end (end of file reached)");
        ++cursor_;
        if (t.kind != Tk::Directive || !Names::isKeyword(t.id)) continue;
        if (opensBlock(t.id)) {
            ++depth;
        } else if (Kw(t.id) == Kw::end) {
            if (depth == 0) return SkipStop::End;
            --depth;
        } else if (depth == 0 && stopAtElse && Kw(t.id) == Kw::else_) {
            return SkipStop::Else;
        } else if (depth == 0 && stopAtElse && !stopAtCase && Kw(t.id) == Kw::elseif) {
            return SkipStop::Elseif;
        } else if (depth == 0 && stopAtCase && Kw(t.id) == Kw::case_) {
            return SkipStop::Case;
        } else if (depth == 0 && stopAtCase && Kw(t.id) == Kw::range) {
            return SkipStop::Range;
        }
    }
}

void Interpreter::skipPastEnds(int count, const Loc& opener) {
    int depth = 0;
    while (count > 0) {
        const Token& t = *cursor_;
        if (t.kind == Tk::End) error(opener, "this block is never closed by #end (end of file reached)");
        ++cursor_;
        if (t.kind != Tk::Directive || !Names::isKeyword(t.id)) continue;
        if (opensBlock(t.id)) {
            ++depth;
        } else if (Kw(t.id) == Kw::end) {
            if (depth > 0) --depth;
            else --count;
        }
    }
}

void Interpreter::dirIf(const Loc& at) { ifBranches(condition("if"), at, "if"); }

void Interpreter::ifBranches(bool taken, const Loc& at, const char* name) {
    while (!taken) {
        const SkipStop s = skip(true, false, at, name);
        if (s == SkipStop::End) return;
        taken = s == SkipStop::Else || condition("elseif");
    }
    frames_.back().ctl.push_back(Ctl{Ctl::If, at});
}

bool Interpreter::definedTest() {
    expectSym('(', "after #ifdef / #ifndef");
    const bool defined = definedName();
    if (!isSym(')')) errorHere("expected ')' after the identifier, found " + describe());
    next();
    return defined;
}

void Interpreter::dirIfdef(const Loc& at, bool wantDefined) {
    ifBranches(definedTest() == wantDefined, at, wantDefined ? "ifdef" : "ifndef");
}

// Met while running a branch: the rest of the #if is skipped. In a #switch, a running clause
// falls through #else.
void Interpreter::dirElse(const Loc& at, bool isElseif) {
    auto& ctl = frames_.back().ctl;
    if (!isElseif && !ctl.empty() && ctl.back().kind == Ctl::Switch) return;
    if (ctl.empty() || ctl.back().kind != Ctl::If)
        error(at, std::string(isElseif ? "#elseif" : "#else") + " without a matching #if");
    const Loc opener = ctl.back().loc;
    skip(false, false, opener, "if");
    ctl.pop_back();
}

void Interpreter::dirEnd(const Loc& at) {
    Frame& f = frames_.back();
    if (f.ctl.empty()) {
        if (f.kind == Frame::Macro) return returnFromMacro();
        error(at, "#end without a matching #if, #while, #for, #switch or #macro");
    }
    Ctl& c = f.ctl.back();
    switch (c.kind) {
        case Ctl::If:
        case Ctl::Switch:
            f.ctl.pop_back();
            return;
        case Ctl::While:
            if (++iterations_ > limits_.loopIterations)
                error(c.loc, "loops ran more than " + std::to_string(limits_.loopIterations) + " iterations (runaway #while?)");
            jumpTo(c.pos);  // the #while runs again and tests its condition
            markReplayed(topFile_);
            f.ctl.pop_back();
            return;
        case Ctl::For: {
            if (++iterations_ > limits_.loopIterations)
                error(c.loc, "loops ran more than " + std::to_string(limits_.loopIterations) + " iterations (runaway #for?)");
            Binding* b = scopes_.find(c.var);
            if (!b || b->value.type != VType::Float)
                error(c.loc, "the #for counter '" + std::string(names_.name(c.var)) + "' is no longer a float");
            const double v = b->value.c[0] + c.step;
            scopes_.local(c.var, Value::number(v));
            if (c.step > 0 ? v <= c.end : v >= c.end) {
                jumpTo(c.pos);
                markReplayed(topFile_);
            } else {
                f.ctl.pop_back();
            }
            return;
        }
    }
}

// ---- switch --------------------------------------------------------------------------------------

void Interpreter::dirSwitch(const Loc& at) {
    expectSym('(', "after #switch");
    const Loc vAt = loc();
    const Value v = fullExpression();
    if (v.type != VType::Float) error(vAt, "#switch needs a float");
    if (!isSym(')')) errorHere("expected ')' after the #switch value, found " + describe());
    next();
    Ctl c{Ctl::Switch, at};
    c.value = v.c[0];
    frames_.back().ctl.push_back(c);
    switchClauses(skip(true, true, at, "switch"), at);
}

// Skipping from a false clause, each #case or #range met is tested; the first true one runs.
// Once a clause runs, POV-Ray 3.7 falls through every later #case, #range and #else until
// #break or #end without testing them (measured with POV-Ray 3.7.0.10; its reference says the
// later conditions are tested).
void Interpreter::switchClauses(SkipStop s, const Loc& opener) {
    for (;;) {
        if (s == SkipStop::End) return frames_.back().ctl.pop_back();
        if (s == SkipStop::Else) return;
        if (caseMatches(s == SkipStop::Range)) return;
        s = skip(true, true, opener, "switch");
    }
}

bool Interpreter::caseMatches(bool isRange) {
    const double value = frames_.back().ctl.back().value;
    expectSym('(', isRange ? "after #range" : "after #case");
    bool match;
    if (isRange) {
        const double lo = toFloat(fullExpression(), loc(), "#range");
        expectSym(',', "between the bounds of #range");
        const double hi = toFloat(fullExpression(), loc(), "#range");
        match = lo <= value && value <= hi;
    } else {
        match = std::fabs(toFloat(fullExpression(), loc(), "#case") - value) < kEpsilon;
    }
    if (!isSym(')')) errorHere("expected ')' after the #case / #range value, found " + describe());
    next();
    return match;
}

// Met while a clause runs: fall through (its value is read and not tested).
void Interpreter::dirCase(const Loc& at, bool isRange) {
    auto& ctl = frames_.back().ctl;
    if (ctl.empty() || ctl.back().kind != Ctl::Switch) error(at, std::string(isRange ? "#range" : "#case") + " outside #switch");
    caseMatches(isRange);
}

void Interpreter::dirBreak(const Loc& at) {
    Frame& f = frames_.back();
    for (size_t i = f.ctl.size(); i-- > 0;) {
        if (f.ctl[i].kind == Ctl::If) continue;
        skipPastEnds(int(f.ctl.size() - i), f.ctl[i].loc);
        f.ctl.resize(i);
        return;
    }
    if (f.kind == Frame::Macro) {
        f.ctl.clear();
        return returnFromMacro();
    }
    error(at, "#break outside #switch, #while, #for or #macro");
}

// ---- loops ---------------------------------------------------------------------------------------

void Interpreter::dirWhile(const Loc& at, uint32_t directivePos) {
    if (condition("while")) {
        Ctl c{Ctl::While, at};
        c.pos = directivePos;
        frames_.back().ctl.push_back(c);
        return;
    }
    skip(false, false, at, "while");
}

void Interpreter::dirFor(const Loc& at) {
    expectSym('(', "after #for");
    const uint32_t var = readNewName("#for counter");
    expectSym(',', "after the #for counter");
    const double start = toFloat(fullExpression(), loc(), "#for start");
    expectSym(',', "after the #for start value");
    const double end = toFloat(fullExpression(), loc(), "#for end");
    double step = 1;
    if (acceptSym(',')) step = toFloat(fullExpression(), loc(), "#for step");
    if (!isSym(')')) errorHere("expected ')' to close #for, found " + describe());
    next();
    if (step == 0) error(at, "#for step must not be 0");
    scopes_.local(var, Value::number(start));
    if (step > 0 ? start <= end : start >= end) {
        Ctl c{Ctl::For, at};
        c.pos = topPos();
        c.var = var;
        c.end = end;
        c.step = step;
        frames_.back().ctl.push_back(c);
        return;
    }
    skip(false, false, at, "for");
}

// ---- names and declarations ----------------------------------------------------------------------

uint32_t Interpreter::readNewName(const char* what) {
    const Token& t = tokNoMacro();
    if (t.kind != Tk::Name) errorHere(std::string("expected an identifier for the ") + what + ", found " + describe());
    if (Names::isKeyword(t.id))
        errorHere("'" + std::string(names_.name(t.id)) + "' is a reserved word and cannot be used as the " + what);
    const uint32_t id = t.id;
    next();
    return id;
}

void Interpreter::dirUndef() {
    tokNoMacro();  // the name, not expanded: `#undef M` of a macro M (ior.inc does so)
    const Loc at{curFile_, cur_->line, cur_->col};
    const uint32_t name = readNewName("#undef");
    if (!scopes_.undef(name)) warning(at, "#undef of '" + std::string(names_.name(name)) + "', which is not defined");
}

void Interpreter::dirDeclare(const Loc&, bool isLocal) {
    const uint32_t level = scopes_.level();  // the value may end inside a macro called here
    bool deprecated = false, once = false;
    uint32_t message = UINT32_MAX;
    if (tokNoMacro().kind == Tk::Name && cur_->id == uint32_t(Kw::deprecated)) {
        next();
        deprecated = true;
        if (tokNoMacro().kind == Tk::Name && cur_->id == uint32_t(Kw::once)) {
            next();
            once = true;
        }
        if (tokNoMacro().kind == Tk::String) {
            message = uint32_t(deprecatedMessages_.size());
            deprecatedMessages_.push_back(parseString());
        }
    }
    const Loc nameAt = loc();
    const uint32_t name = readNewName(isLocal ? "#local" : "#declare");
    std::vector<size_t> path;  // the element's flat index in each (nested) array
    if (isSym('[')) {
        Binding* b = scopes_.find(name);
        if (!b || b->value.type != VType::Array)
            error(nameAt, "'" + std::string(names_.name(name)) + "' is not an array");
        arrayElement(b->value, true, &path);
    }
    expectSym('=', "after the identifier in #", isLocal ? "local" : "declare");
    const Loc valueAt = loc();
    const bool numeric = atNumericStart();
    Value v = parseRValue();
    const bool wasNumeric = numeric || v.isNumeric();
    Binding& bound = assignTarget(name, isLocal, path, std::move(v), nameAt, level);
    if (deprecated) {
        bound.deprecated = true;
        bound.deprecatedOnce = once;
        bound.deprecatedMessage = message;
    }
    if (wasNumeric && have_) {
        if (isSym(';')) {
            next();
        } else if (version_ >= 3.5) {
            error(valueAt, "the declaration of '" + std::string(names_.name(name)) +
                               "' must end with ';' (float, vector and colour declarations need one since POV-Ray 3.5)");
        }
        return;
    }
    // Other declarations may end with ';': taken when it is the very next token of this file.
    if (!have_) {
        if (cursor_->kind == Tk::Symbol && cursor_->sym == ';') ++cursor_;
    } else if (isSym(';')) {
        next();
    }
}

Binding& Interpreter::assignTarget(uint32_t name, bool isLocal, const std::vector<size_t>& path, Value v, const Loc& at,
                                   uint32_t level) {
    // Arrays are copied on assignment; one that nothing else holds (a literal just made, a macro's
    // result) is taken as it is.
    if (v.type == VType::Array) v = v.ref.use_count() == 1 ? adoptArray(std::move(v), at) : copyCharged(v, at);
    if (path.empty()) return isLocal ? scopes_.localAt(name, std::move(v), level) : scopes_.declareAt(name, std::move(v), level);
    // The element is found again from the name: reading the value may have changed the array.
    Binding* b = scopes_.find(name);
    Value* slot = b ? &b->value : nullptr;
    ArrayData* a = nullptr;
    for (const size_t flat : path) {
        if (!slot || slot->type != VType::Array || flat >= slot->arr().elems.size())
            error(at, "array '" + std::string(names_.name(name)) + "' changed while its element was being assigned");
        a = &slot->arr();
        slot = &a->elems[flat];
    }
    const bool numericKind = v.isNumeric();
    if (a->elemType != VType::Undefined) {
        const bool wasNumeric = isNumericType(a->elemType);
        if (numericKind != wasNumeric || (!numericKind && a->elemType != v.type))
            error(at, std::string("array '") + std::string(names_.name(name)) + "' holds " + typeName(a->elemType) +
                          " elements; a " + typeName(v.type) + " cannot be stored in it");
    } else {
        a->elemType = v.type;
    }
    *slot = std::move(v);
    return *b;
}

// ---- macros defined ------------------------------------------------------------------------------

void Interpreter::dirMacro(const Loc& at) {
    auto def = std::make_shared<MacroDef>();
    def->name = readNewName("macro name");
    def->loc = at;
    expectSym('(', "after the macro name");
    if (tokNoMacro().kind != Tk::Symbol || cur_->sym != ')') {
        for (;;) {
            bool optional = false;
            if (tokNoMacro().kind == Tk::Name && cur_->id == uint32_t(Kw::optional)) {
                next();
                optional = true;
            }
            const uint32_t p = readNewName("macro parameter");
            for (uint32_t q : def->params)
                if (q == p) error(at, "macro parameter '" + std::string(names_.name(p)) + "' is named twice");
            def->params.push_back(p);
            def->optional.push_back(optional);
            if (tokNoMacro().kind == Tk::Symbol && cur_->sym == ',') {
                next();
                // POV-Ray 3.7 takes a comma before the ')' (shapes3.inc's Rounded_Tube).
                if (tokNoMacro().kind == Tk::Symbol && cur_->sym == ')') break;
                continue;
            }
            // ... and parameters without a comma between them (shapes3.inc's
            // Half_Hollowed_Rounded_Cylinder2).
            if (tokNoMacro().kind == Tk::Name) continue;
            break;
        }
    }
    if (tokNoMacro().kind != Tk::Symbol || cur_->sym != ')')
        errorHere("expected ',' or ')' in the macro's parameter list, found " + describe());
    next();
    def->file = frames_.back().file->id;
    def->bodyStart = topPos();
    skip(false, false, at, "macro");
    const uint32_t name = def->name;
    scopes_.declare(name, Value::macro(std::move(def)));
}

// ---- include, version, default, messages --------------------------------------------------------

void Interpreter::dirInclude(const Loc& at) {
    const std::string name = parseString();
    const std::string path = findFile(name);
    if (path.empty())
        error(at, "cannot find include file \"" + name + "\" (searched the scene's folder, the library paths" +
                      (options_.installedIncludeDir.empty() ? std::string() : " and " + options_.installedIncludeDir) + ")");
    uint32_t includes = 0;
    for (const Frame& f : frames_) includes += f.kind == Frame::Include;
    if (includes >= limits_.includeDepth)
        error(at, "include files nested deeper than " + std::to_string(limits_.includeDepth) + " (does a file include itself?)");
    const SourceFile& f = openFile(path, name);
    Frame fr;
    fr.kind = Frame::Include;
    fr.site = at;
    pushFile(f, std::move(fr));
}

void Interpreter::dirVersion() {
    const Loc at = loc();
    const double v = parseFloat();
    if (isSym(';')) next();
    else warning(at, "#version should end with ';'");
    version_ = v;
    versionSet_ = true;
}

void Interpreter::dirDefault() {
    const Loc at = loc();
    expectSym('{', "after #default");
    while (!isSym('}')) {
        if (atEnd()) error(at, "#default { is never closed");
        const Kw k = kw();
        if (k != Kw::texture && k != Kw::pigment && k != Kw::normal && k != Kw::finish)
            errorHere("#default takes a texture, pigment, normal or finish, found " + describe());
        NestGuard guard(*this);
        host_.setDefault(*this, host_.readItem(*this));
    }
    next();
}

void Interpreter::dirMessage(const Loc& at, Kw which) {
    std::string text = parseString();
    if (which != Kw::error && which != Kw::warning) {
        if (diag_.debug) diag_.debug(text);
        return;
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();  // one line each
    if (which == Kw::error) error(at, "#error: " + text);
    if (diag_.warning) diag_.warning(where(at) + ": warning: " + text);
}

}  // namespace rays::sdl
