// Expr checks, in passes over the nodes in index order (children come first), so deep trees
// (`a+a+...+a`, 500,000 deep) need no recursion.
#include "rays/fn/check.h"

#include <algorithm>
#include <string>

#include "rays/fn/compile.h"
#include "rays/fn/internal_functions.h"

namespace rays::fn {
namespace {

std::string plural(int n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

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

}  // namespace

std::vector<char> checkExpr(const Expr& e, int params, std::span<const std::shared_ptr<const Program>> callable,
                            int& callDepth) {
    return Checker(e, params, callable).run(callDepth);
}

}  // namespace rays::fn
