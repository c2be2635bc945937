// Expr → Ir: checks (arity, declared callees, members, parameter and iteration-variable numbers,
// POV-Ray's limits), constant folding and inlining, all in passes over the nodes in index order
// (children come first), so deep trees (`a+a+...+a`, 500,000 deep) need no recursion.
#include "rays/fn/compile.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <vector>

#include "rays/fn/internal_functions.h"
#include "rays/fn/ir.h"
#include "rays/fn/machine.h"
#include "rays/fn/ops.h"

namespace rays::fn {
namespace {

std::string plural(int n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

bool isUnary(Op op) { return opArity(op).min == 1 && opArity(op).max == 1; }
bool isBinary(Op op) { return opArity(op).min == 2 && opArity(op).max == 2; }

// ---- checks ----------------------------------------------------------------------------------

class Checker {
public:
    Checker(const Expr& e, int params, std::span<const std::shared_ptr<const Program>> callable)
        : e_(e), params_(params), callable_(callable) {}

    /// Which nodes the root reaches; throws on any broken rule.
    std::vector<char> run(int& callDepth) {
        if (params_ < 1 || params_ > kMaxParams)
            throw CompileError("a function takes 1 to " + std::to_string(kMaxParams) + " parameters, not " +
                                   std::to_string(params_), 0);
        const int n = static_cast<int>(e_.nodes.size());
        if (e_.root < 0 || e_.root >= n) throw CompileError("function body is empty", 0);
        std::vector<char> reach(n, 0);
        reach[e_.root] = 1;
        int reached = 0;
        for (int i = e_.root; i >= 0; --i) {
            if (!reach[i]) continue;
            ++reached;
            const Node& nd = e_.nodes[i];
            if (nd.first < 0 || nd.count < 0 || size_t(nd.first) + size_t(nd.count) > e_.kids.size())
                throw CompileError("malformed function tree", nd.loc);
            for (int32_t k : e_.children(nd)) {
                if (k < 0 || k >= i) throw CompileError("malformed function tree", nd.loc);
                reach[k] = 1;
            }
        }
        if (reached > kMaxNodes) throw CompileError("function too complex (more than " +
                                                    std::to_string(kMaxNodes) + " operators)", e_.nodes[e_.root].loc);
        // Bottom-up: free iteration variables (bit per slot) and sum/prod nesting.
        std::vector<uint64_t> freeLocals(n, 0);
        std::vector<uint8_t> nesting(n, 0);
        callDepth = 1;
        for (int i = 0; i < n; ++i) {
            if (!reach[i]) continue;
            const Node& nd = e_.nodes[i];
            checkNode(nd, callDepth);
            auto kids = e_.children(nd);
            uint64_t mask = 0;
            int depth = 0;
            for (int32_t k : kids) {
                mask |= freeLocals[k];
                depth = std::max<int>(depth, nesting[k]);
            }
            if (nd.op == Op::Local) mask = uint64_t(1) << nd.id;
            if (nd.op == Op::Sum || nd.op == Op::Prod) {
                const uint64_t own = uint64_t(1) << nd.id;
                mask = freeLocals[kids[0]] | ((freeLocals[kids[1]] | freeLocals[kids[2]]) & ~own);
                depth = std::max<int>(nesting[kids[0]], 1 + std::max(nesting[kids[1]], nesting[kids[2]]));
                if (depth > kMaxLocals)
                    throw CompileError("too many local variables: sum/prod nested deeper than " +
                                           std::to_string(kMaxLocals), nd.loc);
            }
            freeLocals[i] = mask;
            nesting[i] = static_cast<uint8_t>(depth);
        }
        if (freeLocals[e_.root] != 0) {
            for (int i = 0; i < n; ++i)
                if (reach[i] && e_.nodes[i].op == Op::Local)
                    throw CompileError("iteration variable used outside its sum/prod", e_.nodes[i].loc);
        }
        return reach;
    }

private:
    void checkNode(const Node& nd, int& callDepth) const {
        const Arity ar = opArity(nd.op);
        const std::string name(opName(nd.op));
        if (nd.count < ar.min || (ar.max >= 0 && nd.count > ar.max)) {
            std::string want = ar.max == ar.min ? std::to_string(ar.min)
                               : ar.max < 0     ? "at least " + std::to_string(ar.min)
                                                : std::to_string(ar.min) + " or " + std::to_string(ar.max);
            throw CompileError(name + " takes " + want + " argument" + (want == "1" ? "" : "s") + ", " +
                                   std::to_string(nd.count) + " given", nd.loc);
        }
        switch (nd.op) {
            case Op::Param:
                if (nd.id < 0 || nd.id >= params_)
                    throw CompileError("parameter " + std::to_string(nd.id) + " of a function of " +
                                           plural(params_, "parameter"), nd.loc);
                break;
            case Op::Local:
            case Op::Sum:
            case Op::Prod:
                if (nd.id < 0 || nd.id >= kMaxLocals)
                    throw CompileError("iteration variable slot " + std::to_string(nd.id) + " out of range 0.." +
                                           std::to_string(kMaxLocals - 1), nd.loc);
                break;
            case Op::Internal: {
                const InternalFunction* f = internalFunction(nd.id);
                if (!f) throw CompileError("internal(" + std::to_string(nd.id) + ") is not an internal function", nd.loc);
                if (nd.count != f->params)
                    throw CompileError(std::string(f->name) + " takes " + plural(f->params, "argument") + ", " +
                                           std::to_string(nd.count) + " given", nd.loc);
                break;
            }
            case Op::Call: {
                if (nd.id < 0 || size_t(nd.id) >= callable_.size() || !callable_[nd.id])
                    throw CompileError("call of a function not declared before this one (functions cannot call "
                                       "themselves or later functions)", nd.loc);
                const Program& c = *callable_[nd.id];
                if (nd.count != c.params)
                    throw CompileError("function takes " + plural(c.params, "argument") + ", " +
                                           std::to_string(nd.count) + " given", nd.loc);
                const bool vector = c.hostWrapper && c.outputs > 1;
                if (vector && nd.member == Member::None)
                    throw CompileError("a vector or colour function needs a member (.x, .y, .z, .red, ...)", nd.loc);
                if (!vector && nd.member != Member::None)
                    throw CompileError("a float function has no members", nd.loc);
                callDepth = std::max(callDepth, 1 + c.callDepth);
                if (callDepth > kMaxCallDepth)
                    throw CompileError("functions nested deeper than " + std::to_string(kMaxCallDepth), nd.loc);
                break;
            }
            default: break;
        }
    }

    const Expr& e_;
    int params_;
    std::span<const std::shared_ptr<const Program>> callable_;
};

// ---- lowering: folding and inlining -------------------------------------------------------------

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
            std::vector<double> values;
            for (int32_t a : args) values.push_back(ir.nodes[a].value);
            Scratch s(*callee);
            return constant(eval(*callee, values.data(), s), loc);
        }
        return make(irOp(Op::Call), args, calleeIndex(callee), member, 0, loc);
    }

private:
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
            case Op::Select:  // constant condition handled above
            case Op::Cond: return -1;
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

Ir lower(const Expr& e, const std::vector<char>& reach, std::span<const std::shared_ptr<const Program>> callable,
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

/// The tree without the nodes the root no longer reaches (after folding), for inlining.
std::shared_ptr<Ir> compact(const Ir& ir) {
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

}  // namespace

std::shared_ptr<const Program> compile(const Expr& body, int params,
                                       std::span<const std::shared_ptr<const Program>> callable,
                                       const CompileOptions& options) {
    int callDepth = 1;
    const std::vector<char> reach = Checker(body, params, callable).run(callDepth);
    Ir ir = lower(body, reach, callable, options);
    auto p = std::make_shared<Program>();
    p->params = params;
    p->callDepth = callDepth;
    p->callees = ir.callees;
    p->hosts = ir.hosts;
    emitProgram(ir, *p);
    std::shared_ptr<Ir> small = compact(ir);
    if (static_cast<int>(small->nodes.size()) <= options.inlineLimit) p->inlineBody = std::move(small);
    return p;
}

std::shared_ptr<const Program> hostProgram(const HostFunction& host) {
    if (!host.fn || host.inputs < 1 || host.inputs > kMaxParams || host.outputs < 1 || host.outputs > 5)
        throw CompileError("host function needs 1 to " + std::to_string(kMaxParams) + " inputs and 1 to 5 outputs", 0);
    Ir ir;
    ir.hosts.push_back(host);
    for (int i = 0; i < host.inputs; ++i) {
        IrNode n;
        n.op = irOp(Op::Param);
        n.id = i;
        n.cost = 0;
        ir.nodes.push_back(n);
        ir.kids.push_back(i);
    }
    IrNode call;
    call.op = IrOp::Host;
    call.id = 0;
    call.member = Member::X;
    call.first = 0;
    call.count = host.inputs;
    ir.nodes.push_back(call);
    ir.root = host.inputs;
    auto p = std::make_shared<Program>();
    p->params = host.inputs;
    p->outputs = host.outputs;
    p->hosts = ir.hosts;
    p->hostWrapper = true;
    emitProgram(ir, *p);
    return p;
}

}  // namespace rays::fn
