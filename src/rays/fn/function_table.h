// The functions of one scene, in declaration order: compiled float functions and host functions
// (pattern, pigment, transform and spline functions the renderer supplies). A function may call
// only those declared before it, so a table never holds recursion. Entries are immutable
// programs; once the parse is over, any number of threads may evaluate them at once.
#pragma once
#include <memory>
#include <span>
#include <vector>

#include "rays/fn/compile.h"
#include "rays/fn/expr.h"
#include "rays/fn/machine.h"
#include "rays/fn/program.h"

namespace rays::fn {

class FunctionTable {
public:
    /// Compiles `body` (a function of `params` parameters that may call entries 0..size()-1)
    /// and appends it; returns its index. Throws CompileError (with the offending node's loc).
    int addFloat(const Expr& body, int params, const CompileOptions& options = {});
    /// Appends a host function; returns its index. Throws CompileError for bad input/output counts.
    int addHost(const HostFunction& host);

    int size() const { return static_cast<int>(programs_.size()); }
    /// The program of entry i (host entries have a forwarding program).
    const Program& program(int i) const { return *programs_[i]; }
    /// The same, shared (it stays valid when the table is gone: pigment patterns keep it).
    std::shared_ptr<const Program> shared(int i) const { return programs_[i]; }
    int params(int i) const { return programs_[i]->params; }
    int outputs(int i) const { return programs_[i]->outputs; }
    bool isHost(int i) const { return programs_[i]->hostWrapper; }
    /// All entries in order (what the compiler may call).
    std::span<const std::shared_ptr<const Program>> programs() const { return programs_; }

    /// Entry i's value at args (a host function's first output); s is the calling thread's.
    double call(int i, const double* args, Scratch& s) const { return eval(*programs_[i], args, s); }
    /// All of entry i's outputs into out[0..4]; returns how many.
    int callVector(int i, const double* args, double* out, Scratch& s) const {
        return evalVector(*programs_[i], args, out, s);
    }
    /// A scratch that fits every entry so far.
    Scratch makeScratch() const;

private:
    std::vector<std::shared_ptr<const Program>> programs_;
};

}  // namespace rays::fn
