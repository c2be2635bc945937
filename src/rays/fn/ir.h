// The compiler's own tree (fn/lower.cpp builds it from an Expr, fn/emit.cpp turns it into
// machine code): an Expr after validation, constant folding and inlining. Same layout as Expr
// (children before parents), plus two ops for inlined calls: Let evaluates its leading children
// once and binds them to Bound ids for its last child, the inlined body.
#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "rays/fn/expr.h"
#include "rays/fn/program.h"

namespace rays::fn {

enum class IrOp : uint8_t {
    // Values 0 .. Op::Internal are the Op values of expr.h; Call's id names Ir::callees.
    Let = 100,  ///< children: n values, then the body; binds Bound ids id .. id+n-1
    Bound,      ///< the value bound to Bound id `id` by the enclosing Let
    Host,       ///< a host function's member: id names Ir::hosts, children are the arguments
};

inline IrOp irOp(Op op) { return static_cast<IrOp>(op); }

struct IrNode {
    IrOp op = IrOp::Let;
    Member member = Member::None;
    bool loops = false;    ///< a Sum/Prod in this subtree
    int32_t id = 0;
    int32_t first = 0, count = 0;
    double value = 0;
    int32_t loc = 0;
    int32_t cost = 1;      ///< rough instruction count of the subtree (calls count extra)
};

struct Ir {
    std::vector<IrNode> nodes;
    std::vector<int32_t> kids;
    int32_t root = -1;
    int32_t boundIds = 0;  ///< Bound ids used: 0 .. boundIds-1
    std::vector<std::shared_ptr<const Program>> callees;
    std::vector<HostFunction> hosts;

    std::span<const int32_t> children(const IrNode& n) const {
        return {kids.data() + n.first, static_cast<size_t>(n.count)};
    }
    bool isConst(int32_t i) const { return nodes[i].op == irOp(Op::Const); }
};

/// Builds the machine code of `ir` into `p` (code, batch, pool, lists, register counts); `p`
/// already holds params, callees and hosts. With `branches`, scalar code jumps around expensive
/// select/?: arms. Throws CompileError when a frame needs more than 65535 registers.
void emitProgram(const Ir& ir, Program& p, bool branches);

}  // namespace rays::fn
