// The compiler: an expression tree (fn/expr.h) → a Program for the register machine
// (fn/program.h, fn/machine.h). It checks the tree against POV-Ray's rules and limits, folds
// constant subtrees, inlines calls of small compiled functions and emits two forms of code:
// scalar (branches skip untaken select/?: arms, sum/prod loops) and batch (branch-free, for
// blocks of points).
#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "rays/error.h"
#include "rays/fn/expr.h"
#include "rays/fn/program.h"

namespace rays::fn {

/// POV-Ray 3.7's limits (reference 3.3.1.8.3, checked by running POV-Ray 3.7).
inline constexpr int kMaxParams = 56;        ///< parameters per function (and at least 1)
inline constexpr int kMaxLocals = 56;        ///< sum/prod iteration variables alive at once
inline constexpr int kMaxCallDepth = 1024;   ///< functions calling functions (a chain of 1024 works)
/// Operators per function: POV-Ray says "about 200000"; measured, `a+a+...` fails past 524,200
/// additions (about 2^20 of its instructions). Rays counts tree nodes against 2^20.
inline constexpr int kMaxNodes = 1 << 20;

/// A rule or limit broken by a function body. what() is the message without a location (e.g.
/// "function 2 takes 3 arguments, 2 given"); loc() is the Node::loc of the offending node, which
/// the parser turns into FILE:LINE:COL.
class CompileError : public Error {
public:
    CompileError(const std::string& message, int32_t loc) : Error(message), loc_(loc) {}
    int32_t loc() const { return loc_; }

private:
    int32_t loc_;
};

struct CompileOptions {
    bool fold = true;         ///< evaluate constant subtrees at compile time
    bool inlineCalls = true;  ///< copy small compiled callees into the caller
    int inlineLimit = 64;     ///< largest callee (folded tree nodes) that is inlined
    bool branches = true;     ///< scalar code jumps around expensive select/?: arms
};

/// Compiles `body`, a function of `params` parameters (1..56). A Call node's id indexes
/// `callable` (the functions declared before this one: compiled programs and host wrappers);
/// calling anything else is an error, so functions cannot recurse. Throws CompileError.
std::shared_ptr<const Program> compile(const Expr& body, int params,
                                       std::span<const std::shared_ptr<const Program>> callable,
                                       const CompileOptions& options = {});

/// A program that forwards `host.inputs` arguments to `host` (a table entry for a host function);
/// evalVector returns all its outputs, eval the first.
std::shared_ptr<const Program> hostProgram(const HostFunction& host);

}  // namespace rays::fn
