// Expr → Ir: constant folding (the same ops::unary/binary code the machine runs, so folded
// values are the machine's) and inlining of small callees, in one pass over the nodes in index
// order (children come first).
#include "rays/fn/lower.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "rays/fn/internal_functions.h"
#include "rays/fn/machine.h"
#include "rays/fn/ops.h"

namespace rays::fn {
namespace {

// Loop repetitions and calls a folded call may run (more: the call stays).
constexpr uint64_t kFoldBudget = 10000;

bool isUnary(Op op) { return opArity(op).min == 1 && opArity(op).max == 1; }
bool isBinary(Op op) { return opArity(op).min == 2 && opArity(op).max == 2; }

bool pureFoldable(IrOp op) {
    return static_cast<int>(op) <= static_cast<int>(Op::Internal) && op != irOp(Op::Call) &&
           op != irOp(Op::Param) && op != irOp(Op::Local);
}

class Lowerer {
public:
    Lowerer(const CompileOptions& o) : opt_(o) {}

    Ir ir;

    /// A node with the given children, folded when they allow it; returns its index (which may
    /// be a child's or an existing node's).
    int32_t make(IrOp op, std::span<const int32_t> kids, int32_t id = 0, Member member = Member::None,
                 double value = 0, int32_t loc = 0) {
        if (opt_.fold) {
            int32_t folded = fold(op, kids, id, loc);
            if (folded >= 0) return folded;
        }
        if (op == irOp(Op::Degrees) || op == irOp(Op::Radians)) {
            // a·(180/π) exactly as ops::unary computes it; a multiply the emitter fuses.
            const double k = op == irOp(Op::Degrees) ? ops::kDegreesPerRadian : ops::kRadiansPerDegree;
            const int32_t two[2] = {kids[0], constant(k, loc)};
            return make(irOp(Op::Mul), two, 0, Member::None, 0, loc);
        }
        IrNode n;
        n.op = op;
        n.member = member;
        n.id = id;
        n.value = value;
        n.loc = loc;
        n.first = static_cast<int32_t>(ir.kids.size());
        n.count = static_cast<int32_t>(kids.size());
        n.loops = op == irOp(Op::Sum) || op == irOp(Op::Prod);
        int64_t cost = 1;
        for (int32_t k : kids) {
            cost += ir.nodes[k].cost;
            n.loops = n.loops || ir.nodes[k].loops;
        }
        if (op == irOp(Op::Call) || op == irOp(Op::Internal) || op == IrOp::Host) cost += 20;
        if (n.loops) cost += 50;
        n.cost = static_cast<int32_t>(std::min<int64_t>(cost, 1 << 30));
        ir.kids.insert(ir.kids.end(), kids.begin(), kids.end());
        ir.nodes.push_back(n);
        return static_cast<int32_t>(ir.nodes.size()) - 1;
    }

    int32_t constant(double v, int32_t loc = 0) {
        IrNode n;
        n.op = irOp(Op::Const);
        n.value = v;
        n.loc = loc;
        n.cost = 0;
        n.first = static_cast<int32_t>(ir.kids.size());
        ir.nodes.push_back(n);
        return static_cast<int32_t>(ir.nodes.size()) - 1;
    }

    int32_t leaf(IrOp op, int32_t id, int32_t loc) {
        IrNode n;
        n.op = op;
        n.id = id;
        n.loc = loc;
        n.cost = 0;
        n.first = static_cast<int32_t>(ir.kids.size());
        ir.nodes.push_back(n);
        return static_cast<int32_t>(ir.nodes.size()) - 1;
    }

    /// Index of `p` in ir.callees (added when new).
    int32_t calleeIndex(const std::shared_ptr<const Program>& p) {
        for (size_t i = 0; i < ir.callees.size(); ++i)
            if (ir.callees[i] == p) return static_cast<int32_t>(i);
        ir.callees.push_back(p);
        return static_cast<int32_t>(ir.callees.size()) - 1;
    }
    int32_t hostIndex(const HostFunction& h) {
        for (size_t i = 0; i < ir.hosts.size(); ++i)
            if (ir.hosts[i].fn == h.fn && ir.hosts[i].data == h.data) return static_cast<int32_t>(i);
        ir.hosts.push_back(h);
        return static_cast<int32_t>(ir.hosts.size()) - 1;
    }

    /// A call of `callee` with lowered arguments `args`.
    int32_t call(const std::shared_ptr<const Program>& callee, std::span<const int32_t> args, Member member,
                 int32_t loc) {
        if (callee->hostWrapper) {
            return make(IrOp::Host, args, hostIndex(callee->hosts[0]), member, 0, loc);
        }
        if (opt_.inlineCalls && callee->inlineBody) return inlineCall(*callee->inlineBody, args, loc);
        if (opt_.fold && allConst(args)) {
            const int32_t folded = foldCall(*callee, args, loc);
            if (folded >= 0) return folded;
        }
        return make(irOp(Op::Call), args, calleeIndex(callee), member, 0, loc);
    }

private:
    /// The value of `callee` at constant `args`, run now; -1 when it runs a host function (whose
    /// value may not be known yet: pattern functions give 0 while parsing) or when its loops and
    /// calls exceed kFoldBudget (the compile runs under no parse loop limit).
    int32_t foldCall(const Program& callee, std::span<const int32_t> args, int32_t loc) {
        if (callee.callsHost) return -1;
        std::vector<double> values;
        for (int32_t a : args) values.push_back(ir.nodes[a].value);
        Scratch s(callee);
        LoopBudget budget(kFoldBudget);
        try {
            return constant(eval(callee, values.data(), s), loc);
        } catch (const LoopBudgetExceeded&) {
            return -1;
        }
    }

    bool allConst(std::span<const int32_t> kids) const {
        return std::all_of(kids.begin(), kids.end(), [&](int32_t k) { return ir.isConst(k); });
    }

    int32_t fold(IrOp op, std::span<const int32_t> kids, int32_t id, int32_t loc) {
        const auto val = [&](size_t i) { return ir.nodes[kids[i]].value; };
        const auto isK = [&](size_t i, double v) {
            return ir.isConst(kids[i]) && val(i) == v && !std::signbit(val(i)) == !std::signbit(v);
        };
        const Op o = static_cast<Op>(op);
        if (op == irOp(Op::Select) && ir.isConst(kids[0])) {
            const double a = val(0);
            if (kids.size() == 3) return a < 0 ? kids[1] : kids[2];
            return a < 0 ? kids[1] : (a == 0 ? kids[2] : kids[3]);
        }
        if (op == irOp(Op::Cond) && ir.isConst(kids[0])) return val(0) != 0 ? kids[1] : kids[2];
        // Exact identities: x*1, 1*x, x/1, x-(+0), -(-x).
        if (op == irOp(Op::Mul) && isK(1, 1.0)) return kids[0];
        if (op == irOp(Op::Mul) && isK(0, 1.0)) return kids[1];
        if (op == irOp(Op::Div) && isK(1, 1.0)) return kids[0];
        if (op == irOp(Op::Sub) && isK(1, 0.0)) return kids[0];
        if (op == irOp(Op::Neg) && ir.nodes[kids[0]].op == irOp(Op::Neg)) return ir.children(ir.nodes[kids[0]])[0];
        if (!pureFoldable(op) || op == irOp(Op::Sum) || op == irOp(Op::Prod) || !allConst(kids)) {
            if ((op == irOp(Op::Sum) || op == irOp(Op::Prod)) && allConst(kids)) return foldSequence(op, kids, loc);
            return -1;
        }
        if (isUnary(o)) return constant(ops::unary(o, val(0)), loc);
        if (isBinary(o)) return constant(ops::binary(o, val(0), val(1)), loc);
        switch (o) {
            case Op::Max:
            case Op::Min: {
                double r = val(0);
                for (size_t i = 1; i < kids.size(); ++i) r = ops::binary(o, r, val(i));
                return constant(r, loc);
            }
            case Op::Internal: {
                double args[kMaxParams + 16];
                for (size_t i = 0; i < kids.size(); ++i) args[i] = val(i);
                return constant(internalFunction(id)->fn(args), loc);
            }
            default: return -1;
        }
    }

    // sum/prod with constant bounds and a body that does not depend on the variable.
    int32_t foldSequence(IrOp op, std::span<const int32_t> kids, int32_t loc) {
        const double from = ir.nodes[kids[0]].value, to = ir.nodes[kids[1]].value, body = ir.nodes[kids[2]].value;
        const bool sum = op == irOp(Op::Sum);
        double acc = sum ? 0.0 : 1.0;
        int steps = 0;
        for (double i = from; i <= to; i += 1) {
            if (++steps > 1000000) return -1;
            acc = sum ? acc + body : acc * body;
        }
        return constant(acc, loc);
    }

    /// Copies the callee's folded tree into ir with its parameters replaced by `args`.
    int32_t inlineCall(const Ir& body, std::span<const int32_t> args, int32_t loc) {
        // Parameters the body uses.
        std::vector<char> used(args.size(), 0);
        for (const IrNode& n : body.nodes)
            if (n.op == irOp(Op::Param)) used[n.id] = 1;
        // Arguments that are leaves are substituted; others are evaluated once (Let).
        std::vector<int32_t> subst(args.size(), -1), bindValues;
        const int32_t paramBase = ir.boundIds;
        for (size_t p = 0; p < args.size(); ++p) {
            if (!used[p]) continue;
            const IrOp a = ir.nodes[args[p]].op;
            if (a == irOp(Op::Const) || a == irOp(Op::Param) || a == IrOp::Bound) {
                subst[p] = args[p];
            } else {
                subst[p] = leaf(IrOp::Bound, ir.boundIds++, loc);
                bindValues.push_back(args[p]);
            }
        }
        const int32_t boundBase = ir.boundIds;
        ir.boundIds += body.boundIds;
        std::vector<int32_t> map(body.nodes.size(), -1);
        std::vector<int32_t> kids;
        for (size_t i = 0; i < body.nodes.size(); ++i) {
            const IrNode& n = body.nodes[i];
            kids.clear();
            for (int32_t k : body.children(n)) kids.push_back(map[k]);
            switch (n.op) {
                case IrOp::Bound: map[i] = leaf(IrOp::Bound, n.id + boundBase, n.loc); break;
                case IrOp::Let: map[i] = make(IrOp::Let, kids, n.id + boundBase, Member::None, 0, n.loc); break;
                case IrOp::Host: map[i] = make(IrOp::Host, kids, hostIndex(body.hosts[n.id]), n.member, 0, n.loc); break;
                default:
                    if (n.op == irOp(Op::Param)) map[i] = subst[n.id];
                    else if (n.op == irOp(Op::Const)) map[i] = constant(n.value, n.loc);
                    else if (n.op == irOp(Op::Local)) map[i] = leaf(n.op, n.id, n.loc);
                    else if (n.op == irOp(Op::Call)) map[i] = call(body.callees[n.id], kids, n.member, n.loc);
                    else map[i] = make(n.op, kids, n.id, n.member, n.value, n.loc);
            }
        }
        int32_t result = map[body.root];
        if (bindValues.empty()) return result;
        bindValues.push_back(result);
        return make(IrOp::Let, bindValues, paramBase, Member::None, 0, loc);
    }

    CompileOptions opt_;
};

}  // namespace

Ir lowerExpr(const Expr& e, const std::vector<char>& reach, std::span<const std::shared_ptr<const Program>> callable,
             const CompileOptions& opt) {
    Lowerer lw(opt);
    std::vector<int32_t> map(e.nodes.size(), -1);
    std::vector<int32_t> kids;
    for (size_t i = 0; i < e.nodes.size(); ++i) {
        if (!reach[i]) continue;
        const Node& n = e.nodes[i];
        kids.clear();
        for (int32_t k : e.children(n)) kids.push_back(map[k]);
        switch (n.op) {
            case Op::Const: map[i] = lw.constant(n.value, n.loc); break;
            case Op::Param:
            case Op::Local: map[i] = lw.leaf(irOp(n.op), n.id, n.loc); break;
            case Op::Call: map[i] = lw.call(callable[n.id], kids, n.member, n.loc); break;
            default: map[i] = lw.make(irOp(n.op), kids, n.id, n.member, n.value, n.loc);
        }
    }
    lw.ir.root = map[e.root];
    return std::move(lw.ir);
}

std::shared_ptr<Ir> compactIr(const Ir& ir) {
    std::vector<char> reach(ir.nodes.size(), 0);
    reach[ir.root] = 1;
    for (int32_t i = ir.root; i >= 0; --i)
        if (reach[i])
            for (int32_t k : ir.children(ir.nodes[i])) reach[k] = 1;
    auto out = std::make_shared<Ir>();
    out->boundIds = ir.boundIds;
    out->callees = ir.callees;
    out->hosts = ir.hosts;
    std::vector<int32_t> map(ir.nodes.size(), -1);
    for (size_t i = 0; i < ir.nodes.size(); ++i) {
        if (!reach[i]) continue;
        IrNode n = ir.nodes[i];
        auto kids = ir.children(ir.nodes[i]);
        n.first = static_cast<int32_t>(out->kids.size());
        for (int32_t k : kids) out->kids.push_back(map[k]);
        map[i] = static_cast<int32_t>(out->nodes.size());
        out->nodes.push_back(n);
    }
    out->root = map[ir.root];
    return out;
}

}  // namespace rays::fn
