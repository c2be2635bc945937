// The function machine (src/rays/fn): every op against hand values and POV-Ray 3.7's measured
// edge cases, sum/prod, calls with members, and the compiler's forms agreeing with each other.
// Every value is compiled eight ways (folding, jumps and inlining each on and off) and run by
// scalar and batch code, and all must agree bit for bit, so each op test also checks folding
// and the batch machine.
#include <gtest/gtest.h>

#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "rays/fn/compile.h"
#include "rays/fn/function_table.h"
#include "rays/fn/machine.h"
#include "support/fn_sexpr.h"

using namespace rays::fn;
using rays::fn::testing::sexpr;

namespace { namespace RAYS_TEST_UNIT {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// A value the C++ compiler cannot fold (GCC folds libm calls on constants correctly rounded,
// glibc at run time may differ in the last bit).
double opaque(double v) {
    volatile double x = v;
    return x;
}

bool same(double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
}

// Batch evaluation of one point (padded into a block).
double batchOne(const Program& p, const std::vector<double>& args) {
    std::vector<std::vector<double>> cols(args.size());
    std::vector<const double*> ptrs;
    for (size_t j = 0; j < args.size(); ++j) {
        cols[j] = std::vector<double>(3, args[j]);
        ptrs.push_back(cols[j].data());
    }
    double out[3];
    Scratch s;
    evalBatch(p, ptrs.data(), out, 3, s);
    return out[1];
}

// The value of `text` at args, checked to agree across folding, jumps and batch code. With
// `table`, calls name its entries.
double value(const std::string& text, const std::vector<double>& args, const FunctionTable* table = nullptr) {
    const Expr e = sexpr(text);
    const int params = args.empty() ? 1 : static_cast<int>(args.size());
    std::vector<double> a = args.empty() ? std::vector<double>{0} : args;
    std::span<const std::shared_ptr<const Program>> callable;
    if (table) callable = table->programs();
    double first = 0;
    bool have = false;
    for (int fold = 0; fold < 2; ++fold)
        for (int branches = 0; branches < 2; ++branches)
            for (int inl = 0; inl < 2; ++inl) {
                CompileOptions o;
                o.fold = fold;
                o.branches = branches;
                o.inlineCalls = inl;
                auto p = compile(e, params, callable, o);
                Scratch s(*p);
                const double v = eval(*p, a.data(), s);
                const double vb = batchOne(*p, a);
                EXPECT_TRUE(same(v, vb)) << text << " scalar " << v << " batch " << vb;
                if (!have) first = v;
                have = true;
                EXPECT_TRUE(same(v, first)) << text << " fold=" << fold << " branches=" << branches
                                            << " inline=" << inl << ": " << v << " vs " << first;
            }
    return first;
}

std::string compileError(const std::string& text, int params, const FunctionTable* table = nullptr,
                         int32_t* loc = nullptr) {
    std::span<const std::shared_ptr<const Program>> callable;
    if (table) callable = table->programs();
    try {
        compile(sexpr(text), params, callable);
    } catch (const CompileError& e) {
        if (loc) *loc = e.loc();
        return e.what();
    }
    return "(no error)";
}

TEST(FnMachine, Arithmetic) {
    EXPECT_EQ(value("(+ x y)", {2, 3}), 5);
    EXPECT_EQ(value("(- x y)", {2, 3}), -1);
    EXPECT_EQ(value("(* x y)", {2, 3}), 6);
    EXPECT_EQ(value("(/ x y)", {3, 2}), 1.5);
    EXPECT_EQ(value("(neg x)", {2}), -2);
    EXPECT_TRUE(std::signbit(value("(neg x)", {0})));
    EXPECT_EQ(value("(+ (* x x) (* y y))", {3, 4}), 25);
    EXPECT_EQ(value("(- (* x y) z)", {3, 4, 5}), 7);
    EXPECT_EQ(value("(- z (* x y))", {3, 4, 5}), -7);
    EXPECT_EQ(value("(+ z (* x y))", {3, 4, 5}), 17);
    EXPECT_EQ(value("(- 10 x)", {4}), 6);
    EXPECT_EQ(value("(/ 10 x)", {4}), 2.5);
    EXPECT_EQ(value("(/ x 4)", {10}), 2.5);
    EXPECT_EQ(value("(* 3 (+ x 1))", {1}), 6);
}

TEST(FnMachine, DivisionByZeroIsInfinityNotAnError) {
    EXPECT_EQ(value("(/ x y)", {1, 0}), INFINITY);
    EXPECT_EQ(value("(/ x y)", {-1, 0}), -INFINITY);
    EXPECT_TRUE(std::isnan(value("(/ x y)", {0, 0})));
}

TEST(FnMachine, ComparisonsAreExactWithPovRaysNanRules) {
    // Inside functions POV-Ray 3.7 compares exactly (measured: (1 = 1+1e-12) is 0).
    EXPECT_EQ(value("(= x y)", {1, 1 + 1e-12}), 0);
    EXPECT_EQ(value("(!= x y)", {0, 1e-12}), 1);
    EXPECT_EQ(value("(< x y)", {0, 1e-12}), 1);
    EXPECT_EQ(value("(<= x y)", {1e-12, 0}), 0);
    EXPECT_EQ(value("(<= x y)", {2, 2}), 1);
    EXPECT_EQ(value("(>= x y)", {2, 2}), 1);
    EXPECT_EQ(value("(> x y)", {2, 2}), 0);
    EXPECT_EQ(value("(> x y)", {3, 2}), 1);
    EXPECT_EQ(value("(= x y)", {2, 2}), 1);
    // With NaN (measured): < <= = false; > >= != true (they are !(a <= b), !(a < b), !(a = b)).
    for (double a : {1.0, kNaN}) {
        const double b = std::isnan(a) ? 1.0 : kNaN;
        EXPECT_EQ(value("(< x y)", {a, b}), 0);
        EXPECT_EQ(value("(<= x y)", {a, b}), 0);
        EXPECT_EQ(value("(= x y)", {a, b}), 0);
        EXPECT_EQ(value("(> x y)", {a, b}), 1);
        EXPECT_EQ(value("(>= x y)", {a, b}), 1);
        EXPECT_EQ(value("(!= x y)", {a, b}), 1);
    }
}

TEST(FnMachine, LogicalOpsTestNonZeroExactly) {
    EXPECT_EQ(value("(& x y)", {1e-12, 1}), 1);  // measured: no epsilon inside functions
    EXPECT_EQ(value("(& x y)", {0.5, 2}), 1);
    EXPECT_EQ(value("(& x y)", {0, 3}), 0);
    EXPECT_EQ(value("(& x y)", {-1, 1}), 1);
    EXPECT_EQ(value("(& x y)", {kNaN, 1}), 1);
    EXPECT_EQ(value("(| x y)", {0, 0}), 0);
    EXPECT_EQ(value("(| x y)", {-2, 0}), 1);
    EXPECT_EQ(value("(| x y)", {0, kNaN}), 1);
    EXPECT_EQ(value("(! x)", {0}), 1);
    EXPECT_EQ(value("(! x)", {1e-300}), 0);
    EXPECT_EQ(value("(! x)", {kNaN}), 0);
    EXPECT_EQ(value("(?: x y z)", {1e-12, 5, 6}), 5);
    EXPECT_EQ(value("(?: x y z)", {0, 5, 6}), 6);
    EXPECT_EQ(value("(?: x y z)", {kNaN, 5, 6}), 5);
}

TEST(FnMachine, SelectFollowsTheReferenceTable) {
    // Reference 3.3.1.5.4: A = -2 -1 0 1 2 gives -1 -1 0 1 1 and -1 -1 1 1 1.
    const double a[] = {-2, -1, 0, 1, 2};
    const double four[] = {-1, -1, 0, 1, 1}, three[] = {-1, -1, 1, 1, 1};
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(value("(select x -1 0 1)", {a[i]}), four[i]);
        EXPECT_EQ(value("(select x -1 1)", {a[i]}), three[i]);
    }
    // Measured edge cases: -0 is not negative; NaN picks the last arm.
    EXPECT_EQ(value("(select x 10 20)", {-0.0}), 20);
    EXPECT_EQ(value("(select x 10 20)", {-1e-300}), 10);
    EXPECT_EQ(value("(select x 10 20 30)", {-0.0}), 20);
    EXPECT_EQ(value("(select x 10 20 30)", {1e-12}), 30);
    EXPECT_EQ(value("(select x 10 20)", {kNaN}), 20);
    EXPECT_EQ(value("(select x 10 20 30)", {kNaN}), 30);
    // Expensive arms are jumped around in scalar code; the value is the same.
    const std::string big = "(select x (sin (cos (sin (cos (sin y))))) (+ 1 (* y (* y (* y (* y y))))) (sqrt (exp (sin y))))";
    EXPECT_EQ(value(big, {-1, 0.5}), std::sin(std::cos(std::sin(std::cos(std::sin(opaque(0.5)))))));
    EXPECT_EQ(value(big, {0, 0.5}), 1 + 0.5 * (0.5 * (0.5 * (0.5 * 0.5))));
    EXPECT_EQ(value(big, {1, 0.5}), std::sqrt(std::exp(std::sin(opaque(0.5)))));
    EXPECT_EQ(value(big, {kNaN, 0.5}), std::sqrt(std::exp(std::sin(opaque(0.5)))));
}

TEST(FnMachine, IntTruncatesThroughA32BitInt) {
    EXPECT_EQ(value("(int x)", {-2.5}), -2);
    EXPECT_EQ(value("(int x)", {2.7}), 2);
    EXPECT_FALSE(std::signbit(value("(int x)", {-0.5})));  // measured: +0
    EXPECT_EQ(value("(int x)", {2147483647.9}), 2147483647);
    EXPECT_EQ(value("(int x)", {-2147483648.9}), -2147483648.0);
    // Measured: out of the int range POV-Ray gives INT_MIN.
    EXPECT_EQ(value("(int x)", {1e20}), -2147483648.0);
    EXPECT_EQ(value("(int x)", {-3e9}), -2147483648.0);
    EXPECT_EQ(value("(int x)", {kNaN}), -2147483648.0);
    EXPECT_EQ(value("(div x y)", {7, 2}), 3);
    EXPECT_EQ(value("(div x y)", {-7, 2}), -3);
    EXPECT_EQ(value("(div x y)", {1, 0}), -2147483648.0);
}

TEST(FnMachine, ModIsFmod) {
    EXPECT_EQ(value("(mod x y)", {-7, 3}), -1);
    EXPECT_EQ(value("(mod x y)", {7, -3}), 1);
    EXPECT_EQ(value("(mod x y)", {7.5, 2}), 1.5);
    EXPECT_EQ(value("(mod x y)", {1e20, 3}), 1);  // measured; ((a/b) - int(a/b))*b would not give it
    EXPECT_EQ(value("(mod x y)", {5.3, 1.1}), 0.8999999999999995);
    EXPECT_TRUE(std::signbit(value("(mod x y)", {-6, 3})));
    EXPECT_TRUE(std::isnan(value("(mod x y)", {1, 0})));
}

TEST(FnMachine, FloorCeilAbs) {
    EXPECT_EQ(value("(floor x)", {-2.5}), -3);
    EXPECT_EQ(value("(ceil x)", {-2.5}), -2);
    EXPECT_TRUE(std::signbit(value("(ceil x)", {-0.5})));  // measured: -0
    EXPECT_EQ(value("(abs x)", {-3}), 3);
    EXPECT_FALSE(std::signbit(value("(abs x)", {-0.0})));
}

TEST(FnMachine, MathFunctionsAreTheCLibrarys) {
    volatile double at = 0.37;  // not a constant: GCC would fold std::atanh(0.37) correctly rounded
    const double v = at, one = 1 + at, ten = 10 * (at / at), two = 2 * (at / at);
    EXPECT_EQ(value("(sin x)", {v}), std::sin(v));
    EXPECT_EQ(value("(cos x)", {v}), std::cos(v));
    EXPECT_EQ(value("(tan x)", {v}), std::tan(v));
    EXPECT_EQ(value("(asin x)", {v}), std::asin(v));
    EXPECT_EQ(value("(acos x)", {v}), std::acos(v));
    EXPECT_EQ(value("(atan x)", {v}), std::atan(v));
    EXPECT_EQ(value("(sinh x)", {v}), std::sinh(v));
    EXPECT_EQ(value("(cosh x)", {v}), std::cosh(v));
    EXPECT_EQ(value("(tanh x)", {v}), std::tanh(v));
    EXPECT_EQ(value("(asinh x)", {v}), std::asinh(v));
    EXPECT_EQ(value("(acosh x)", {one}), std::acosh(one));
    EXPECT_EQ(value("(atanh x)", {v}), std::atanh(v));
    EXPECT_EQ(value("(exp x)", {v}), std::exp(v));
    EXPECT_EQ(value("(ln x)", {ten}), std::log(ten));
    EXPECT_EQ(value("(log x)", {1000}), 3);
    EXPECT_EQ(value("(sqrt x)", {two}), std::sqrt(two));
    EXPECT_TRUE(std::isnan(value("(sqrt x)", {-1})));  // measured: NaN, no error
    EXPECT_EQ(value("(atan2 x y)", {1, -1}), 2.35619449019234484);
    EXPECT_EQ(value("(atan2 x y)", {0, 0}), 0);
    EXPECT_EQ(value("(pow x y)", {-2, 3}), -8);
    EXPECT_EQ(value("(pow x y)", {0, 0}), 1);
    EXPECT_TRUE(std::isnan(value("(pow x y)", {-8, 1.0 / 3})));
    EXPECT_EQ(value("(pow x 0.5)", {two}), std::pow(two, 0.5));
    EXPECT_EQ(value("(pow x 2)", {3}), 9);  // emitted as a multiply
}

TEST(FnMachine, DegreesAndRadiansRoundLikePovRay) {
    // Measured: degrees(8.355) = a·(180/π), not a·180/π (which is 478.70623783180287).
    EXPECT_EQ(value("(degrees x)", {8.355}), 478.70623783180281);
    EXPECT_EQ(value("(degrees x)", {1}), 57.29577951308232286);
    // Measured: radians(91.505) = a·(π/180), not a·π/180 (1.5970635320374114).
    EXPECT_EQ(value("(radians x)", {91.505}), 1.5970635320374111);
}

TEST(FnMachine, MinMaxAreNaryAndOrderSensitiveWithNan) {
    EXPECT_EQ(value("(min x y z)", {3, 1, 2}), 1);
    EXPECT_EQ(value("(max x y z p3)", {3, 1, 5, 2}), 5);
    EXPECT_EQ(value("(max x 4)", {3}), 4);
    EXPECT_EQ(value("(min 4 x)", {3}), 3);
    // Measured: max(nan, 1) = nan, max(1, nan) = 1, min(nan, 1) = 1, min(1, nan) = nan.
    EXPECT_TRUE(std::isnan(value("(max x y)", {kNaN, 1})));
    EXPECT_EQ(value("(max x y)", {1, kNaN}), 1);
    EXPECT_EQ(value("(min x y)", {kNaN, 1}), 1);
    EXPECT_TRUE(std::isnan(value("(min x y)", {1, kNaN})));
    EXPECT_TRUE(std::isnan(value("(max x 1)", {kNaN})));
    EXPECT_EQ(value("(max 1 x)", {kNaN}), 1);
    EXPECT_EQ(value("(min x 1)", {kNaN}), 1);
    EXPECT_TRUE(std::isnan(value("(min 1 x)", {kNaN})));
}

TEST(FnMachine, SumAndProd) {
    EXPECT_EQ(value("(sum 0 1 x i0)", {3}), 6);
    EXPECT_EQ(value("(prod 0 1 x i0)", {5}), 120);              // factorial, reference 3.3.1.8.1
    EXPECT_EQ(value("(sum 0 0.5 x i0)", {3}), 4.5);             // measured
    EXPECT_EQ(value("(sum 0 3 x i0)", {1}), 0);                 // no step: the neutral element
    EXPECT_EQ(value("(prod 0 3 x i0)", {1}), 1);
    EXPECT_EQ(value("(sum 0 1 3.99 i0)", {0}), 6);
    EXPECT_EQ(value("(prod 0 x y i0)", {2.5, 3}), 2.5);         // measured: 3.5 > 3 stops
    EXPECT_EQ(value("(sum 0 1 3 (sum 1 1 i0 (* i1 10)))", {0}), 100);  // measured
    EXPECT_EQ(value("(sum 0 1 x (* i0 i0))", {4}), 30);
    EXPECT_EQ(value("(sum 0 1 x (+ y (* i0 0.5)))", {4, 1}), 9);
    EXPECT_EQ(value("(sum 0 0 1000000 (* i0 0.1))", {0}), 50000050000.0);  // measured
    // The upper bound sees the variable at its start value (POV-Ray: sum(i,1,3,sum(i,1,i,i)) is 3).
    EXPECT_EQ(value("(sum 0 1 3 (sum 0 1 i0 i0))", {0}), 3);
    // A sum inside a select arm and a select inside a sum.
    EXPECT_EQ(value("(select x 0 (sum 0 1 y i0))", {1, 4}), 10);
    EXPECT_EQ(value("(sum 0 1 4 (select (- i0 2.5) 0 i0))", {0}), 7);
}

TEST(FnMachine, SumNestingLimitIs56) {
    auto nested = [](int n) {
        std::string s = "1";
        for (int i = 0; i < n; ++i) s = "(sum " + std::to_string(i % 56) + " 1 1 " + s + ")";
        return s;
    };
    EXPECT_EQ(value(nested(56), {0}), 1);
    EXPECT_EQ(compileError(nested(57), 1), "too many local variables: sum/prod nested deeper than 56");
}

TEST(FnMachine, InternalFunctionsAreCallable) {
    EXPECT_EQ(value("(internal 61 x y z 1)", {0.3, 0.4, 0.5}), std::sqrt(opaque(0.5)) - 1);
    EXPECT_EQ(value("(internal 61 x y z 1)", {0, 0, 0}), -1);
    EXPECT_EQ(value("(internal 61 0 0 2 1)", {0}), 1);  // folded
    EXPECT_EQ(value("(+ 1 (internal 70 x y z 0.8 0.2))", {1.582, 1.507, 1.243}), 1 + 1.7338483700359018);
}

TEST(FnMachine, CallsOfEarlierFunctionsInlinedOrNot) {
    FunctionTable t;
    const int f0 = t.addFloat(sexpr("(+ (* x x) (sin y))"), 2);  // function(a, b) { a*a + sin(b) }
    const int f1 = t.addFloat(sexpr("(* 2 (call 0 x (+ x 1)))"), 1);
    EXPECT_EQ(f0, 0);
    EXPECT_EQ(f1, 1);
    EXPECT_EQ(value("(call 0 x y)", {1, 2}, &t), 1 + std::sin(opaque(2.0)));
    EXPECT_EQ(value("(call 1 x)", {3}, &t), 2 * (9 + std::sin(opaque(4.0))));
    EXPECT_EQ(value("(+ (call 0 (* x 2) 0) (call 0 3 y))", {0.5, 0.25}, &t), 1 + (9 + std::sin(opaque(0.25))));
    EXPECT_EQ(value("(call 0 1 2)", {0}, &t), 1 + std::sin(opaque(2.0)));  // constant arguments
    // A callee with a sum, called inside a sum: its variable is its own.
    t.addFloat(sexpr("(sum 0 1 x i0)"), 1);
    EXPECT_EQ(value("(sum 0 1 3 (call 2 i0))", {0}, &t), 1 + 3 + 6);
    // The table evaluates entries itself too.
    Scratch s = t.makeScratch();
    const double args[2] = {1, 2};
    EXPECT_EQ(t.call(0, args, s), 1 + std::sin(opaque(2.0)));
}

TEST(FnMachine, InliningAndFoldingShrinkTheCode) {
    FunctionTable t;
    t.addFloat(sexpr("(+ (* x x) (* y y))"), 2);
    const Expr e = sexpr("(call 0 x 2)");
    CompileOptions off;
    off.inlineCalls = false;
    off.fold = false;
    auto inlined = compile(e, 1, t.programs());
    auto called = compile(e, 1, t.programs(), off);
    EXPECT_TRUE(inlined->callees.empty());
    EXPECT_EQ(called->callees.size(), 1u);
    EXPECT_LT(inlined->code.size(), 4u);  // x*x + 4: one fused instruction and a return
    Scratch s(*called);
    const double x = 1.5;
    EXPECT_EQ(eval(*inlined, &x, s), eval(*called, &x, s));
    auto folded = compile(sexpr("(* x (+ (sin 0.5) (sqrt 2)))"), 1, {});
    EXPECT_EQ(folded->code.size(), 2u);  // MulK, Ret
}

// A host "vector function": (x + 1, 2, 3) with 3 outputs, or rgbft (0.1, 0.2, 0.3, 0.4, 0.5).
void hostVector(const void* data, const double* in, double* out) {
    const int n = *static_cast<const int*>(data);
    if (n == 3) {
        out[0] = in[0] + 1;
        out[1] = 2;
        out[2] = 3;
    } else {
        for (int i = 0; i < 5; ++i) out[i] = 0.1 * (i + 1);
    }
}

TEST(FnMachine, HostFunctionsWithMembers) {
    static const int three = 3, five = 5;
    FunctionTable t;
    const int tr = t.addHost({&hostVector, &three, 3, 3});
    const int pg = t.addHost({&hostVector, &five, 3, 5});
    EXPECT_TRUE(t.isHost(tr));
    EXPECT_EQ(t.outputs(pg), 5);
    EXPECT_EQ(value("(call 0 .x x 0 0)", {0.5}, &t), 1.5);
    EXPECT_EQ(value("(call 0 .u x 0 0)", {0.5}, &t), 1.5);
    EXPECT_EQ(value("(call 0 .green x 0 0)", {0.5}, &t), 2);
    EXPECT_EQ(value("(call 0 .z x 0 0)", {0.5}, &t), 3);
    EXPECT_EQ(value("(call 0 .t x 0 0)", {0.5}, &t), 0);  // past the outputs: 0
    // Measured in POV-Ray with a transform function giving (1.5, 2, 3) and a pigment.
    EXPECT_EQ(value("(call 0 .gray x 0 0)", {0.5}, &t), 1.96550000000000002);
    EXPECT_EQ(value("(call 0 .hf x 0 0)", {0.5}, &t), 1.5019519941176471);
    EXPECT_EQ(value("(call 1 .filter x y z)", {0, 0, 0}, &t), 0.4);
    EXPECT_EQ(value("(call 1 .t x y z)", {0, 0, 0}, &t), 0.4);
    EXPECT_EQ(value("(call 1 .transmit x y z)", {0, 0, 0}, &t), 0.5);
    EXPECT_EQ(value("(+ (call 1 .red x y z) (call 0 .y x y z))", {0, 0, 0}, &t), 2.1);
    Scratch s = t.makeScratch();
    double out[5];
    const double at[3] = {0.5, 0, 0};
    EXPECT_EQ(t.callVector(tr, at, out, s), 3);
    EXPECT_EQ(out[0], 1.5);
    EXPECT_EQ(t.callVector(pg, at, out, s), 5);
    EXPECT_EQ(out[4], 0.5);
    EXPECT_EQ(t.call(tr, at, s), 1.5);
    // A compiled function's vector form has one output.
    t.addFloat(sexpr("(* x 2)"), 1);
    EXPECT_EQ(t.callVector(2, at, out, s), 1);
    EXPECT_EQ(out[0], 1);
}

TEST(FnMachine, MemberErrors) {
    static const int three = 3;
    FunctionTable t;
    t.addHost({&hostVector, &three, 3, 3});
    t.addFloat(sexpr("(* x 2)"), 1);
    EXPECT_EQ(compileError("(call 0 x y z)", 3, &t), "a vector or colour function needs a member (.x, .y, .z, .red, ...)");
    EXPECT_EQ(compileError("(call 1 .x x)", 1, &t), "a float function has no members");
    EXPECT_TRUE(memberFromName("grey") == Member::Gray);
    EXPECT_FALSE(memberFromName("f").has_value());  // measured: POV-Ray rejects .f
}

TEST(FnMachine, ErrorsNameTheNode) {
    FunctionTable t;
    t.addFloat(sexpr("(* x 2)"), 1);
    int32_t loc = 0;
    EXPECT_EQ(compileError("(+ x (select y 1))", 2, nullptr, &loc), "select takes 3 or 4 arguments, 2 given");
    EXPECT_EQ(loc, 6);
    EXPECT_EQ(compileError("(sin x y)", 2), "sin takes 1 argument, 2 given");
    EXPECT_EQ(compileError("(max x)", 1), "max takes at least 2 arguments, 1 given");
    EXPECT_EQ(compileError("(call 0 x y)", 2, &t, &loc), "function takes 1 argument, 2 given");
    EXPECT_EQ(loc, 1);
    EXPECT_EQ(compileError("(call 1 x)", 1, &t), "call of a function not declared before this one "
                                                  "(functions cannot call themselves or later functions)");
    EXPECT_EQ(compileError("(internal 61 x y z)", 3), "f_sphere takes 4 arguments, 3 given");
    EXPECT_EQ(compileError("(internal 77 x y z)", 3), "internal(77) is not an internal function");
    EXPECT_EQ(compileError("(+ x p3)", 3, nullptr, &loc), "parameter 3 of a function of 3 parameters");
    EXPECT_EQ(loc, 6);
    EXPECT_EQ(compileError("(+ x i0)", 1), "iteration variable used outside its sum/prod");
    EXPECT_EQ(compileError("(sum 0 i0 1 1)", 1), "iteration variable used outside its sum/prod");
    EXPECT_EQ(compileError("x", 57), "a function takes 1 to 56 parameters, not 57");
    EXPECT_EQ(compileError("x", 0), "a function takes 1 to 56 parameters, not 0");
    EXPECT_EQ(compileError("x", 56), "(no error)");
}

TEST(FnMachine, CallDepthLimitIs1024) {
    // Measured: a chain of 1024 functions each calling the one before works in POV-Ray; more aborts it.
    FunctionTable t;
    t.addFloat(sexpr("(+ x 1)"), 1);
    for (int i = 1; i < 1024; ++i) t.addFloat(sexpr("(+ (call " + std::to_string(i - 1) + " x) 1)"), 1);
    Scratch s = t.makeScratch();
    const double zero = 0;
    EXPECT_EQ(t.call(1023, &zero, s), 1024);
    EXPECT_EQ(t.program(1023).callDepth, 1024);
    EXPECT_EQ(compileError("(call 1023 x)", 1, &t), "functions nested deeper than 1024");
}

TEST(FnMachine, DeepTreesCompileWithoutRecursion) {
    // a+a+...+a, 500,000 additions (POV-Ray accepts up to about 524,200): a left-deep tree.
    Expr e;
    int32_t acc = e.param(0);
    for (int i = 0; i < 500000; ++i) acc = e.add(Op::Add, {acc, e.param(0)});
    auto p = compile(e, 1, {});
    Scratch s(*p);
    const double two = 2;
    EXPECT_EQ(eval(*p, &two, s), 1000002);
    EXPECT_EQ(batchOne(*p, {2}), 1000002);
    // Right-deep too (sin(sin(...(x)))).
    Expr r;
    int32_t v = r.param(0);
    for (int i = 0; i < 100000; ++i) v = r.add(Op::Sin, {v});
    auto q = compile(r, 1, {});
    Scratch sq(*q);
    EXPECT_GT(eval(*q, &two, sq), 0);
}

TEST(FnMachine, TooManyOperatorsIsAnError) {
    Expr e;
    int32_t acc = e.param(0);
    for (int i = 0; i < kMaxNodes / 2; ++i) acc = e.add(Op::Add, {acc, e.param(0)});
    EXPECT_THROW(compile(e, 1, {}), CompileError);
    try {
        compile(e, 1, {});
    } catch (const CompileError& err) {
        EXPECT_STREQ(err.what(), "function too complex (more than 1048576 operators)");
    }
}

TEST(FnMachine, BatchMatchesScalarOverManyPoints) {
    const Expr e = sexpr("(- (+ (* x x) (* y y) ) (select (- z 0.5) (* z z) (sin z) (cos z)))");
    auto p = compile(e, 3, {});
    ASSERT_FALSE(p->batch.empty());
    const size_t n = 101;  // not a multiple of kBatch
    std::vector<double> x(n), y(n), z(n), out(n);
    for (size_t i = 0; i < n; ++i) {
        x[i] = 0.01 * static_cast<double>(i) - 0.5;
        y[i] = std::sin(static_cast<double>(i));
        z[i] = (i % 7 == 0) ? 0.5 : std::cos(static_cast<double>(i) * 0.3);
    }
    Scratch s(*p);
    evalBatchXYZ(*p, x.data(), y.data(), z.data(), out.data(), n, s);
    for (size_t i = 0; i < n; ++i) {
        const double a[3] = {x[i], y[i], z[i]};
        EXPECT_TRUE(same(out[i], eval(*p, a, s))) << i;
    }
    // A program with a loop has no batch code and runs point by point.
    auto loop = compile(sexpr("(sum 0 1 x (* i0 y))"), 3, {});
    EXPECT_TRUE(loop->batch.empty());
    evalBatchXYZ(*loop, x.data(), y.data(), z.data(), out.data(), n, s);
    const double a[3] = {x[100], y[100], z[100]};
    EXPECT_EQ(out[100], eval(*loop, a, s));
}

TEST(FnMachine, ConstantFoldingGivesTheSameValuesAsTheMachine) {
    // Each op with constant arguments (folded at compile time) against the same op on parameters.
    const char* ops1[] = {"neg", "abs", "acos", "acosh", "asin", "asinh", "atan", "atanh", "ceil", "cos", "cosh",
                          "exp", "floor", "sin", "sinh", "sqrt", "tan", "tanh", "degrees", "radians", "int", "ln",
                          "log", "!"};
    const char* ops2[] = {"+", "-", "*", "/", "<", "<=", ">", ">=", "=", "!=", "&", "|", "atan2", "mod", "pow", "div",
                          "max", "min"};
    const double vals[] = {-2.5, -0.3, 0, 0.7, 1.5, 3e9, kNaN};
    for (const char* op : ops1)
        for (double a : vals) {
            const std::string k = std::isnan(a) ? "nan" : std::to_string(a);
            auto folded = compile(sexpr(std::string("(") + op + " " + k + ")"), 1, {});
            auto run = compile(sexpr(std::string("(") + op + " x)"), 1, {});
            Scratch s(*run);
            const double a0 = std::strtod(k.c_str(), nullptr);
            EXPECT_TRUE(same(eval(*folded, &a0, s), eval(*run, &a0, s))) << op << " " << k;
        }
    for (const char* op : ops2)
        for (double a : vals)
            for (double b : vals) {
                const std::string ka = std::isnan(a) ? "nan" : std::to_string(a);
                const std::string kb = std::isnan(b) ? "nan" : std::to_string(b);
                auto folded = compile(sexpr(std::string("(") + op + " " + ka + " " + kb + ")"), 1, {});
                auto run = compile(sexpr(std::string("(") + op + " x y)"), 2, {});
                Scratch s(*run);
                const double ab[2] = {std::strtod(ka.c_str(), nullptr), std::strtod(kb.c_str(), nullptr)};
                EXPECT_TRUE(same(eval(*folded, ab, s), eval(*run, ab, s))) << op << " " << ka << " " << kb;
            }
}

TEST(FnMachine, ThreadsShareOneTable) {
    // Two threads evaluate the same const table (calls, a host function, an internal function,
    // a loop) at the same points, each with its own Scratch; both must match a one-thread run.
    static const int three = 3;
    FunctionTable t;
    t.addHost({&hostVector, &three, 3, 3});
    t.addFloat(sexpr("(+ (call 0 .x x y z) (internal 70 x y z 0.8 0.2))"), 3);
    t.addFloat(sexpr("(- (call 1 x y z) (sum 0 1 3 (* i0 (sin (+ x (+ y z))))))"), 3);
    CompileOptions noInline;
    noInline.inlineCalls = false;
    t.addFloat(sexpr("(* (call 2 x y z) (call 2 z y x))"), 3, noInline);
    const FunctionTable& table = t;
    const int n = 20000;
    auto point = [](int i, double* a) {
        a[0] = std::sin(i * 0.1);
        a[1] = std::cos(i * 0.07);
        a[2] = 0.001 * i;
    };
    std::vector<double> expect(n);
    {
        Scratch s = table.makeScratch();
        for (int i = 0; i < n; ++i) {
            double a[3];
            point(i, a);
            expect[i] = table.call(3, a, s);
        }
    }
    std::vector<double> got[2] = {std::vector<double>(n), std::vector<double>(n)};
    auto work = [&](int k) {
        Scratch s = table.makeScratch();
        for (int i = 0; i < n; ++i) {
            double a[3];
            point(i, a);
            got[k][i] = table.call(3, a, s);
        }
    };
    std::thread a(work, 0), b(work, 1);
    a.join();
    b.join();
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < n; ++i) ASSERT_TRUE(same(got[k][i], expect[i])) << k << " " << i;
}

TEST(FnMachine, FusedInstructionsRoundLikeTheSeparateOps) {
    // a*b + c with a*b inexact: a fused multiply-add would round once and differ in the last bit.
    const double a = 1 + 0x1p-30, b = 1 - 0x1p-30, c = -1;
    volatile double product = a * b;  // rounded, as the tree's Mul is
    const double twoRoundings = product + c;
    ASSERT_NE(twoRoundings, std::fma(a, b, c));  // the case distinguishes them
    EXPECT_EQ(value("(+ (* x y) z)", {a, b, c}), twoRoundings);
    EXPECT_EQ(value("(- (* x y) z)", {a, b, -c}), twoRoundings);
}

TEST(FnMachine, JumpedArmsWithComputedTests) {
    // The test value lives in a temporary that must survive the first arm (select with four
    // arguments tests it twice); every arm is expensive enough to be jumped around.
    const std::string arm1 = "(sin (cos (sin (cos (sin (cos (* y 2)))))))";
    const std::string arm2 = "(cos (sin (cos (sin (cos (sin (* y 3)))))))";
    const std::string arm3 = "(exp (sin (cos (sin (cos (sin (* y 4)))))))";
    const std::string sel = "(select (- (* x x) 1) " + arm1 + " " + arm2 + " " + arm3 + ")";
    const double y = 0.3;
    auto f = [](double v, double k) { return std::sin(std::cos(std::sin(std::cos(std::sin(std::cos(v * k)))))); };
    auto g = [](double v, double k) { return std::cos(std::sin(std::cos(std::sin(std::cos(std::sin(v * k)))))); };
    auto h = [](double v, double k) { return std::exp(std::sin(std::cos(std::sin(std::cos(std::sin(v * k)))))); };
    EXPECT_EQ(value(sel, {0.5, y}), f(opaque(y), 2));
    EXPECT_EQ(value(sel, {1, y}), g(opaque(y), 3));
    EXPECT_EQ(value(sel, {-1.5, y}), h(opaque(y), 4));
    const std::string cond = "(+ 1 (?: (- x 1) " + arm1 + " " + arm2 + "))";
    EXPECT_EQ(value(cond, {3, y}), 1 + f(opaque(y), 2));
    EXPECT_EQ(value(cond, {1, y}), 1 + g(opaque(y), 3));
    // CompileOptions::branches turns the jumps off (value() has run both forms).
    auto jumps = [](const Program& p) {
        int n = 0;
        for (const Instr& in : p.code) n += in.op == Code::Jump || in.op == Code::JumpIfNotNeg;
        return n;
    };
    CompileOptions straight;
    straight.branches = false;
    EXPECT_GT(jumps(*compile(sexpr(sel), 2, {})), 0);
    EXPECT_EQ(jumps(*compile(sexpr(sel), 2, {}, straight)), 0);
}

TEST(FnMachine, BatchRunsCalleesThatAreNotInlined) {
    // One callee with batch code, one with a loop (run lane by lane), neither inlined.
    FunctionTable t;
    CompileOptions noInline;
    noInline.inlineCalls = false;
    t.addFloat(sexpr("(+ (* x x) (* y z))"), 3, noInline);
    t.addFloat(sexpr("(sum 0 1 3 (* i0 x))"), 1, noInline);
    const int top = t.addFloat(sexpr("(- (call 0 x y z) (call 1 (+ x 1)))"), 3, noInline);
    const Program& p = t.program(top);
    ASSERT_FALSE(p.batch.empty());
    ASSERT_EQ(p.callees.size(), 2u);
    const size_t n = 70;
    std::vector<double> x(n), y(n), z(n), out(n);
    for (size_t i = 0; i < n; ++i) {
        x[i] = 0.1 * static_cast<double>(i);
        y[i] = 1 - 0.05 * static_cast<double>(i);
        z[i] = 0.5;
    }
    Scratch s = t.makeScratch();
    evalBatchXYZ(p, x.data(), y.data(), z.data(), out.data(), n, s);
    for (size_t i = 0; i < n; ++i) {
        const double a[3] = {x[i], y[i], z[i]};
        EXPECT_TRUE(same(out[i], eval(p, a, s))) << i;  // batch = scalar, bit for bit
        EXPECT_NEAR(out[i], (x[i] * x[i] + y[i] * z[i]) - 6 * (x[i] + 1), 1e-12) << i;
    }
}

std::atomic<int> hostRuns{0};
// A host function that counts its runs: in[0] + 7.
void countingHost(const void*, const double* in, double* out) {
    ++hostRuns;
    out[0] = in[0] + 7;
}

TEST(FnMachine, CallsWithConstantArgumentsFoldOnlyWhenSafe) {
    // A call that is not inlined, with constant arguments, is folded by running the callee at
    // compile time. Not when the callee runs a host function (at parse time pattern and pigment
    // functions give 0, their rendered value is not known yet), and not when its loops and calls
    // run long: no parse loop limit guards the compile.
    FunctionTable t;
    CompileOptions noInline;
    noInline.inlineCalls = false;
    t.addHost({&countingHost, nullptr, 3, 1});
    t.addFloat(sexpr("(* 2 (call 0 x y z))"), 3, noInline);          // 1: calls the host
    t.addFloat(sexpr("(sum 0 1 1000000 (* i0 x))"), 1, noInline);    // 2: a long loop
    t.addFloat(sexpr("(sum 0 1 10 (* i0 x))"), 1, noInline);         // 3: a short loop
    hostRuns = 0;
    auto viaHost = compile(sexpr("(call 1 1 2 3)"), 1, t.programs(), noInline);
    EXPECT_EQ(hostRuns, 0);
    EXPECT_EQ(viaHost->callees.size(), 1u);
    Scratch s(*viaHost);
    const double x = 0;
    EXPECT_EQ(eval(*viaHost, &x, s), 16);
    EXPECT_EQ(hostRuns, 1);
    auto longLoop = compile(sexpr("(call 2 2)"), 1, t.programs(), noInline);
    EXPECT_EQ(longLoop->callees.size(), 1u);
    s.fit(*longLoop);
    EXPECT_EQ(eval(*longLoop, &x, s), 1000001000000.0);
    auto shortLoop = compile(sexpr("(call 3 2)"), 1, t.programs(), noInline);
    EXPECT_TRUE(shortLoop->callees.empty());  // folded
    EXPECT_EQ(eval(*shortLoop, &x, s), 110);
    // Calls count as loops do: a chain where each function calls the one before twice runs
    // 2^20 calls.
    FunctionTable chain;
    chain.addFloat(sexpr("(+ x 1)"), 1, noInline);
    for (int k = 0; k < 20; ++k)
        chain.addFloat(sexpr("(+ (call " + std::to_string(k) + " x) (call " + std::to_string(k) + " x))"), 1, noInline);
    auto top = compile(sexpr("(call 20 1)"), 1, chain.programs(), noInline);
    EXPECT_EQ(top->callees.size(), 1u);
    s.fit(*top);
    EXPECT_EQ(eval(*top, &x, s), 2.0 * (1 << 20));
}

}}  // namespace RAYS_TEST_UNIT, namespace
