// Function-machine benchmark: typical isosurface functions evaluated by the machine (one point
// at a time, and in batches) and by the same formula written in C++ (the anchor), in one run.
//
//   build-bench/bench/fn_eval [Google Benchmark flags, e.g. --benchmark_repetitions=5]
//
// Each benchmark evaluates 4096 points spread over [-1.5, 1.5]³ per iteration; the summary at
// the end gives ns per evaluation and machine/native ratios. The functions:
//   sphere          sqrt(x*x + y*y + z*z) - 1
//   torus           f_torus(x, y, z, 0.8, 0.2)                  (internal(70) in the tree)
//   noisy           sqrt(x*x + y*y + z*z) - 1 + 0.3*f_noise3d(2x, 2y, 2z)
//   superellipsoid  pow(pow(|x|,2/e) + pow(|y|,2/e), e/n) + pow(|z|,2/n) - 1, e = 0.3, n = 0.5
//   expr40          a 40-node polynomial/trigonometric blend (see expr40 below)
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "rays/fn/compile.h"
#include "rays/fn/internal_functions.h"
#include "rays/fn/machine.h"
#include "rays/fn/noise.h"

using namespace rays::fn;

namespace {

constexpr int kPoints = 4096;

struct Points {
    std::vector<double> x, y, z;
    Points() : x(kPoints), y(kPoints), z(kPoints) {
        uint32_t s = 12345;
        auto next = [&] {
            s = s * 1664525u + 1013904223u;
            return (s >> 8) * (3.0 / 16777216.0) - 1.5;
        };
        for (int i = 0; i < kPoints; ++i) {
            x[i] = next();
            y[i] = next();
            z[i] = next();
        }
    }
};
const Points& points() {
    static const Points p;
    return p;
}

// Tree builders for the machine's side.
struct B {
    Expr e;
    int32_t x() { return e.param(0); }
    int32_t y() { return e.param(1); }
    int32_t z() { return e.param(2); }
    int32_t k(double v) { return e.constant(v); }
    int32_t op(Op o, int32_t a, int32_t b) { return e.add(o, {a, b}); }
    int32_t op(Op o, int32_t a) { return e.add(o, {a}); }
    int32_t add(int32_t a, int32_t b) { return op(Op::Add, a, b); }
    int32_t sub(int32_t a, int32_t b) { return op(Op::Sub, a, b); }
    int32_t mul(int32_t a, int32_t b) { return op(Op::Mul, a, b); }
    int32_t r() { return op(Op::Sqrt, add(add(mul(x(), x()), mul(y(), y())), mul(z(), z()))); }
};

Expr sphereExpr() {
    B b;
    b.sub(b.r(), b.k(1));
    return b.e;
}
double sphereNative(double x, double y, double z) { return std::sqrt(x * x + y * y + z * z) - 1; }

Expr torusExpr() {
    B b;
    const int32_t args[5] = {b.x(), b.y(), b.z(), b.k(0.8), b.k(0.2)};
    b.e.internal(70, args);
    return b.e;
}
double torusNative(double x, double y, double z) {
    const double ring = std::sqrt(x * x + z * z) - 0.8;
    return std::sqrt(ring * ring + y * y) - 0.2;
}

Expr noisyExpr() {
    B b;
    const int32_t n[3] = {b.mul(b.x(), b.k(2)), b.mul(b.y(), b.k(2)), b.mul(b.z(), b.k(2))};
    const int32_t noise = b.e.internal(76, n);
    b.add(b.sub(b.r(), b.k(1)), b.mul(b.k(0.3), noise));
    return b.e;
}
double noisyNative(double x, double y, double z) {
    return std::sqrt(x * x + y * y + z * z) - 1 + 0.3 * noise3d(2 * x, 2 * y, 2 * z);
}

Expr superellipsoidExpr() {
    B b;
    const double e = 0.3, n = 0.5;
    const int32_t ax = b.op(Op::Pow, b.op(Op::Abs, b.x()), b.k(2 / e));
    const int32_t ay = b.op(Op::Pow, b.op(Op::Abs, b.y()), b.k(2 / e));
    const int32_t az = b.op(Op::Pow, b.op(Op::Abs, b.z()), b.k(2 / n));
    b.sub(b.add(b.op(Op::Pow, b.add(ax, ay), b.k(e / n)), az), b.k(1));
    return b.e;
}
double superellipsoidNative(double x, double y, double z) {
    const double e = 0.3, n = 0.5;
    return std::pow(std::pow(std::fabs(x), 2 / e) + std::pow(std::fabs(y), 2 / e), e / n) +
           std::pow(std::fabs(z), 2 / n) - 1;
}

// 40 nodes: (x²y + 0.5·z³ − 0.3)·(1 + 0.2·sin(3x + y)) + max(x·z − 0.1, y² − z·0.7) − 0.25·(x − y)².
Expr expr40() {
    B b;
    const int32_t poly = b.sub(b.add(b.mul(b.mul(b.x(), b.x()), b.y()), b.mul(b.k(0.5), b.mul(b.z(), b.mul(b.z(), b.z())))),
                               b.k(0.3));
    const int32_t wave = b.add(b.k(1), b.mul(b.k(0.2), b.op(Op::Sin, b.add(b.mul(b.k(3), b.x()), b.y()))));
    const int32_t m = b.op(Op::Max, b.sub(b.mul(b.x(), b.z()), b.k(0.1)), b.sub(b.mul(b.y(), b.y()), b.mul(b.z(), b.k(0.7))));
    const int32_t d = b.sub(b.x(), b.y());
    b.sub(b.add(b.mul(poly, wave), m), b.mul(b.k(0.25), b.mul(d, d)));
    return b.e;
}
double expr40Native(double x, double y, double z) {
    const double poly = x * x * y + 0.5 * (z * (z * z)) - 0.3;
    const double wave = 1 + 0.2 * std::sin(3 * x + y);
    const double a = x * z - 0.1, c = y * y - z * 0.7;
    const double m = a < c ? c : a;
    const double d = x - y;
    return poly * wave + m - 0.25 * (d * d);
}

struct Case {
    const char* name;
    Expr (*expr)();
    double (*native)(double, double, double);
};
const Case kCases[] = {
    {"sphere", sphereExpr, sphereNative},
    {"torus", torusExpr, torusNative},
    {"noisy", noisyExpr, noisyNative},
    {"superellipsoid", superellipsoidExpr, superellipsoidNative},
    {"expr40", expr40, expr40Native},
};

void perEval(benchmark::State& state) {
    state.counters["ns/eval"] =
        benchmark::Counter(kPoints, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void machineScalar(benchmark::State& state, const Case& c) {
    auto p = compile(c.expr(), 3, {});
    Scratch s(*p);
    const Points& pt = points();
    for (auto _ : state) {
        double sum = 0;
        for (int i = 0; i < kPoints; ++i) {
            const double a[3] = {pt.x[i], pt.y[i], pt.z[i]};
            sum += eval(*p, a, s);
        }
        benchmark::DoNotOptimize(sum);
    }
    perEval(state);
}

void machineBatch(benchmark::State& state, const Case& c) {
    auto p = compile(c.expr(), 3, {});
    Scratch s(*p);
    const Points& pt = points();
    std::vector<double> out(kPoints);
    for (auto _ : state) {
        evalBatchXYZ(*p, pt.x.data(), pt.y.data(), pt.z.data(), out.data(), kPoints, s);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    perEval(state);
}

void native(benchmark::State& state, const Case& c) {
    const Points& pt = points();
    double (*f)(double, double, double) = c.native;
    benchmark::DoNotOptimize(f);  // an opaque call per point, as a renderer's function pointer would be
    for (auto _ : state) {
        double sum = 0;
        for (int i = 0; i < kPoints; ++i) sum += f(pt.x[i], pt.y[i], pt.z[i]);
        benchmark::DoNotOptimize(sum);
    }
    perEval(state);
}

// Collects ns/eval per benchmark name for the summary.
class Summary : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> ns;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) {
            if (r.error_occurred) continue;
            auto it = r.counters.find("ns/eval");
            if (it == r.counters.end()) continue;
            const std::string name = r.benchmark_name();
            // Keep the median of repetitions when there are any, else the plain run.
            if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
            ns[name.substr(0, name.find("_median"))] = it->second.value * 1e9;
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

}  // namespace

int main(int argc, char** argv) {
    for (const Case& c : kCases) {
        benchmark::RegisterBenchmark((std::string("machine/") + c.name).c_str(), machineScalar, c);
        benchmark::RegisterBenchmark((std::string("batch/") + c.name).c_str(), machineBatch, c);
        benchmark::RegisterBenchmark((std::string("native/") + c.name).c_str(), native, c);
    }
    benchmark::Initialize(&argc, argv);
    Summary summary;
    benchmark::RunSpecifiedBenchmarks(&summary);
    std::printf("\n%-16s %12s %12s %12s %14s %12s\n", "function", "machine ns", "batch ns", "native ns",
                "machine/native", "batch/native");
    for (const Case& c : kCases) {
        const double m = summary.ns[std::string("machine/") + c.name];
        const double b = summary.ns[std::string("batch/") + c.name];
        const double n = summary.ns[std::string("native/") + c.name];
        if (n <= 0) continue;
        std::printf("%-16s %12.2f %12.2f %12.2f %14.2f %12.2f\n", c.name, m, b, n, m / n, b / n);
    }
    benchmark::Shutdown();
    return 0;
}
