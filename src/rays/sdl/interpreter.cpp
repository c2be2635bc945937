// The interpreter's frames: files opened and lexed once, the token fetch that runs directives and
// expands macros on the way, macro calls and returns, the top-level loop and messages.
#include "rays/sdl/interpreter.h"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>

#include "rays/error.h"
#include "rays/io/file_text.h"
#include "rays/sdl/frames.h"
#include "rays/sdl/lexer.h"
#include "rays/util/stack_room.h"

namespace rays::sdl {

namespace fs = std::filesystem;

Interpreter::Interpreter(const LanguageOptions& options, ItemHost& host, Diagnostics diagnostics, Limits limits)
    : options_(options), host_(host), diag_(std::move(diagnostics)), limits_(limits) {
    if (options.version > 0) {
        version_ = options.version;
        versionSet_ = true;
    }
}

Interpreter::~Interpreter() = default;


void Interpreter::tooDeep() {
    const bool counted = nesting_ > limits_.nesting;
    --nesting_;
    // rawLoc, not loc(): fetching the next token could expand a macro and nest once more.
    error(rawLoc(), counted ? "nesting deeper than " + std::to_string(limits_.nesting) + " levels"
                            : "nesting too deep for the parser's stack (" + std::to_string(nesting_) + " levels)");
}

// ---- files ---------------------------------------------------------------------------------------

namespace {
bool isRegularFile(const std::string& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}
bool isDirectory(const std::string& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}
}  // namespace

const SourceFile& Interpreter::openFile(const std::string& path, const std::string& shownName) {
    if (auto it = fileByPath_.find(path); it != fileByPath_.end()) {
        markReplayed(it->second);  // included again: its tokens are read again
        return *files_[it->second];
    }
    if (isDirectory(path)) failFile(shownName, "is a directory, not a scene file");
    FileText text(path, TextForm::Source);
    if (text.status() == FileText::Status::CannotOpen) failFile(shownName, "cannot open file");
    if (text.status() == FileText::Status::CannotRead) failFile(shownName, "cannot read file");
    if (text.status() == FileText::Status::TooLarge)
        failFile(shownName, "file is larger than " + FileText::describe(kMaxTextFileBytes) + " (the limit for scene text)");
    auto f = std::make_unique<SourceFile>();
    f->id = uint32_t(files_.size());
    f->path = path;
    f->shownName = shownName;
    lexFile(text.text(), *f, names_);
    fileByPath_.emplace(path, f->id);
    files_.push_back(std::move(f));
    return *files_.back();
}

const SourceFile& Interpreter::textFile(std::string_view text, const std::string& shownName) {
    auto f = std::make_unique<SourceFile>();
    f->id = uint32_t(files_.size());
    f->path = shownName;
    f->shownName = shownName;
    lexFile(text, *f, names_);
    files_.push_back(std::move(f));
    return *files_.back();
}

std::string Interpreter::findFile(const std::string& name) const {
    if (name.empty()) return {};
    const fs::path p(name);
    auto tryPath = [](const fs::path& candidate) -> std::string {
        const std::string s = candidate.string();
        if (isRegularFile(s)) return s;
        if (!candidate.has_extension() && isRegularFile(s + ".inc")) return s + ".inc";
        return {};
    };
    if (p.is_absolute()) return tryPath(p);
    std::vector<std::string> dirs{sceneFolder_};
    for (const std::string& d : options_.libraryPaths) dirs.push_back(d);
    if (!options_.installedIncludeDir.empty()) dirs.push_back(options_.installedIncludeDir);
    for (const std::string& d : dirs)
        if (std::string found = tryPath(fs::path(d) / p); !found.empty()) return found;
    return {};
}

// ---- running -------------------------------------------------------------------------------------

void Interpreter::declareGlobal(const std::string& name, Value v) {
    scopes_.declare(names_.intern(name), std::move(v));
}

void Interpreter::runText(std::string_view text, const std::string& shownName, const std::string& folder) {
    stackFloor_ = threadStackFloor();
    sceneFolder_ = folder;
    const SourceFile& f = textFile(text, shownName);
    Frame fr;
    fr.kind = Frame::Main;
    pushFile(f, std::move(fr));
    if (!options_.includeHeader.empty()) includeHeader(Loc{f.id, 1, 1});
    topLevelLoop();
}

void Interpreter::includeHeader(const Loc& at) {
    const std::string& name = options_.includeHeader;
    const std::string path = findFile(name);
    if (path.empty())
        throw Error("rays: error: Include_Header: cannot find \"" + name + "\" (searched the scene's folder, the library paths" +
                    (options_.installedIncludeDir.empty() ? std::string() : " and " + options_.installedIncludeDir) + ")");
    const SourceFile& h = openFile(path, name);
    Frame fr;
    fr.kind = Frame::Include;
    fr.site = at;  // its errors say "included from SCENE:1:1"
    pushFile(h, std::move(fr));
}

void Interpreter::saveTop() {
    if (!frames_.empty()) frames_.back().pos = topPos();
}

void Interpreter::enterTop() {
    const Frame& f = frames_.back();
    base_ = f.file->tokens.data();
    cursor_ = base_ + f.pos;
    topFile_ = f.file->id;
}

void Interpreter::pushFile(const SourceFile& f, Frame&& frame) {
    frame.file = &f;
    frame.pos = 0;
    if (frame.kind == Frame::Include) {
        scopes_.pushLevel();
        frame.ownScope = true;
    }
    saveTop();
    frames_.push_back(std::move(frame));
    enterTop();
}

void Interpreter::topLevelLoop() {
    for (;;) {
        const Token& t = tok();
        if (t.kind == Tk::End) break;
        if (t.kind == Tk::Name && Names::isKeyword(t.id) && host_.startsItem(Kw(t.id))) {
            NestGuard guard(*this);
            ItemRef item = host_.readItem(*this);
            host_.topLevel(*this, item);
            continue;
        }
        if (t.kind == Tk::Name && t.id == uint32_t(Kw::default_)) {  // `default { }` without '#' (POV-Ray 2 syntax, still read)
            next();
            dirDefault();
            continue;
        }
        if (isSym(';')) {  // POV-Ray accepts stray semicolons between items
            next();
            continue;
        }
        if (isIdentifier() && !identBinding())
            errorHere("undeclared identifier '" + std::string(names_.name(t.id)) + "'");
        if (isIdentifier())
            errorHere("an identifier of type " + std::string(typeName(identBinding()->value.type)) +
                      " cannot stand alone; use object { " + std::string(names_.name(t.id)) + " } for an object");
        errorHere("expected a scene item (object, light_source, camera, ...), found " + describe());
    }
}

void Interpreter::tickSlow() {
    if (diag_.checkInterrupt) diag_.checkInterrupt();
    if (ticks_ > limits_.tokens) errorHere("the parse read more than " + std::to_string(limits_.tokens) + " tokens");
}

void Interpreter::fetchSlow(bool expandMacros) {
    for (;;) {
        tick();
        const Token& t = *cursor_;
        if (t.kind == Tk::End) {
            if (frames_.size() == 1) {
                const Frame& f = frames_.back();
                if (!f.ctl.empty()) {
                    const Ctl& open = f.ctl.back();
                    error(open.loc, "this directive is never closed by #end (end of file reached)");
                }
                cur_ = &t;
                curFile_ = topFile_;
                have_ = true;
                return;
            }
            endOfFrame();
            continue;
        }
        ++cursor_;
        if (t.kind == Tk::Directive) {
            NestGuard guard(*this);  // a directive read while another reads its arguments: #debug #debug "x"
            directive(t);
            if (have_) return;  // a directive that looked ahead left the token after it current
            continue;
        }
        if (expandMacros && t.kind == Tk::Name && !Names::isKeyword(t.id)) {
            const Binding* b = scopes_.find(t.id);
            if (b && b->value.type == VType::Macro) {
                const Value m = b->value;
                invokeMacro(t, m);
                continue;
            }
        }
        cur_ = &t;
        curFile_ = topFile_;
        have_ = true;
        return;
    }
}

void Interpreter::endOfFrame() {
    Frame& f = frames_.back();
    if (!f.ctl.empty()) error(f.ctl.back().loc, "this directive is never closed by #end (end of file reached)");
    if (f.kind == Frame::Macro) error(f.site, "macro body ended without #end");
    if (f.ownScope) scopes_.popLevel();
    frames_.pop_back();
    enterTop();
}

// ---- macros --------------------------------------------------------------------------------------

void Interpreter::invokeMacro(const Token& nameTok, const Value& macroValue) {
    // Reading the arguments may expand another macro call before this one returns: M(M(M(...))).
    NestGuard guard(*this);
    const auto def = std::static_pointer_cast<const MacroDef>(macroValue.ref);
    const Loc at{topFile_, nameTok.line, nameTok.col};
    const std::string_view nameView = names_.name(nameTok.id);
    auto name = [&] { return std::string(nameView); };  // built only for messages
    if (!isSym('(')) error(at, "macro " + name() + " must be called with a parameter list: " + name() + "(...)");
    next();
    Args args;  // Undefined: an argument left empty
    SmallVec<ByRefArg, 4> byRef;
    const size_t n = def->params.size();
    if (!isSym(')')) {
        for (;;) {
            if (args.size() >= n) {
                if (isSym(')')) break;  // a comma after the last argument (shapes3.inc's templates)
                errorHere("macro " + name() + " takes " + std::to_string(n) + " parameters, more were given");
            }
            if (isSym(',') || isSym(')')) {
                args.emplace_back();
            } else if (!passByReference(def->params[args.size()], args, byRef)) {
                args.push_back(parseRValue());
            }
            if (isSym(')')) break;
            if (!acceptSym(',') && atEnd())  // POV-Ray also reads arguments not separated by ','
                errorHere("expected ',' or ')' in the arguments of macro " + name() + ", found " + describe());
        }
    }
    next();  // ')'
    while (args.size() < n) args.emplace_back();
    for (size_t i = 0; i < n; ++i)
        if (!args[i].defined() && !def->optional[i])
            error(at, "macro " + name() + " takes " + std::to_string(n) + " parameters; '" +
                          std::string(names_.name(def->params[i])) + "' was not given");
    if (macroDepth_ >= limits_.macroDepth)
        error(at, "macro calls nested deeper than " + std::to_string(limits_.macroDepth) + " (runaway recursion?)");
    scopes_.pushLevel();
    for (size_t i = 0; i < args.size(); ++i)
        if (args[i].defined()) scopes_.local(def->params[i], std::move(args[i]));
    Frame fr;
    fr.kind = Frame::Macro;
    fr.file = files_[def->file].get();
    markReplayed(def->file);
    fr.pos = def->bodyStart;
    fr.site = at;
    fr.macro = def;
    fr.byRef = std::move(byRef);
    fr.ownScope = true;
    saveTop();
    frames_.push_back(std::move(fr));
    ++macroDepth_;
    enterTop();
}

// A lone identifier is passed by reference (POV-Ray 3.7 reference, "Returning Values Via
// Parameters"): the macro's changes to the parameter are copied back to it on return.
bool Interpreter::passByReference(uint32_t param, Args& args, SmallVec<ByRefArg, 4>& byRef) {
    if (!isIdentifier()) return false;
    const Token& after = *cursor_;
    if (after.kind != Tk::Symbol || (after.sym != ',' && after.sym != ')')) return false;
    Binding* b = identBinding();
    if (!b)
        errorHere("cannot pass the undeclared identifier '" + std::string(names_.name(cur_->id)) +
                  "' as a macro parameter; declare it first");
    args.push_back(copyCharged(b->value, loc()));
    byRef.push_back(ByRefArg{param, cur_->id, b->serial});
    next();
    return true;
}

void Interpreter::returnFromMacro() {
    Frame& f = frames_.back();
    SmallVec<std::pair<const ByRefArg*, Value>, 4> back;
    for (size_t i = 0; i < f.byRef.size(); ++i) {
        const ByRefArg& r = f.byRef[i];
        if (Binding* b = scopes_.find(r.param); b && b->level == scopes_.level()) back.emplace_back(&r, b->value);
    }
    scopes_.popLevel();
    for (size_t i = 0; i < back.size(); ++i)
        if (Binding* target = scopes_.findSerial(back[i].first->target, back[i].first->serial))
            target->value = back[i].second;
    frames_.pop_back();
    --macroDepth_;
    enterTop();
}

// ---- tokens and messages -------------------------------------------------------------------------

void Interpreter::expectSym(char c, std::string_view context) {
    if (!isSym(c)) errorHere(std::string("expected '") + c + "' " + std::string(context) + ", found " + describe());
    next();
}

void Interpreter::expectKw(Kw k, std::string_view context) {
    if (!isKw(k))
        errorHere("expected '" + std::string(keywordName(k)) + "' " + std::string(context) + ", found " + describe());
    next();
}

Binding* Interpreter::identBinding() {
    if (!isIdentifier()) return nullptr;
    return scopes_.find(cur_->id);
}

std::string Interpreter::describe() {
    const Token& t = tok();
    switch (t.kind) {
        case Tk::End: return "end of file";
        case Tk::Number: {
            char buf[64];
            std::snprintf(buf, sizeof buf, "number %g", t.number);
            return buf;
        }
        case Tk::String: return "a string";
        case Tk::Name:
            if (Names::isKeyword(t.id)) return "'" + std::string(names_.name(t.id)) + "'";
            if (const Binding* b = scopes_.find(t.id))
                return std::string(typeName(b->value.type)) + " identifier '" + std::string(names_.name(t.id)) + "'";
            return "undeclared identifier '" + std::string(names_.name(t.id)) + "'";
        case Tk::Directive: return "'#" + std::string(names_.name(t.id)) + "'";
        case Tk::Symbol:
            switch (t.sym) {
                case kLessEq: return "'<='";
                case kGreaterEq: return "'>='";
                case kNotEq: return "'!='";
                default: return std::string("'") + char(t.sym) + "'";
            }
    }
    return "?";
}

Loc Interpreter::rawLoc() const {
    if (have_ || frames_.empty() || !cursor_) return cur_ ? Loc{curFile_, cur_->line, cur_->col} : Loc{};
    return Loc{topFile_, cursor_->line, cursor_->col};
}

std::string Interpreter::where(const Loc& at) const {
    std::string s = files_.empty() ? std::string("?") : files_[at.file]->shownName;
    if (at.line > 0) s += ":" + std::to_string(at.line) + ":" + std::to_string(at.col);
    return s;
}

// The include files and macro calls the parse is in, innermost first; a deep stack (recursion)
// shows its 4 innermost and 2 outermost frames.
std::string Interpreter::context() const {
    std::string s;
    const size_t n = frames_.size() - 1;  // frames above the main file
    for (size_t k = 0; k < n; ++k) {
        if (n > 8 && k == 4) {
            s += "; ... " + std::to_string(n - 6) + " more";
            k = n - 3;
            continue;
        }
        const Frame& f = frames_[n - k];
        s += s.empty() ? " (" : "; ";
        if (f.kind == Frame::Macro)
            s += "in macro " + std::string(names_.name(f.macro->name)) + " called at " + where(f.site);
        else
            s += "in " + f.file->shownName + " included from " + where(f.site);
    }
    return s.empty() ? s : s + ")";
}

// Errors are one line: line breaks in what the message quotes (a file name or an #error text
// written across lines) are shown as \n and \r.
void Interpreter::error(const Loc& at, const std::string& msg) {
    std::string line;
    line.reserve(msg.size());
    for (const char c : msg) {
        if (c == '\n') line += "\\n";
        else if (c == '\r') line += "\\r";
        else line += c;
    }
    throw Error(where(at) + ": error: " + line + context());
}

void Interpreter::warning(const Loc& at, const std::string& msg) {
    const int seen = ++warnedTimes_[msg];
    if (seen > 3) return;  // the same warning is shown three times at most
    const std::string line = where(at) + ": warning: " + msg + (seen == 3 ? " (further ones not shown)" : "");
    if (diag_.warning) diag_.warning(line);
}

}  // namespace rays::sdl
