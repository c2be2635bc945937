// A compiled function: code for a register machine (fn/machine.h runs it), its constants, the
// argument lists of its calls and the functions it calls.
//
// Why registers and not a stack: a tree of N operators becomes about N instructions that name
// their operands (`d = a + b`, `d = a * 2.5` with the constant in the instruction), where a stack
// machine needs loads and stores around every operator; each instruction costs one dispatch, so
// fewer, fatter instructions are what makes the interpreter fast. The same register code runs
// over blocks of points at once (Program::batch): every instruction then loops over kBatch lanes,
// the dispatch cost is shared and the loops vectorise.
#pragma once
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "rays/fn/expr.h"
#include "rays/fn/ops.h"

namespace rays::fn {

struct Ir;

/// Points evaluated together by the batch form (registers hold kBatch lanes each).
inline constexpr int kBatch = 32;

/// A function supplied by the host (pattern, pigment, transform and spline functions): `inputs`
/// arguments in, `outputs` values (1..5) out. `fn` must be safe to call from many threads at once.
/// `data` is its per-call context (a compiled pattern, a matrix); `keep`, when set, owns it, so
/// that every program calling the function keeps it alive (the renderer outlives the parse).
struct HostFunction {
    using Fn = void (*)(const void* data, const double* in, double* out);
    HostFunction(Fn f = nullptr, const void* d = nullptr, int in = 3, int out = 1, std::shared_ptr<const void> k = {})
        : fn(f), data(d), inputs(in), outputs(out), keep(std::move(k)) {}
    Fn fn = nullptr;
    const void* data = nullptr;
    int inputs = 3;
    int outputs = 1;
    std::shared_ptr<const void> keep;
};

/// Machine opcodes. Fields: d destination, a/b/c operand registers, k an immediate constant, aux
/// a jump target, a callee or an internal number; `list` an offset into Program::lists.
///   Ret: return r[a]. Mov: d = a. Const: d = k.
///   Neg .. Log (RAYS_FN_UNARY_OPS, fn/ops.h): d = f(a). Sqr: d = a*a. Add .. Min
///   (RAYS_FN_BINARY_OPS): d = a op b. AddK .. PowK: d = a op k (K first: d = k op a).
///   MulAdd, MulSub: d = a*b ± c, rounded twice as the separate ops.
///   Select3: d = a < 0 ? b : c. Select4: d = a < 0 ? b : a == 0 ? c : r[aux]. Cond: d = a != 0 ? b : c.
///   Jump: go to aux. JumpIfZero: if a == 0. JumpIfNotNeg: if !(a < 0). JumpIfNotZero: if !(a == 0).
///   JumpIfNotLe: if !(a <= b) (the sum/prod loop test).
///   Call: d = compiled callee aux of the c arguments listed at `list`. Host: d = member b of host
///   function aux of those arguments. Internal: d = internal function aux of those arguments.
enum class Code : uint16_t {
    Ret, Mov, Const,
#define RAYS_FN_CODE_ENUM(name, expr) name,
    RAYS_FN_UNARY_OPS(RAYS_FN_CODE_ENUM)
    Sqr,
    RAYS_FN_BINARY_OPS(RAYS_FN_CODE_ENUM)
#undef RAYS_FN_CODE_ENUM
    AddK, SubK, KSub, MulK, DivK, KDiv, MaxK, KMax, MinK, KMin, PowK,
    MulAdd, MulSub, Select3, Select4, Cond,
    Jump, JumpIfZero, JumpIfNotNeg, JumpIfNotZero, JumpIfNotLe,
    Call, Host, Internal,
};

struct Instr {
    Code op = Code::Ret;
    uint16_t d = 0, a = 0, b = 0, c = 0;
    uint16_t unused = 0;
    uint32_t aux = 0;  ///< jump target, callee, host or internal number; for Call/Host/Internal
                       ///< the argument list's offset is in `list`
    union {
        double k = 0;
        uint32_t list;
    };
};

/// A compiled float function. Immutable once built: any number of threads may run it at once,
/// each with its own Scratch.
struct Program {
    int params = 0;                ///< arguments, 1..56 (registers 0..params-1)
    int outputs = 1;               ///< 1 for compiled functions; a host function's outputs
    std::vector<Instr> code;       ///< scalar code (jumps around untaken branches, loops)
    std::vector<Instr> batch;      ///< branch-free code for kBatch lanes; empty: run lanes one by one
    std::vector<double> pool;      ///< constants copied to registers params.. at every scalar run
    std::vector<double> batchPool; ///< the same for the batch code (broadcast to all lanes)
    std::vector<uint16_t> lists;   ///< argument registers of Call/Host/Internal instructions
    std::vector<std::shared_ptr<const Program>> callees;  ///< compiled functions called (aux)
    std::vector<HostFunction> hosts;                      ///< host functions called (aux)
    int registers = 0;             ///< registers of one scalar frame (params, pool, temporaries)
    int batchRegisters = 0;        ///< registers of one batch frame
    int scalarFrame = 0;           ///< doubles a scalar run needs, callees' frames included
    int batchFrame = 0;            ///< doubles a batch run needs, callees' frames included
    int callDepth = 1;             ///< 1 + the deepest chain of calls below (before inlining)
    bool hostWrapper = false;      ///< this program only forwards its arguments to hosts[0]
    bool callsHost = false;        ///< it or a function it calls runs a host function
    std::shared_ptr<const Ir> inlineBody;  ///< the folded tree, kept when small enough to inline
};

}  // namespace rays::fn
