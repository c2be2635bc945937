// The machine's two loops. Each opcode's arithmetic is written once (RAYS_FN_LANE_OPS, the ops'
// from fn/ops.h) and expanded into both the scalar loop (one register = one double) and the
// batch loop (one register = kBatch lanes, one instruction = one loop over the lanes, restrict
// pointers so the compiler vectorises it: batch code never writes a register it reads,
// fn/emit.cpp).
#include "rays/fn/machine.h"

#include <algorithm>
#include <cstring>

#include "rays/fn/compile.h"
#include "rays/fn/internal_functions.h"
#include "rays/fn/ops.h"

namespace rays::fn {

namespace {
thread_local uint64_t* tlLoopLeft = nullptr;  // the innermost LoopBudget's count, or null
}  // namespace

LoopBudget::LoopBudget(uint64_t iterations) : initial_(iterations), left_(iterations), outer_(tlLoopLeft) {
    tlLoopLeft = &left_;
}

LoopBudget::~LoopBudget() { tlLoopLeft = outer_; }

void Scratch::fit(const Program& p) {
    if (scalar_.size() < static_cast<size_t>(p.scalarFrame)) scalar_.resize(p.scalarFrame);
    if (batch_.size() < static_cast<size_t>(p.batchFrame)) batch_.resize(p.batchFrame);
}

namespace {

using ops::maxOf;
using ops::minOf;
using ops::toInt;
using ops::truth;

// X(code, expression of A, B, C (registers a, b, c), D (register aux) and K (the immediate)):
// the ops of fn/ops.h and the machine's own forms.
#define RAYS_FN_LANE_OPS(X)                          \
    X(Mov, A)                                        \
    X(Const, K)                                      \
    RAYS_FN_UNARY_OPS(X)                             \
    X(Sqr, A * A)                                    \
    RAYS_FN_BINARY_OPS(X)                            \
    X(AddK, A + K)                                   \
    X(SubK, A - K)                                   \
    X(KSub, K - A)                                   \
    X(MulK, A * K)                                   \
    X(DivK, A / K)                                   \
    X(KDiv, K / A)                                   \
    X(MaxK, maxOf(A, K))                             \
    X(KMax, maxOf(K, A))                             \
    X(MinK, minOf(A, K))                             \
    X(KMin, minOf(K, A))                             \
    X(PowK, std::pow(A, K))                          \
    X(MulAdd, A * B + C)                             \
    X(MulSub, A * B - C)                             \
    X(Select3, A < 0 ? B : C)                        \
    X(Select4, A < 0 ? B : (A == 0 ? C : D))         \
    X(Cond, A != 0 ? B : C)

constexpr int kMaxArgs = kMaxParams;

// A few doubles: a plain loop (memcpy's call costs more than the copy for 3 parameters).
inline void copyDoubles(double* dst, const double* src, size_t n) {
    for (size_t i = 0; i < n; ++i) dst[i] = src[i];
}

double runScalar(const Program& p, double* r);

// Copies a callee's arguments and pool into its frame `cr`.
inline void enterScalar(const Program& callee, const Program& p, const Instr& in, const double* r, double* cr) {
    const uint16_t* l = p.lists.data() + in.list;
    for (int i = 0; i < in.c; ++i) cr[i] = r[l[i]];
    copyDoubles(cr + callee.params, callee.pool.data(), callee.pool.size());
}

double callHost(const HostFunction& h, Member m, const double* in) {
    double out[5] = {0, 0, 0, 0, 0};
    h.fn(h.data, in, out);
    return ops::member(m, out, h.outputs);
}

// The scalar loop: one switch (a direct-threaded variant, one indirect jump per handler, measured
// no faster here: expr40 48.3 against 49.4 ns).
double runScalar(const Program& p, double* r) {
    const Instr* const code = p.code.data();
    const Instr* ip = code;
    for (;;) {
        const Instr& in = *ip;
        switch (in.op) {
#define RAYS_FN_SCALAR(name, expr)                                                     \
    case Code::name: {                                                                 \
        [[maybe_unused]] const double A = r[in.a], B = r[in.b], C = r[in.c], K = in.k; \
        [[maybe_unused]] const double D = in.op == Code::Select4 ? r[in.aux] : 0.0;    \
        r[in.d] = (expr);                                                              \
        ++ip;                                                                          \
        continue;                                                                      \
    }
            RAYS_FN_LANE_OPS(RAYS_FN_SCALAR)
#undef RAYS_FN_SCALAR
            case Code::Ret: return r[in.a];
            case Code::Jump: ip = code + in.aux; continue;
            case Code::JumpIfZero: ip = r[in.a] == 0 ? code + in.aux : ip + 1; continue;
            case Code::JumpIfNotNeg: ip = !(r[in.a] < 0) ? code + in.aux : ip + 1; continue;
            case Code::JumpIfNotZero: ip = !(r[in.a] == 0) ? code + in.aux : ip + 1; continue;
            case Code::JumpIfNotLe:  // the sum/prod loop test: one more repetition when it falls through
                if (!(r[in.a] <= r[in.b])) {
                    ip = code + in.aux;
                    continue;
                }
                if (tlLoopLeft && (*tlLoopLeft)-- == 0) {
                    *tlLoopLeft = 0;
                    throw LoopBudgetExceeded();
                }
                ++ip;
                continue;
            case Code::Call: {
                if (tlLoopLeft && (*tlLoopLeft)-- == 0) {  // a call tree can double at every level
                    *tlLoopLeft = 0;
                    throw LoopBudgetExceeded();
                }
                const Program& callee = *p.callees[in.aux];
                double* cr = r + p.registers;
                enterScalar(callee, p, in, r, cr);
                r[in.d] = runScalar(callee, cr);
                ++ip;
                continue;
            }
            case Code::Host:
            case Code::Internal: {
                double args[kMaxArgs];
                const uint16_t* l = p.lists.data() + in.list;
                for (int i = 0; i < in.c; ++i) args[i] = r[l[i]];
                r[in.d] = in.op == Code::Host ? callHost(p.hosts[in.aux], static_cast<Member>(in.b), args)
                                              : internalFunction(static_cast<int>(in.aux))->fn(args);
                ++ip;
                continue;
            }
        }
        return 0;  // not reached: every opcode is handled above
    }
}

// Batch code never writes a register it reads in the same instruction (fn/emit.cpp), so the
// lane loops have no loop-carried dependences; GCC ignores restrict on local pointers, so say it.
#if defined(__GNUC__) && !defined(__clang__)
#define RAYS_FN_IVDEP _Pragma("GCC ivdep")
#else
#define RAYS_FN_IVDEP
#endif

inline double* lanes(double* r, int reg) { return r + static_cast<size_t>(reg) * kBatch; }

// Registers params.. of a batch frame get the pool, every lane.
void broadcastPool(const Program& p, double* r) {
    for (size_t q = 0; q < p.batchPool.size(); ++q) std::fill_n(lanes(r, p.params + static_cast<int>(q)), kBatch, p.batchPool[q]);
}

// Runs p's batch code on frame r (params and pool set); returns the result's lanes. `scalar` is
// the scratch for callees run lane by lane.
const double* runBatch(const Program& p, double* r, double* scalar) {
    const Instr* const code = p.batch.data();
    for (const Instr* ip = code;; ++ip) {
        const Instr& in = *ip;
        switch (in.op) {
#define RAYS_FN_BATCH(name, expr)                                                    \
    case Code::name: {                                                               \
        double* __restrict d = lanes(r, in.d);                                       \
        const double* __restrict a = lanes(r, in.a);                                 \
        const double* __restrict b = lanes(r, in.b);                                 \
        const double* __restrict c = lanes(r, in.c);                                 \
        const double* __restrict dd = lanes(r, in.op == Code::Select4 ? static_cast<int>(in.aux) : 0); \
        [[maybe_unused]] const double K = in.k;                                      \
        RAYS_FN_IVDEP                                                                \
        for (int l = 0; l < kBatch; ++l) {                                           \
            [[maybe_unused]] const double A = a[l], B = b[l], C = c[l], D = dd[l];   \
            d[l] = (expr);                                                           \
        }                                                                            \
        continue;                                                                    \
    }
            RAYS_FN_LANE_OPS(RAYS_FN_BATCH)
#undef RAYS_FN_BATCH
            case Code::Ret: return lanes(r, in.a);
            case Code::Call: {
                const Program& callee = *p.callees[in.aux];
                const uint16_t* l = p.lists.data() + in.list;
                double* d = lanes(r, in.d);
                if (!callee.batch.empty()) {
                    double* cr = r + static_cast<size_t>(p.batchRegisters) * kBatch;
                    for (int i = 0; i < in.c; ++i) std::memcpy(lanes(cr, i), lanes(r, l[i]), sizeof(double) * kBatch);
                    broadcastPool(callee, cr);
                    const double* res = runBatch(callee, cr, scalar);
                    std::memcpy(d, res, sizeof(double) * kBatch);
                } else {
                    for (int lane = 0; lane < kBatch; ++lane) {
                        for (int i = 0; i < in.c; ++i) scalar[i] = lanes(r, l[i])[lane];
                        copyDoubles(scalar + callee.params, callee.pool.data(), callee.pool.size());
                        d[lane] = runScalar(callee, scalar);
                    }
                }
                continue;
            }
            case Code::Host:
            case Code::Internal: {
                const uint16_t* l = p.lists.data() + in.list;
                double* d = lanes(r, in.d);
                double args[kMaxArgs];
                for (int lane = 0; lane < kBatch; ++lane) {
                    for (int i = 0; i < in.c; ++i) args[i] = lanes(r, l[i])[lane];
                    d[lane] = in.op == Code::Host ? callHost(p.hosts[in.aux], static_cast<Member>(in.b), args)
                                                  : internalFunction(static_cast<int>(in.aux))->fn(args);
                }
                continue;
            }
            default: return lanes(r, 0);  // jumps never appear in batch code
        }
    }
}

}  // namespace

double eval(const Program& p, const double* args, Scratch& s) {
    if (!s.fitsScalar(p)) s.fit(p);
    double* r = s.scalar();
    copyDoubles(r, args, static_cast<size_t>(p.params));
    copyDoubles(r + p.params, p.pool.data(), p.pool.size());
    return runScalar(p, r);
}

int evalVector(const Program& p, const double* args, double* out, Scratch& s) {
    if (p.hostWrapper) {
        const HostFunction& h = p.hosts[0];
        for (int i = 0; i < 5; ++i) out[i] = 0;
        h.fn(h.data, args, out);
        return h.outputs;
    }
    out[0] = eval(p, args, s);
    return 1;
}

void evalBatch(const Program& p, const double* const* args, double* out, size_t n, Scratch& s) {
    if (!s.fitsBatch(p)) s.fit(p);
    if (p.batch.empty()) {
        double point[kMaxArgs];
        for (size_t i = 0; i < n; ++i) {
            for (int j = 0; j < p.params; ++j) point[j] = args[j][i];
            out[i] = eval(p, point, s);
        }
        return;
    }
    double* r = s.batch();
    broadcastPool(p, r);
    for (size_t first = 0; first < n; first += kBatch) {
        const size_t count = std::min<size_t>(kBatch, n - first);
        for (int j = 0; j < p.params; ++j) {
            double* dst = lanes(r, j);
            std::memcpy(dst, args[j] + first, sizeof(double) * count);
            std::fill(dst + count, dst + kBatch, args[j][first + count - 1]);  // padding lanes: a real point
        }
        const double* res = runBatch(p, r, s.scalar());
        std::memcpy(out + first, res, sizeof(double) * count);
    }
}

void evalBatchXYZ(const Program& p, const double* x, const double* y, const double* z, double* out, size_t n,
                  Scratch& s) {
    const double* args[3] = {x, y, z};
    evalBatch(p, args, out, n, s);
}

}  // namespace rays::fn
