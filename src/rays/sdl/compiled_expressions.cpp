// Running the expressions compiled for their places (expr_code.h): the reader's binary() asks
// here first, and reads the text itself when the place has no code or the code does not fit what
// the identifiers hold now.
#include <algorithm>
#include <cmath>

#include "rays/sdl/frames.h"
#include "rays/sdl/interpreter.h"
#include "rays/sdl/pure_builtins.h"

namespace rays::sdl {

namespace {

constexpr int kRunStack = 33;     // above expr_code.cpp's kMaxCompiledStack
constexpr int kMaxIdents = 64;    // identifiers checked per run; code with more is read as text
constexpr uint8_t kMissesToGiveUp = 8;  // runs in a row whose identifiers did not fit
constexpr uint8_t kUnknownType = ExprCode::kUnknownType;
constexpr int kElementsScanned = 64;  // elements looked at for the type of an array's vectors

// The type code (ExprCode::types) of a float or vector value.
uint8_t typeCode(const Value& v) { return v.type == VType::Float ? 0 : v.dim; }

// The type code of the elements of array a read with n indices, kUnknownType when they are not
// floats or vectors (or no element is set among the first ones, for vectors). Vectors of one
// array may differ in size: the last run's size is kept, and a run meeting another one stops.
uint8_t elementTypeCode(const ArrayData& a, size_t n, uint8_t last) {
    if (a.sizes.size() != n) return kUnknownType;
    if (a.elemType == VType::Float) return 0;
    if (a.elemType != VType::Vector) return kUnknownType;
    if (last != kUnknownType && last != 0) return last;
    const size_t scan = std::min(a.elems.size(), size_t(kElementsScanned));
    for (size_t i = 0; i < scan; ++i)
        if (a.elems[i].type == VType::Vector) return a.elems[i].dim;
    return kUnknownType;
}

// The element of array a at the indices (floats) as arrayElement finds it, or null where the reader
// would stop with an error (an index out of range, an unset element) or the element is not of the
// type code want.
const Value* elementAt(const ArrayData& a, const double* index, uint8_t want) {
    size_t flat = 0;
    for (size_t d = 0; d < a.sizes.size(); ++d) {
        const double i = index[d];
        if (!(i > -1 && i < double(a.sizes[d]))) return nullptr;
        flat = flat * size_t(a.sizes[d]) + size_t(int(i));
    }
    const Value& e = a.elems[flat];
    if (want == 0 ? e.type != VType::Float : (e.type != VType::Vector || e.dim != want)) return nullptr;
    return &e;
}

}  // namespace

bool Interpreter::compiledOperand(int minPrec, bool full, bool colorCtx, Num& out) {
    if (cur_ + 1 != cursor_ || curFile_ != topFile_) return false;  // the current token is this file's next one
    if (topFile_ >= exprSlots_.size() || exprSlots_[topFile_].empty()) return false;  // a file read once
    const uint32_t start = uint32_t(cur_ - base_);
    int32_t& slot = exprSlots_[topFile_][start];
    if (slot < 0 && slot != kExprSeen) {  // untried: compiled on the second reading
        if (slot == kExprUntried) slot = kExprSeen;
        return false;
    }
    if (slot == kExprSeen) {
        ExprCode code;
        if (!compileExpression(base_, start, minPrec, full, colorCtx, code) || code.idents.size() > size_t(kMaxIdents)) {
            slot = kExprNever;
            return false;
        }
        slot = int32_t(exprCodes_.size());
        exprCodes_.push_back(std::move(code));
    }
    ExprCode& code = exprCodes_[size_t(slot)];
    if (code.minPrec != minPrec || code.full != full || code.colorCtx != colorCtx) return false;

    // Every identifier must hold a float or a vector now; a run with other types than the last
    // checked one is type-checked again.
    const Binding* binds[kMaxIdents];
    uint8_t types[kMaxIdents];
    bool sameTypes = true;
    auto miss = [&]() {
        if (++code.misses >= kMissesToGiveUp) slot = kExprNever;
        return false;
    };
    for (size_t i = 0; i < code.idents.size(); ++i) {
        const Binding* b = scopes_.find(code.idents[i]);
        if (!b || b->deprecated) return miss();
        if (code.indexCount[i] == 0) {
            if (b->value.type != VType::Float && b->value.type != VType::Vector) return miss();
            types[i] = typeCode(b->value);
        } else {
            if (b->value.type != VType::Array) return miss();
            types[i] = elementTypeCode(b->value.arr(), code.indexCount[i], code.types[i]);
            if (types[i] == kUnknownType) return miss();
        }
        binds[i] = b;
        sameTypes = sameTypes && types[i] == code.types[i];
    }
    if (!sameTypes) {
        if (!typeCheckExpression(code, types)) return miss();
        std::copy(types, types + code.idents.size(), code.types.begin());
        code.scalar = scalarExpression(code, types);
    }
    code.misses = 0;

    if (code.scalar) {
        double v = 0;
        if (!runScalar(code, binds, v)) return miss();
        out = Num::number(v);
    } else if (!runCompiled(code, binds, out)) {
        return miss();
    }
    // The tokens read count as the reader's fetches would have (the first one was fetched).
    const uint64_t before = ticks_;
    ticks_ += code.end - start - 1;
    if ((before >> 16) != (ticks_ >> 16)) tickSlow();
    jumpTo(code.end);
    have_ = false;
    // What follows may go on with the operand: its components after a directive, or after a
    // macro's end in the caller's text (compileExpression lets the code stop there only after one
    // plain operand; the caller's binaryAfter then reads any operators).
    if (mayGoOnElsewhere(base_[code.end])) out = postfix(out);
    return true;
}

bool Interpreter::runScalar(const ExprCode& code, const Binding* const* binds, double& out) {
    double st[kRunStack];
    int top = 0;
    size_t ident = 0;
    for (const ExprOp& op : code.ops) {
        switch (op.code) {
            case ExprOp::Const: st[top++] = code.consts[op.arg].c[0]; break;
            case ExprOp::Ident: st[top++] = binds[ident++]->value.c[0]; break;
            case ExprOp::Element: {
                top -= op.aux;
                const Value* e = elementAt(binds[ident]->value.arr(), &st[top], code.types[ident]);
                if (!e) return false;
                ++ident;
                st[top++] = e->c[0];
                break;
            }
            case ExprOp::Env: st[top++] = environmentValue(Kw(op.arg)); break;
            case ExprOp::Neg: st[top - 1] = -st[top - 1]; break;
            case ExprOp::Not: st[top - 1] = unaryOperator('!', Num::number(st[top - 1])).c[0]; break;
            case ExprOp::Binary:
                --top;
                st[top - 1] = combineFloats(char(op.aux), st[top - 1], st[top]);
                break;
            case ExprOp::Math1: st[top - 1] = mathFunction1(Kw(op.arg))(st[top - 1]); break;
            case ExprOp::Math2: {
                double r = 0;
                --top;
                mathFunction2(Kw(op.arg), st[top - 1], st[top], r);
                st[top - 1] = r;
                break;
            }
            case ExprOp::MinMax: {
                const int n = op.aux;
                double r = st[top - n];
                for (int i = 1; i < n; ++i) r = Kw(op.arg) == Kw::max ? std::max(r, st[top - n + i]) : std::min(r, st[top - n + i]);
                top -= n - 1;
                st[top - 1] = r;
                break;
            }
            case ExprOp::Select: {
                const int n = op.aux;
                const double s = st[top - n];
                const double r = st[top - n + (s < 0 ? 1 : (n == 3 || s == 0) ? 2 : 3)];
                top -= n - 1;
                st[top - 1] = r;
                break;
            }
            case ExprOp::Cond:
                top -= 2;
                st[top - 1] = std::fabs(st[top - 1]) > 1e-10 ? st[top] : st[top + 1];
                break;
            case ExprOp::Rand: {
                const Outcome<double> r = random_.rand(st[top - 1]);
                if (!r.ok()) error(Loc{topFile_, base_[op.at].line, base_[op.at].col}, r.error);
                st[top - 1] = r.value;
                break;
            }
            case ExprOp::Dot: case ExprOp::Vector: case ExprOp::VecFn: break;  // never in scalar code
        }
    }
    out = st[0];
    return true;
}

bool Interpreter::runCompiled(const ExprCode& code, const Binding* const* binds, Num& out) {
    // Uninitialised room (Num is an implicit-lifetime aggregate): zeroing 33 values would cost
    // more than most runs.
    alignas(Num) unsigned char room[sizeof(Num) * kRunStack];
    Num* st = reinterpret_cast<Num*>(room);
    int top = 0;
    size_t ident = 0;
    auto opLoc = [&](const ExprOp& op) { return Loc{topFile_, base_[op.at].line, base_[op.at].col}; };
    for (const ExprOp& op : code.ops) {
        switch (op.code) {
            case ExprOp::Const: st[top++] = code.consts[op.arg]; break;
            case ExprOp::Ident: st[top++] = Num::of(binds[ident++]->value); break;
            case ExprOp::Element: {
                double index[5];
                top -= op.aux;
                for (int i = 0; i < op.aux; ++i) index[i] = st[top + i].c[0];
                const Value* e = elementAt(binds[ident]->value.arr(), index, code.types[ident]);
                if (!e) return false;
                ++ident;
                st[top++] = Num::of(*e);
                break;
            }
            case ExprOp::Env: st[top++] = Num::number(environmentValue(Kw(op.arg))); break;
            case ExprOp::Neg: st[top - 1] = unaryOperator('-', st[top - 1]); break;
            case ExprOp::Not: st[top - 1] = unaryOperator('!', st[top - 1]); break;
            case ExprOp::Binary:
                --top;
                st[top - 1] = combine(char(op.aux), st[top - 1], st[top]);
                break;
            case ExprOp::Dot: {
                const Num& v = st[top - 1];
                st[top - 1] = Num::number(op.aux == 5 ? grayOf(v) : v.c[op.aux]);
                break;
            }
            case ExprOp::Vector: {
                Num v;
                v.type = VType::Vector;
                v.dim = op.aux;
                for (int i = 0; i < op.aux; ++i) v.c[size_t(i)] = st[top - op.aux + i].c[0];
                top -= op.aux - 1;
                st[top - 1] = v;
                break;
            }
            case ExprOp::Math1: st[top - 1] = Num::number(mathFunction1(Kw(op.arg))(st[top - 1].c[0])); break;
            case ExprOp::Math2: {
                double r = 0;
                --top;
                mathFunction2(Kw(op.arg), st[top - 1].c[0], st[top].c[0], r);
                st[top - 1] = Num::number(r);
                break;
            }
            case ExprOp::MinMax: {
                const int n = op.aux;
                double r = st[top - n].c[0];
                for (int i = 1; i < n; ++i) {
                    const double a = st[top - n + i].c[0];
                    r = Kw(op.arg) == Kw::max ? std::max(r, a) : std::min(r, a);
                }
                top -= n - 1;
                st[top - 1] = Num::number(r);
                break;
            }
            case ExprOp::VecFn: {
                const int n = op.aux;
                Num r;
                if (!vectorFunction(Kw(op.arg), &st[top - n], n, r)) error(opLoc(op), "vnormalize of a zero vector");
                top -= n - 1;
                st[top - 1] = r;
                break;
            }
            case ExprOp::Select: {
                const int n = op.aux;
                const double s = st[top - n].c[0];
                const int pick = s < 0 ? 1 : (n == 3 || s == 0) ? 2 : 3;
                const Num r = st[top - n + pick];
                top -= n - 1;
                st[top - 1] = r;
                break;
            }
            case ExprOp::Cond: {
                top -= 2;
                st[top - 1] = std::fabs(st[top - 1].c[0]) > 1e-10 ? st[top] : st[top + 1];  // truth(), as fullNum reads it
                break;
            }
            case ExprOp::Rand: {
                const Outcome<double> r = random_.rand(st[top - 1].c[0]);
                if (!r.ok()) error(opLoc(op), r.error);
                st[top - 1] = Num::number(r.value);
                break;
            }
        }
    }
    out = st[0];
    return true;
}

}  // namespace rays::sdl
