// The register machine that runs compiled functions (fn/program.h): one point at a time
// (eval, evalVector) or over arrays of points (evalBatch). No heap allocation once a Scratch
// fits the program, no virtual calls; any number of threads may run the same Program at once,
// each with its own Scratch.
#pragma once
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "rays/fn/program.h"

namespace rays::fn {

/// Per-thread working memory: the registers of a run and of the calls below it.
class Scratch {
public:
    Scratch() = default;
    /// A scratch that fits `p` (and so never allocates while running it).
    explicit Scratch(const Program& p) { fit(p); }
    /// Grows to fit `p`'s scalar and batch frames (allocates only when it grows).
    void fit(const Program& p);
    bool fitsScalar(const Program& p) const { return scalar_.size() >= static_cast<size_t>(p.scalarFrame); }
    bool fitsBatch(const Program& p) const {
        return fitsScalar(p) && batch_.size() >= static_cast<size_t>(p.batchFrame);
    }
    double* scalar() { return scalar_.data(); }
    double* batch() { return batch_.data(); }

private:
    std::vector<double> scalar_, batch_;
};

/// While one lives, the sum/prod loops of runs on this thread may repeat, and functions may call
/// other functions, `iterations` times in all; the next repetition or call throws
/// LoopBudgetExceeded. The scene language sets one around the calls it makes while parsing, so
/// that a call cannot run unbounded; renders set none.
class LoopBudget {
public:
    explicit LoopBudget(uint64_t iterations);
    ~LoopBudget();
    LoopBudget(const LoopBudget&) = delete;
    LoopBudget& operator=(const LoopBudget&) = delete;
    /// Repetitions and calls so far.
    uint64_t used() const { return initial_ - left_; }

private:
    uint64_t initial_, left_;
    uint64_t* outer_;
};

/// Thrown by a run whose loops and calls used up the thread's LoopBudget.
class LoopBudgetExceeded : public std::runtime_error {
public:
    LoopBudgetExceeded() : std::runtime_error("function loops ran past their budget") {}
};

/// The function's value at `args` (p.params values). For a host function: its first output.
double eval(const Program& p, const double* args, Scratch& s);

/// All outputs of the function at `args` into out[0..4]; returns how many (1 for compiled
/// float functions, 1..5 for host functions).
int evalVector(const Program& p, const double* args, double* out, Scratch& s);

/// out[i] = the function at (args[0][i], args[1][i], ...) for i < n: one array per parameter.
/// Branch-free programs run kBatch points per instruction; others point by point.
void evalBatch(const Program& p, const double* const* args, double* out, size_t n, Scratch& s);

/// evalBatch for a function of x, y, z (p.params must be 3).
void evalBatchXYZ(const Program& p, const double* x, const double* y, const double* z, double* out, size_t n,
                  Scratch& s);

}  // namespace rays::fn
