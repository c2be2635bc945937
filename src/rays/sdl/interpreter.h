// The interpreter of POV-Ray's scene language. It reads files as token arrays (lexer.h), runs
// directives as it meets them (#declare #local #undef #if #ifdef #ifndef #elseif #else #switch
// #case #range #break #while #for #macro #include #version #default #debug #warning #error
// #fopen #read #write #fclose), expands macro calls, and evaluates expressions. Scene items are
// read by the host (host.h) through the calls below; the interpreter knows nothing of rendering.
//
// Tokens are fetched lazily, as POV-Ray does: tok() fetches the current token when it has not
// been fetched yet (running any directive and expanding any macro met on the way), next()
// consumes it. A reader that has consumed a closing '}' has not looked further, so a
// `#declare O = sphere {...}` binds O before the directive after it runs.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "rays/fn/function_table.h"
#include "rays/sdl/expr_code.h"
#include "rays/sdl/host.h"
#include "rays/sdl/item.h"
#include "rays/sdl/names.h"
#include "rays/sdl/options.h"
#include "rays/sdl/pov_random.h"
#include "rays/sdl/scopes.h"
#include "rays/sdl/small_vec.h"
#include "rays/sdl/source_file.h"
#include "rays/sdl/token.h"
#include "rays/sdl/value.h"

namespace rays::sdl {

/// Where messages go: warnings and #debug text (each warning a complete line without '\n'),
/// and how a long parse learns of Ctrl-C.
struct Diagnostics {
    std::function<void(const std::string&)> warning;
    std::function<void(const std::string&)> debug;  ///< #debug, #render, #statistics text as written
    std::function<void()> checkInterrupt;            ///< called now and then; throws to stop the parse (Ctrl-C)
};

/// Limits that keep every parse bounded (docs/scene-language.md, "Limits").
struct Limits {
    uint64_t loopIterations = 100'000'000;  ///< #while and #for iterations in one parse
    uint32_t macroDepth = 10'000;            ///< nested macro calls
    uint32_t includeDepth = 64;              ///< nested include files
    uint32_t nesting = 4'000;                ///< nested items, expressions and parentheses
    uint64_t tokens = uint64_t(1) << 30;     ///< tokens consumed (a runaway recursion ends here)
    uint64_t arrayElements = uint64_t(1) << 28;  ///< array elements and spline points made in one parse, new and copied
    uint64_t stringBytes = uint64_t(1) << 36;    ///< bytes of the strings string functions make in one parse
    uint64_t writeBytes = uint64_t(1) << 34;     ///< bytes #write writes in one parse
    /// Objects the scene builder (src/rays/pov) makes from the parsed items: every copy of a declared
    /// object counts, a mesh counts its triangles too, a height field its samples.
    uint64_t sceneObjects = uint64_t(1) << 26;
    /// Items in the declared items used in other items, counted at every use: what POV-Ray copies
    /// there, and what the scene builder walks.
    uint64_t itemCopies = uint64_t(1) << 27;
};

class Interpreter {
public:
    Interpreter(const LanguageOptions& options, ItemHost& host, Diagnostics diagnostics, Limits limits = {});
    ~Interpreter();
    Interpreter(const Interpreter&) = delete;
    Interpreter& operator=(const Interpreter&) = delete;

    /// Parses scene text (a scene file's, read by the caller) to its end, giving top-level items to
    /// the host; shownName names it in messages, folder is where its includes are looked up first.
    /// Throws Error "FILE:LINE:COL: error: ..." (with the include chain and macro calls) on bad input.
    void runText(std::string_view text, const std::string& shownName, const std::string& folder = ".");

    // ---- tokens -------------------------------------------------------------------------
    /// The current token (fetched now if it was not yet: directives run, macros expand).
    const Token& tok() {
        if (!have_) fetch(true);
        return *cur_;
    }
    /// Consumes the current token.
    void next() {
        if (!have_) fetch(true);
        have_ = false;
    }
    /// The current token without expanding a macro name (for names being defined or tested).
    const Token& tokNoMacro() {
        if (!have_) fetch(false);
        return *cur_;
    }
    Loc loc() {
        tok();
        return Loc{curFile_, cur_->line, cur_->col};
    }
    bool isKw(Kw k) { return tok().kind == Tk::Name && cur_->id == uint32_t(k); }
    /// Whether the next token is keyword k, looking at the file's text only: no directive runs and
    /// no macro expands to find out (for items that may go on after their block, before a
    /// following #declare has run).
    bool peekRawKw(Kw k) const {
        const Token* t = peekRaw();
        return t && t->kind == Tk::Name && t->id == uint32_t(k);
    }
    /// The next token in the file's text (the current one if it was fetched), the tokens after it
    /// following in the array: no directive runs and no macro expands.
    const Token* peekRaw() const { return have_ ? cur_ : cursor_; }
    bool isSym(char c) { return tok().kind == Tk::Symbol && cur_->sym == uint8_t(c); }
    bool isKeyword() { return tok().kind == Tk::Name && Names::isKeyword(cur_->id); }
    bool isIdentifier() { return tok().kind == Tk::Name && !Names::isKeyword(cur_->id); }
    Kw kw() { return isKeyword() ? Kw(cur_->id) : Kw::Count; }
    bool atEnd() { return tok().kind == Tk::End; }
    bool acceptSym(char c) {
        if (!isSym(c)) return false;
        next();
        return true;
    }
    bool acceptKw(Kw k) {
        if (!isKw(k)) return false;
        next();
        return true;
    }
    void expectSym(char c, std::string_view context);
    /// The same with the context in two parts, joined only when the symbol is missing.
    void expectSym(char c, std::string_view contextA, std::string_view contextB) {
        if (isSym(c)) return next();
        expectSym(c, std::string(contextA) + std::string(contextB));
    }
    void expectKw(Kw k, std::string_view context);
    /// The binding of the current identifier token, or null (undeclared, or not an identifier).
    Binding* identBinding();
    /// The current token's spelling for messages: "'sphere'", "'}'", "number 3.5", "end of file".
    std::string describe();
    std::string_view spelling(uint32_t nameId) const { return names_.name(nameId); }

    // ---- expressions --------------------------------------------------------------------------
    /// True when the current token can start a float, vector or colour expression.
    bool atNumericStart();
    /// True when the current token can start a string expression.
    bool atStringStart();
    /// A float, vector or colour expression (its type as written); colorContext allows colour
    /// keywords (rgb, red, filter, ...) inside it, as after `color`.
    Value parseNumeric(bool colorContext = false);
    double parseFloat();
    int parseInt(std::string_view what);
    /// A vector promoted or cut to dim components (a float fills all of them).
    std::array<double, 5> parseVector(int dim);
    /// A colour: optional `color`/`colour`, then any colour expression; a float fills all five
    /// components, a vector leaves filter and transmit 0 (POV-Ray's promotion rules).
    Value parseColor();
    std::string parseString();
    /// `[Bool]` after a flag keyword: true when no float expression follows.
    bool parseOptionalBool();
    /// Any value that may follow `=` in #declare: numeric, string, item, array, function, spline.
    Value parseRValue();
    /// Reads the `function { ... }` at the current token (`function` keyword current).
    Value parseFunction();
    /// Reads a function body `{ ... }` (the '{' current) with the given parameter names.
    Value parseFunctionBody(std::vector<uint32_t> params, const Loc& at);
    /// Reads `spline { ... }` (keyword current).
    Value parseSplineBlock();

    // ---- messages -------------------------------------------------------------------------------
    [[noreturn]] void error(const Loc& at, const std::string& msg);
    [[noreturn]] void errorHere(const std::string& msg) { error(loc(), msg); }
    void warning(const Loc& at, const std::string& msg);
    /// "file:line:col".
    std::string where(const Loc& at) const;
    /// Resolves a file name as #include does (scene folder, library paths, installed includes);
    /// empty when not found.
    std::string findFile(const std::string& name) const;

    // ---- state the host reads -----------------------------------------------------------------
    double version() const { return version_; }
    /// The version whose rules the scene follows: version() once a #version directive or the
    /// Version= option set it; before that POV-Ray 3.7 keeps pre-3.7 compatibility (measured: an
    /// include that saves `version` and restores it with #version switches a scene without
    /// #version to 3.7's rules).
    double compatibilityVersion() const { return versionSet_ ? version_ : kUnversioned; }
    static constexpr double kUnversioned = 3.62;
    const LanguageOptions& options() const { return options_; }
    ItemHost& host() { return host_; }
    /// `assumed_gamma` as the host read it from global_settings (needed for srgb colours); 0 unset.
    void setAssumedGamma(double g) { assumedGamma_ = g; }
    double assumedGamma() const { return assumedGamma_; }
    /// Counts a nesting level of the host's readers; throws past Limits::nesting, or when the
    /// thread's stack is nearly used up (a deep nest of heavy levels, smaller thread stacks).
    class NestGuard {
    public:
        explicit NestGuard(Interpreter& in) : in_(in) {
            if (++in_.nesting_ > in_.limits_.nesting ||
                reinterpret_cast<uintptr_t>(__builtin_frame_address(0)) < in_.stackFloor_)
                in_.tooDeep();
        }
        ~NestGuard() { --in_.nesting_; }
        NestGuard(const NestGuard&) = delete;
        NestGuard& operator=(const NestGuard&) = delete;

    private:
        Interpreter& in_;
    };

    /// The value of the identifier at the current token with its `[i]` and `.x` postfixes and nothing
    /// after them, as a float (an error naming what otherwise): a constant operand of a function body.
    double parseIdentifierOperand(std::string_view what) {
        const Loc at = loc();
        return toFloat(postfix(identifierValue(false)), at, what);
    }

    /// Counts the items of a declared item used in another one (Limits::itemCopies); throws past it.
    void countItemCopy(uint64_t items, const Loc& at) {
        spend(itemCopies_, items, limits_.itemCopies, at, "items used again through identifiers (each use counts the item's whole tree)");
    }

    /// Defines identifier `name` at global level (command-line Declare=NAME=VALUE).
    void declareGlobal(const std::string& name, Value v);

private:
    friend class DirectiveRunner;
    using Args = SmallVec<Value, 4>;  ///< the arguments of a call
    struct Ctl;
    struct Frame;
    /// A macro parameter passed by reference: copied back to the caller's binding on return.
    struct ByRefArg {
        uint32_t param = 0;   ///< the macro's parameter name
        uint32_t target = 0;  ///< the caller's identifier
        uint32_t serial = 0;  ///< its binding
    };

    // files and frames (interpreter.cpp)
    const SourceFile& openFile(const std::string& path, const std::string& shownName);
    /// Pushes options_.includeHeader as an include read before the scene's first item (site at).
    void includeHeader(const Loc& at);
    const SourceFile& textFile(std::string_view text, const std::string& shownName);
    void pushFile(const SourceFile& f, Frame&& frame);
    /// Fetches the next token: plain tokens here (inline); directives, macro names and file ends
    /// through fetchSlow.
    void fetch(bool expandMacros) {
        const Token& t = *cursor_;
        if (t.kind == Tk::Directive || t.kind == Tk::End) return fetchSlow(expandMacros);
        tick();
        if (expandMacros && t.kind == Tk::Name && !Names::isKeyword(t.id)) {
            const Binding* b = scopes_.find(t.id);
            if (b && b->value.type == VType::Macro) return fetchSlow(expandMacros);
        }
        ++cursor_;
        cur_ = &t;
        curFile_ = topFile_;
        have_ = true;
    }
    void fetchSlow(bool expandMacros);
    void endOfFrame();
    void topLevelLoop();
    std::string context() const;
    /// Counts a token; every 65536th checks for Ctrl-C and the token limit (tickSlow).
    void tick() {
        if ((++ticks_ & 0xFFFF) == 0) tickSlow();
    }
    void tickSlow();
    [[noreturn]] void tooDeep();
    /// Where the next raw token is (no directive run, no macro expanded).
    Loc rawLoc() const;

    // directives (directives.cpp)
    void directive(const Token& t);
    void dirInclude(const Loc& at);
    void dirDeclare(const Loc& at, bool isLocal);
    void dirUndef();
    void dirIf(const Loc& at);
    /// After an #if's test: runs the branch taken, or skips to the #else / #elseif that runs, or past #end.
    void ifBranches(bool taken, const Loc& at, const char* name);
    void dirIfdef(const Loc& at, bool wantDefined);
    void dirElse(const Loc& at, bool isElseif);
    void dirEnd(const Loc& at);
    void dirSwitch(const Loc& at);
    void dirCase(const Loc& at, bool isRange);
    void dirBreak(const Loc& at);
    enum class SkipStop;
    void switchClauses(SkipStop s, const Loc& opener);
    bool caseMatches(bool isRange);
    void dirWhile(const Loc& at, uint32_t directivePos);
    void dirFor(const Loc& at);
    void dirMacro(const Loc& at);
    void dirVersion();
    void dirDefault();
    void dirMessage(const Loc& at, Kw which);
    void dirFopen(const Loc& at);
    void dirFclose();
    void dirRead(const Loc& at);
    void dirWrite(const Loc& at);
    bool condition(const char* directiveName);
    bool definedTest();
    void finishDirectiveParen();
    uint32_t readNewName(const char* what);
    /// Skips raw tokens of the current frame to the directive that ends the skipped part.
    enum class SkipStop { Else, Elseif, End, Case, Range };
    SkipStop skip(bool stopAtElse, bool stopAtCase, const Loc& opener, const char* openerName);
    void skipPastEnds(int count, const Loc& opener);
    void invokeMacro(const Token& nameTok, const Value& macro);
    bool passByReference(uint32_t param, Args& args, SmallVec<ByRefArg, 4>& byRef);
    void returnFromMacro();
    Binding& assignTarget(uint32_t name, bool isLocal, const std::vector<size_t>& path, Value v, const Loc& at, uint32_t level);
    Value readArrayValue(const Loc& at);
    /// Adds n to one of the parse's running totals; throws "more than LIMIT WHAT in this parse" past limit.
    void spend(uint64_t& total, uint64_t n, uint64_t limit, const Loc& at, const char* what);
    /// An array held by v alone, kept as it is; its element arrays held elsewhere too are copied.
    Value adoptArray(Value v, const Loc& at);
    /// copyValue, with the elements an array copy makes charged.
    Value copyCharged(const Value& v, const Loc& at);

    // expressions (expressions.cpp)
    Value fullExpression() { return fullNum().value(); }
    Num fullNum();
    Num binary(int minPrec, bool full, bool colorCtx);
    Num stringComparison();
    Num logical() { return binary(1, true, false); }
    Num additive(bool colorCtx) { return binary(3, false, colorCtx); }
    Num binaryAfter(Num a, int minPrec, bool full, bool colorCtx);
    bool quickOperand(bool full, Num& out);
    /// The operand binary(minPrec, full, colorCtx) reads at the current token, from the code compiled
    /// for its place (expr_code.h), the tokens after it fetched as the reader would; false when the
    /// place has no code or the identifiers hold other kinds of values now (nothing consumed).
    bool compiledOperand(int minPrec, bool full, bool colorCtx, Num& out);
    /// Runs code whose identifiers hold the given bindings (type-checked): its value, or false
    /// (nothing changed) when an array element read is not there or of another type.
    bool runCompiled(const ExprCode& code, const Binding* const* binds, Num& out);
    /// The same for code that makes floats only (ExprCode::scalar).
    bool runScalar(const ExprCode& code, const Binding* const* binds, double& out);
    Num unary(bool colorCtx);
    Num factor(bool colorCtx);
    Num postfix(Num v);
    Num identifierValue(bool colorCtx);
    Num colorKeyword();
    Num colorComponents(Num c);
    Num vectorLiteral();
    /// clock, clock_delta, clock_on, initial/final_clock, initial/final_frame, frame_number,
    /// image_width, image_height, version.
    double environmentValue(Kw k) const;
    Num numericOf(const Value& v, const Loc& at);
    double toFloat(const Value& v, const Loc& at, std::string_view what);
    double toFloat(const Num& v, const Loc& at, std::string_view what);
    bool truth(const Value& v, const Loc& at) { return truth(Num::of(v), at); }
    bool truth(const Num& v, const Loc& at);
    /// The element `[i][j]...` of arr (the current token is '['), going on into elements that are
    /// arrays while '[' follows; pathOut gets the flat index at each array level.
    Value arrayElement(const Value& arr, bool forAssign, std::vector<size_t>* pathOut);

    // built-in functions (builtins.cpp)
    bool isBuiltinFunction(Kw k) const;
    Value builtin(Kw k, const Loc& at);
    std::string builtinString(Kw k, const Loc& at);
    Value callFunction(const Value& f, const Loc& at);
    Value callSpline(const Value& s, const Loc& at);
    Args callArgs(const char* name, size_t minArgs, size_t maxArgs);
    bool definedName();
    bool peekRawSym(char c);
    bool peekRawSymAfterName(char c);
    Value parseArray();
    void arrayInitializer(ArrayData& a, size_t dim, size_t& flat);
    std::string stringFunction(Kw k, const Loc& at);
    Value geometryQuery(Kw k, const Loc& at);

    const LanguageOptions& options_;
    ItemHost& host_;
    Diagnostics diag_;
    Limits limits_;
    Names names_;
    Scopes scopes_;
    std::vector<std::unique_ptr<SourceFile>> files_;
    std::unordered_map<std::string, uint32_t> fileByPath_;
    std::vector<Frame> frames_;
    std::string sceneFolder_ = ".";

    const Token* cur_ = nullptr;  ///< the current token (tokens of every file stay in place)
    uint32_t curFile_ = 0;        ///< the file it came from
    bool have_ = false;
    // The top frame's read position: cursor_ points at its next raw token (its Frame::pos is
    // stale while it is on top, saved when another frame is pushed over it).
    const Token* cursor_ = nullptr;
    const Token* base_ = nullptr;
    uint32_t topFile_ = 0;
    uint32_t topPos() const { return uint32_t(cursor_ - base_); }
    void jumpTo(uint32_t pos) { cursor_ = base_ + pos; }
    /// After frames_ changed: the cursor follows the (new) top frame.
    void enterTop();
    /// Saves the cursor into the top frame before another frame goes over it.
    void saveTop();

    /// The version in force: `version`'s value; 3.7 (POV-Ray's own) until a #version or Version=.
    double version_ = 3.7;
    bool versionSet_ = false;  ///< a #version directive or the Version= option set version_
    double assumedGamma_ = 0;
    uint32_t nesting_ = 0;
    uint32_t macroDepth_ = 0;  ///< macro frames on the stack
    uintptr_t stackFloor_ = 0;  ///< NestGuard refuses to nest below this stack address (0: no check)
    uint64_t iterations_ = 0;
    uint64_t arrayElements_ = 0, stringBytes_ = 0, writeBytes_ = 0, itemCopies_ = 0;
    uint64_t ticks_ = 0;
    std::vector<std::string> deprecatedMessages_;
    RandomStreams random_;
    std::shared_ptr<fn::FunctionTable> functions_ = std::make_shared<fn::FunctionTable>();
    std::unordered_map<std::string, int> warnedTimes_;
    /// Compiled expressions: by file id, for each token the index of the code compiled at it in
    /// exprCodes_, kExprUntried or kExprNever.
    /// Only files whose tokens are read again (a loop's body, a macro's, a file included twice) have
    /// slots, and a place is compiled on its second reading (kExprSeen after the first): a file read
    /// once, a big mesh's, costs nothing here.
    static constexpr int32_t kExprUntried = -1, kExprNever = -2, kExprSeen = -3;
    std::vector<std::vector<int32_t>> exprSlots_;
    void markReplayed(uint32_t file) {
        if (file >= exprSlots_.size()) exprSlots_.resize(size_t(file) + 1);
        if (exprSlots_[file].empty()) exprSlots_[file].assign(files_[file]->tokens.size(), kExprUntried);
    }
    std::vector<ExprCode> exprCodes_;
};

}  // namespace rays::sdl
