// Ir → register-machine code (fn/program.h). A walk with an explicit stack (trees may be 500,000
// deep), registers handed out and taken back in stack order, constants kept in the instructions
// (AddK, MulK, ...) or in the pool, a multiply feeding an add fused into MulAdd/MulSub.
// Two forms: scalar code may jump around expensive select/?: arms and loops for sum/prod; batch
// code is branch-free and never writes a register it reads in the same instruction, so the
// machine's lane loops can use restrict pointers (a tree with a sum/prod gets no batch code).
#include <algorithm>
#include <bit>
#include <string>
#include <unordered_map>

#include "rays/fn/compile.h"
#include "rays/fn/ir.h"

namespace rays::fn {
namespace {

// Virtual registers while emitting: parameters as themselves, temporaries and pool entries in
// their own ranges; renumbered once their counts are known.
constexpr int32_t kTempBase = 1 << 24;
constexpr int32_t kPoolBase = 2 << 24;
constexpr int32_t kBranchCost = 6;  // arms costing more than this are jumped around (scalar code)

struct VInstr {
    Code op = Code::Ret;
    int32_t d = 0, a = 0, b = 0, c = 0;
    uint32_t aux = 0;
    uint32_t list = 0;
    double k = 0;
};

struct Operand {
    int32_t reg = -1;
    double k = 0;
    bool isConst = false;
    bool temp = false;  ///< the consumer frees the register
    int32_t def = -1;   ///< the instruction that wrote this temporary, when fusable
};

Operand constOperand(double k) {
    Operand o;
    o.isConst = true;
    o.k = k;
    return o;
}
Operand regOperand(int32_t reg, bool temp, int32_t def = -1) {
    Operand o;
    o.reg = reg;
    o.temp = temp;
    o.def = def;
    return o;
}

// The instruction of a one-child op (Ret for ops without one).
Code unaryCode(Op op) {
    switch (op) {
#define RAYS_FN_CODE_CASE(name, expr) \
    case Op::name: return Code::name;
        RAYS_FN_UNARY_OPS(RAYS_FN_CODE_CASE)
        default: return Code::Ret;
    }
}

// The instruction of a two-child op (Max/Min: of two values).
Code binaryCode(Op op) {
    switch (op) {
        RAYS_FN_BINARY_OPS(RAYS_FN_CODE_CASE)
#undef RAYS_FN_CODE_CASE
        default: return Code::Ret;
    }
}

class Emitter {
public:
    Emitter(const Ir& ir, bool batch, bool branches)
        : ir_(ir), batch_(batch), branches_(branches && !batch), bound_(ir.boundIds) {}

    std::vector<VInstr> code;
    std::vector<int32_t> lists;
    std::vector<double> pool;
    int32_t temps = 0;

    void run() {
        Operand r = tree(ir_.root);
        VInstr ret;
        ret.op = Code::Ret;
        ret.a = reg(r);
        code.push_back(ret);
    }

private:
    struct Frame {
        int32_t node;
        int32_t stage = 0;
        int32_t x[6] = {0, 0, 0, 0, 0, 0};  // per-op state (registers, jumps to patch)
    };

    // ---- registers ----
    int32_t newTemp() {
        if (!free_.empty()) {
            int32_t r = free_.back();
            free_.pop_back();
            return r;
        }
        return kTempBase + temps++;
    }
    void release(const Operand& o) {
        if (o.temp) free_.push_back(o.reg);
    }
    int32_t poolReg(double k) {
        const uint64_t bits = std::bit_cast<uint64_t>(k);
        auto it = poolIndex_.find(bits);
        if (it != poolIndex_.end()) return it->second;
        const int32_t r = kPoolBase + static_cast<int32_t>(pool.size());
        pool.push_back(k);
        poolIndex_.emplace(bits, r);
        return r;
    }
    int32_t reg(const Operand& o) { return o.isConst ? poolReg(o.k) : o.reg; }

    /// The destination of an instruction reading `ins`, whose temporaries are released: `into`
    /// when given, else a new temporary, which in scalar code may reuse an operand's register and
    /// in batch code never does.
    int32_t dest(std::span<const Operand* const> ins, int32_t into = -1) {
        const int32_t d = into < 0 && batch_ ? newTemp() : into;
        for (const Operand* o : ins) release(*o);
        return d >= 0 ? d : newTemp();
    }
    int32_t dest(std::initializer_list<const Operand*> ins, int32_t into = -1) {
        return dest(std::span<const Operand* const>(ins.begin(), ins.size()), into);
    }

    int32_t push(const VInstr& v) {
        code.push_back(v);
        return static_cast<int32_t>(code.size()) - 1;
    }
    VInstr instr(Code op, int32_t d, int32_t a = 0, int32_t b = 0, int32_t c = 0) {
        VInstr v;
        v.op = op;
        v.d = d;
        v.a = a;
        v.b = b;
        v.c = c;
        return v;
    }

    /// Writes `v` into register d (Mov or Const).
    void moveTo(int32_t d, const Operand& v) {
        if (v.isConst) {
            VInstr c = instr(Code::Const, d);
            c.k = v.k;
            push(c);
        } else if (v.reg != d) {
            push(instr(Code::Mov, d, v.reg));
        }
    }

    Operand unary(Op op, const Operand& a) {
        const int32_t ra = reg(a);
        const int32_t d = dest({&a});
        return regOperand(d, true, push(instr(unaryCode(op), d, ra)));
    }

    // a*b from the instruction just emitted, if `o` is its only use.
    bool fusableMul(const Operand& o) const {
        return o.temp && o.def >= 0 && o.def == static_cast<int32_t>(code.size()) - 1 && code[o.def].op == Code::Mul;
    }

    /// a op b into a new temporary, or into `into` when it is given (sum/prod accumulators).
    Operand binary(Op op, const Operand& a, const Operand& b, int32_t into = -1) {
        // Fused multiply-add: (p*q) + b, a + (p*q), (p*q) - b; same rounding as the separate ops.
        const Operand* m = (op == Op::Add || op == Op::Sub) && fusableMul(a) ? &a
                           : op == Op::Add && fusableMul(b)                  ? &b
                                                                             : nullptr;
        if (m) {
            const Operand& other = m == &a ? b : a;
            const int32_t rc = reg(other);
            const VInstr mul = code[m->def];
            const int32_t d = dest({m, &other}, into);
            if (batch_ && (d == mul.a || d == mul.b || d == rc)) {
                // A fresh batch register that aliases the multiply's operands: keep them apart.
                VInstr plain = instr(binaryCode(op), d, m == &a ? m->reg : rc, m == &a ? rc : m->reg);
                push(plain);
                return regOperand(d, into < 0);
            }
            VInstr& f = code[m->def];
            f.op = op == Op::Add ? Code::MulAdd : Code::MulSub;
            f.d = d;
            f.c = rc;
            return regOperand(d, into < 0);
        }
        Code code = binaryCode(op);
        bool withK = false;
        double k = 0;
        int32_t ra = 0, rb = 0;
        if (b.isConst && !a.isConst) {
            withK = true;
            k = b.k;
            ra = a.reg;
            switch (op) {
                case Op::Add: code = Code::AddK; break;
                case Op::Sub: code = Code::SubK; break;
                case Op::Mul: code = Code::MulK; break;
                case Op::Div: code = Code::DivK; break;
                case Op::Max: code = Code::MaxK; break;
                case Op::Min: code = Code::MinK; break;
                case Op::Pow: code = k == 2.0 ? Code::Sqr : Code::PowK; break;
                default: withK = false;
            }
        } else if (a.isConst && !b.isConst) {
            withK = true;
            k = a.k;
            ra = b.reg;
            switch (op) {
                case Op::Add: code = Code::AddK; break;
                case Op::Sub: code = Code::KSub; break;
                case Op::Mul: code = Code::MulK; break;
                case Op::Div: code = Code::KDiv; break;
                case Op::Max: code = Code::KMax; break;
                case Op::Min: code = Code::KMin; break;
                default: withK = false;
            }
        }
        if (!withK) {
            ra = reg(a);
            rb = reg(b);
        }
        const int32_t d = dest({&a, &b}, into);
        VInstr v = instr(code, d, ra, rb);
        v.k = k;
        const int32_t at = push(v);
        return regOperand(d, into < 0, (code == Code::Mul && into < 0) ? at : -1);
    }

    Operand nary(Op op, std::span<const Operand> in) {
        if (op == Op::Max || op == Op::Min) {
            Operand acc = binary(op, in[0], in[1]);
            for (size_t i = 2; i < in.size(); ++i) acc = binary(op, acc, in[i]);
            return acc;
        }
        if (op == Op::Select || op == Op::Cond) {
            int32_t r[4];
            const Operand* ins[4];
            for (size_t i = 0; i < in.size(); ++i) {
                r[i] = reg(in[i]);
                ins[i] = &in[i];
            }
            const int32_t d = dest(std::span<const Operand* const>(ins, in.size()));
            VInstr v = instr(op == Op::Cond ? Code::Cond : in.size() == 3 ? Code::Select3 : Code::Select4, d, r[0],
                             r[1], r[2]);
            if (in.size() == 4) v.aux = static_cast<uint32_t>(r[3]);
            push(v);
            return regOperand(d, true);
        }
        return {};
    }

    Operand callLike(const IrNode& n, std::span<const Operand> in) {
        VInstr v;
        v.list = static_cast<uint32_t>(lists.size());
        for (const Operand& o : in) lists.push_back(reg(o));
        v.c = static_cast<int32_t>(in.size());
        v.aux = static_cast<uint32_t>(n.id);
        if (n.op == IrOp::Host) {
            v.op = Code::Host;
            v.b = static_cast<int32_t>(n.member);
        } else {
            v.op = n.op == irOp(Op::Call) ? Code::Call : Code::Internal;
        }
        // The machine gathers all arguments before writing d, so d may reuse one (scalar code);
        // batch lanes are gathered the same way, so reuse is safe there too.
        for (const Operand& o : in) release(o);
        v.d = newTemp();
        push(v);
        return regOperand(v.d, true);
    }

    // ---- the walk ----
    Operand tree(int32_t root) {
        std::vector<Frame> stack;
        std::vector<Operand> vals;
        std::vector<int32_t> owned;  // Let-bound registers to free when the Let ends
        stack.push_back({root});
        while (!stack.empty()) {
            const int32_t node = stack.back().node;
            const IrNode& n = ir_.nodes[node];
            const auto kids = ir_.children(n);
            const int32_t stage = stack.back().stage;
            const Op op = static_cast<Op>(n.op);
            if (n.count == 0 && n.op != irOp(Op::Call) && n.op != irOp(Op::Internal) && n.op != IrOp::Host) {
                vals.push_back(leaf(n));
                stack.pop_back();
                continue;
            }
            if (n.op == irOp(Op::Sum) || n.op == irOp(Op::Prod)) {
                sequenceStage(stack, vals);
                continue;
            }
            if (n.op == IrOp::Let) {
                letStage(stack, vals, owned);
                continue;
            }
            if ((op == Op::Cond || op == Op::Select) && branches_ && jumpWorthy(n)) {
                branchStage(stack, vals);
                continue;
            }
            if (stage < n.count) {
                stack.back().stage++;
                stack.push_back({kids[stage]});
                continue;
            }
            std::vector<Operand> in(vals.end() - n.count, vals.end());
            vals.resize(vals.size() - n.count);
            stack.pop_back();
            vals.push_back(combine(n, in));
        }
        return vals.back();
    }

    Operand leaf(const IrNode& n) {
        if (n.op == IrOp::Bound) {
            Operand o = bound_[n.id];
            o.temp = false;
            o.def = -1;
            return o;
        }
        const Op op = static_cast<Op>(n.op);
        if (op == Op::Const) return constOperand(n.value);
        if (op == Op::Param) return regOperand(n.id, false);
        if (op == Op::Local) return regOperand(locals_[n.id].back(), false);
        return constOperand(0);
    }

    Operand combine(const IrNode& n, std::span<const Operand> in) {
        if (n.op == IrOp::Host || n.op == irOp(Op::Call) || n.op == irOp(Op::Internal)) return callLike(n, in);
        const Op op = static_cast<Op>(n.op);
        const Arity ar = opArity(op);
        if (ar.min == 1 && ar.max == 1) return unary(op, in[0]);
        if (ar.min == 2 && ar.max == 2) return binary(op, in[0], in[1]);
        return nary(op, in);
    }

    bool jumpWorthy(const IrNode& n) const {
        const auto kids = ir_.children(n);
        for (size_t i = 1; i < kids.size(); ++i) {
            const IrNode& k = ir_.nodes[kids[i]];
            if (k.cost > kBranchCost || k.loops) return true;
        }
        return false;
    }

    // sum/prod: i = from; end = to; acc = 0|1; while (i <= end) { acc op= body; i += 1; }
    void sequenceStage(std::vector<Frame>& stack, std::vector<Operand>& vals) {
        Frame& f = stack.back();
        const IrNode& n = ir_.nodes[f.node];
        const auto kids = ir_.children(n);
        const bool sum = n.op == irOp(Op::Sum);
        switch (f.stage) {
            case 0:
                f.stage = 1;
                stack.push_back({kids[0]});
                return;
            case 1: {
                Operand from = vals.back();
                vals.pop_back();
                const int32_t i = newTemp();
                moveTo(i, from);
                release(from);
                locals_[n.id].push_back(i);
                f.x[0] = i;
                f.stage = 2;
                stack.push_back({kids[1]});
                return;
            }
            case 2: {
                Operand to = vals.back();
                vals.pop_back();
                const int32_t end = newTemp();
                moveTo(end, to);
                release(to);
                const int32_t acc = newTemp();
                moveTo(acc, constOperand(sum ? 0.0 : 1.0));
                f.x[1] = end;
                f.x[2] = acc;
                f.x[3] = push(instr(Code::JumpIfNotLe, 0, f.x[0], end));
                f.stage = 3;
                stack.push_back({kids[2]});
                return;
            }
            default: {
                Operand body = vals.back();
                vals.pop_back();
                const int32_t i = f.x[0], end = f.x[1], acc = f.x[2], test = f.x[3];
                binary(sum ? Op::Add : Op::Mul, regOperand(acc, false), body, acc);
                VInstr step = instr(Code::AddK, i, i);
                step.k = 1;
                push(step);
                VInstr back = instr(Code::Jump, 0);
                back.aux = static_cast<uint32_t>(test);
                push(back);
                code[test].aux = static_cast<uint32_t>(code.size());
                locals_[n.id].pop_back();
                free_.push_back(i);
                free_.push_back(end);
                stack.pop_back();
                vals.push_back(regOperand(acc, true));
            }
        }
    }

    // Let: evaluate the values, bind them, evaluate the body, free what was bound.
    void letStage(std::vector<Frame>& stack, std::vector<Operand>& vals, std::vector<int32_t>& owned) {
        Frame& f = stack.back();
        const IrNode& n = ir_.nodes[f.node];
        const auto kids = ir_.children(n);
        const int32_t values = n.count - 1;
        if (f.stage < values) {
            stack.push_back({kids[f.stage++]});
            return;
        }
        if (f.stage == values) {
            f.x[0] = static_cast<int32_t>(owned.size());
            for (int32_t j = 0; j < values; ++j) {
                Operand v = vals[vals.size() - values + j];
                if (v.temp) owned.push_back(v.reg);
                v.temp = false;
                v.def = -1;
                bound_[n.id + j] = v;
            }
            vals.resize(vals.size() - values);
            f.stage++;
            stack.push_back({kids[values]});
            return;
        }
        Operand body = vals.back();
        vals.pop_back();
        for (size_t j = static_cast<size_t>(f.x[0]); j < owned.size(); ++j) {
            if (!body.isConst && body.reg == owned[j] && !body.temp) {
                body.temp = true;  // the body is a bound value: its register passes to the consumer
                body.def = -1;
            } else {
                free_.push_back(owned[j]);
            }
        }
        owned.resize(static_cast<size_t>(f.x[0]));
        stack.pop_back();
        vals.push_back(body);
    }

    // ?: and select with jumps: test, arm, jump to the end, next test, ...
    void branchStage(std::vector<Frame>& stack, std::vector<Operand>& vals) {
        Frame& f = stack.back();
        const IrNode& n = ir_.nodes[f.node];
        const auto kids = ir_.children(n);
        const bool cond = static_cast<Op>(n.op) == Op::Cond;
        // x[0] result register, x[1] test register, x[2] test is a temporary, x[3] pending test
        // jump, x[4] x[5] jumps to the end.
        if (f.stage == 0) {
            f.stage = 1;
            stack.push_back({kids[0]});
            return;
        }
        auto takeArm = [&]() {
            Operand v = vals.back();
            vals.pop_back();
            moveTo(f.x[0], v);
            release(v);
        };
        auto jumpHere = [&](int32_t at) { code[at].aux = static_cast<uint32_t>(code.size()); };
        auto jumpToEnd = [&]() {
            VInstr j = instr(Code::Jump, 0);
            return push(j);
        };
        if (f.stage == 1) {
            Operand t = vals.back();
            vals.pop_back();
            f.x[1] = reg(t);
            f.x[2] = t.temp ? 1 : 0;
            f.x[0] = newTemp();
            f.x[3] = push(instr(cond ? Code::JumpIfZero : Code::JumpIfNotNeg, 0, f.x[1]));
            if (cond || n.count == 3) {
                if (f.x[2]) free_.push_back(f.x[1]);
                f.x[2] = 0;
            }
            f.stage = 2;
            stack.push_back({kids[1]});
            return;
        }
        if (f.stage == 2) {
            takeArm();
            f.x[4] = jumpToEnd();
            jumpHere(f.x[3]);
            if (n.count == 4) {
                f.x[3] = push(instr(Code::JumpIfNotZero, 0, f.x[1]));
                if (f.x[2]) free_.push_back(f.x[1]);
            }
            f.stage = 3;
            stack.push_back({kids[2]});
            return;
        }
        if (f.stage == 3 && n.count == 4) {
            takeArm();
            f.x[5] = jumpToEnd();
            jumpHere(f.x[3]);
            f.stage = 4;
            stack.push_back({kids[3]});
            return;
        }
        takeArm();
        jumpHere(f.x[4]);
        if (n.count == 4) jumpHere(f.x[5]);
        const int32_t result = f.x[0];
        stack.pop_back();
        vals.push_back(regOperand(result, true));
    }

    const Ir& ir_;
    bool batch_;
    bool branches_;
    std::vector<int32_t> free_;
    std::unordered_map<uint64_t, int32_t> poolIndex_;
    std::vector<int32_t> locals_[kMaxLocals];
    std::vector<Operand> bound_;
};

/// Final register numbers: parameters, pool, temporaries.
struct Numbering {
    int32_t params, pool;
    int32_t operator()(int32_t v) const {
        if (v >= kPoolBase) return params + (v - kPoolBase);
        if (v >= kTempBase) return params + pool + (v - kTempBase);
        return v;
    }
};

bool cIsRegister(Code op) {
    return op == Code::MulAdd || op == Code::MulSub || op == Code::Select3 || op == Code::Select4 || op == Code::Cond;
}

int finish(const Emitter& e, int params, std::vector<Instr>& out, std::vector<double>& pool,
           std::vector<uint16_t>& lists) {
    const Numbering num{params, static_cast<int32_t>(e.pool.size())};
    const int64_t registers = int64_t(params) + int64_t(e.pool.size()) + e.temps;
    if (registers > 65535) throw CompileError("function too complex (needs more than 65535 registers)", 0);
    const size_t listBase = lists.size();
    for (int32_t r : e.lists) lists.push_back(static_cast<uint16_t>(num(r)));
    out.clear();
    for (const VInstr& v : e.code) {
        Instr in;
        in.op = v.op;
        in.d = static_cast<uint16_t>(num(v.d));
        in.a = static_cast<uint16_t>(num(v.a));
        const bool listed = v.op == Code::Call || v.op == Code::Host || v.op == Code::Internal;
        in.b = static_cast<uint16_t>(v.op == Code::Host ? v.b : num(v.b));
        in.c = static_cast<uint16_t>(cIsRegister(v.op) ? num(v.c) : v.c);
        in.aux = v.op == Code::Select4 ? static_cast<uint32_t>(num(static_cast<int32_t>(v.aux))) : v.aux;
        if (listed) in.list = static_cast<uint32_t>(listBase + v.list);
        else in.k = v.k;
        out.push_back(in);
    }
    pool = e.pool;
    return static_cast<int>(registers);
}

}  // namespace

void emitProgram(const Ir& ir, Program& p, bool branches) {
    p.lists.clear();
    Emitter scalar(ir, false, branches);
    scalar.run();
    p.registers = finish(scalar, p.params, p.code, p.pool, p.lists);
    p.batch.clear();
    p.batchPool.clear();
    p.batchRegisters = 0;
    if (!ir.nodes[ir.root].loops) {
        Emitter batch(ir, true, false);
        batch.run();
        p.batchRegisters = finish(batch, p.params, p.batch, p.batchPool, p.lists);
    }
    int scalarCallees = 0, batchCallees = 0;
    for (const auto& c : p.callees) {
        scalarCallees = std::max(scalarCallees, c->scalarFrame);
        batchCallees = std::max(batchCallees, c->batchFrame);
    }
    p.scalarFrame = p.registers + scalarCallees;
    p.batchFrame = p.batch.empty() ? 0 : p.batchRegisters * kBatch + batchCallees;
}

}  // namespace rays::fn
