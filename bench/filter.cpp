// Filter benchmark: Rays' kernels against OpenCV and against a direct 2-D convolution, all in one
// process on the same float32 RGB image (default 4096x4096), clamp/replicate borders on both sides.
//
//   build-bench/bench/filter [--size N] [--threads T] [--runs R] [--direct-runs R] [--only KERNEL]
//
// Rays works on planar float (3 planes), OpenCV on interleaved CV_32FC3, each in its own natural
// layout; conversions are outside the timed region. OpenCV calls, like for like:
//   box_blur_33       cv::blur 33x33
//   gaussian_blur_33  cv::GaussianBlur 33x33, sigma 5.5 (= 33/6, Rays' default)
//   edge_detect_2     cv::filter2D with the 3x3 kernel, then cv::abs
//   sobel             cv::Sobel dx and dy (ksize 3), then cv::magnitude
// "direct" is Rays' own vectorised direct 2-D convolution (convolveDirect) with the full matrix
// (for sobel: both 3x3 derivatives, then the magnitude). Times are medians of --runs runs after a
// warm-up (--direct-runs for the direct convolutions, without warm-up). Ratios: Rays / OpenCV
// (target <= 1.5) and direct / Rays (target >= 20 for the 33x33 kernels).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "rays/image/convolve.h"
#include "rays/image/filter.h"
#include "rays/image/kernels.h"
#include "rays/image/parallel.h"

#ifdef RAYS_BENCH_OPENCV
#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#endif

using namespace rays;

namespace {

using Clock = std::chrono::steady_clock;

struct Options {
    int size = 4096;
    int threads = 0;
    int runs = 5;
    int directRuns = 1;
    std::string only;  ///< run just this kernel (for profiling)
};

[[noreturn]] void usage() {
    std::fprintf(stderr, "usage: filter [--size N] [--threads T] [--runs R] [--direct-runs R] [--only KERNEL]\n");
    std::exit(2);
}

Options parseArgs(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc) usage();
        const int v = std::atoi(argv[++i]);  // (--only takes a name)
        if (a == "--size" && v > 0) o.size = v;
        else if (a == "--threads" && v >= 0) o.threads = v;
        else if (a == "--runs" && v > 0) o.runs = v;
        else if (a == "--direct-runs" && v > 0) o.directRuns = v;
        else if (a == "--only") o.only = argv[i];
        else usage();
    }
    return o;
}

// Median wall time of `runs` calls of f, in ms, after one untimed warm-up call when asked.
template <class F>
double timeMs(int runs, bool warmUp, F&& f) {
    if (warmUp) f();
    std::vector<double> t;
    for (int i = 0; i < runs; ++i) {
        const auto t0 = Clock::now();
        f();
        t.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

// A smooth colour gradient with noise and a few hard edges, values in [0, 1].
PlanarImage testImage(int n) {
    PlanarImage img(n, n, 3);
    uint32_t s = 2463534242u;
    for (int c = 0; c < 3; ++c)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                s ^= s << 13;
                s ^= s >> 17;
                s ^= s << 5;
                const float smooth = 0.5f + 0.3f * std::sin(0.01f * float(x + 2 * c * y)) * std::cos(0.013f * float(y));
                const float edge = ((x / 97 + y / 61) % 2) ? 0.15f : -0.15f;
                img.at(c, x, y) = std::clamp(smooth + edge + float(s % 1000) * 1e-4f - 0.05f, 0.0f, 1.0f);
            }
    return img;
}

float maxAbsDiff(const PlanarImage& a, const PlanarImage& b) {
    float m = 0;
    for (size_t i = 0; i < a.data.size(); ++i) m = std::max(m, std::fabs(a.data[i] - b.data[i]));
    return m;
}

#ifdef RAYS_BENCH_OPENCV
cv::Mat toMat(const PlanarImage& img) {
    std::vector<cv::Mat> planes;
    for (int c = 0; c < img.channels; ++c)
        planes.emplace_back(img.height, img.width, CV_32F, const_cast<float*>(img.plane(c)));
    cv::Mat out;
    cv::merge(planes, out);
    return out;
}

float maxAbsDiff(const PlanarImage& a, const cv::Mat& b) {
    return float(cv::norm(toMat(a), b, cv::NORM_INF));
}

std::string parallelFramework() {
    const std::string info = cv::getBuildInformation();
    const size_t p = info.find("Parallel framework:");
    if (p == std::string::npos) return "?";
    const size_t start = info.find_first_not_of(' ', p + 19);
    return info.substr(start, info.find('\n', start) - start);
}
#endif

struct Row {
    std::string name;
    double rays = 0, opencv = -1, direct = 0, rays8 = 0;
    float diffOpencv = -1, diffDirect = 0;
};

}  // namespace

int main(int argc, char** argv) {
    const Options opt = parseArgs(argc, argv);
    const int threads = parallelThreadCount(opt.threads);
    const int n = opt.size;
    std::printf("Rays filter benchmark: %dx%d RGB float32, clamp borders, %d thread%s, median of %d runs (direct: %d)\n",
                n, n, threads, threads == 1 ? "" : "s", opt.runs, opt.directRuns);
#ifdef RAYS_BENCH_OPENCV
    cv::setNumThreads(threads);
    std::printf("OpenCV %s, parallel framework %s, %d threads\n", CV_VERSION, parallelFramework().c_str(),
                cv::getNumThreads());
#else
    std::printf("OpenCV: not built in (install libopencv-dev and reconfigure)\n");
#endif
    std::fflush(stdout);

    const PlanarImage src = testImage(n);
    Image8 src8(n, n, 3);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            for (int c = 0; c < 3; ++c) src8.row(y)[x * 3 + c] = uint8_t(src.at(c, x, y) * 255.0f + 0.5f);
#ifdef RAYS_BENCH_OPENCV
    const cv::Mat srcMat = toMat(src);
#endif
    Image8 work8 = src8;
    std::vector<Row> rows;
    PlanarImage out, ref, gx, gy;

    for (const char* spec : {"box_blur_33", "gaussian_blur_33", "edge_detect_2", "sobel"}) {
        if (!opt.only.empty() && opt.only != spec) continue;
        Row r;
        r.name = spec;
        const KernelSpec k = parseKernelSpec(spec);
        const std::vector<KernelSpec> list{k};
        r.rays = timeMs(opt.runs, true, [&] { applyKernel(k, src, out, BorderMode::Clamp, threads); });
        // As `rays filter` does: in place on the decoded image (restored, untimed, between runs).
        {
            std::vector<double> t;
            for (int i = 0; i <= opt.runs; ++i) {
                work8.pixels = src8.pixels;
                const auto t0 = Clock::now();
                applyFiltersInPlace(work8, list, BorderMode::Clamp, threads);
                if (i > 0) t.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
            }
            std::sort(t.begin(), t.end());
            r.rays8 = t[t.size() / 2];
        }

        // Direct 2-D convolution with the whole matrix.
        if (k.kind == KernelKind::Sobel) {
            const float kx[9] = {-1, 0, 1, -2, 0, 2, -1, 0, 1}, ky[9] = {-1, -2, -1, 0, 0, 0, 1, 2, 1};
            r.direct = timeMs(opt.directRuns, false, [&] {
                convolveDirect(src, gx, kx, 3, 3, BorderMode::Clamp, false, threads);
                convolveDirect(src, gy, ky, 3, 3, BorderMode::Clamp, false, threads);
                ref.width = gx.width;
                ref.height = gx.height;
                ref.channels = gx.channels;
                ref.data.resize(gx.data.size());
                const size_t total = ref.data.size(), chunk = 65536;
                parallelFor(int((total + chunk - 1) / chunk), threads, [&](int b) {
                    for (size_t i = size_t(b) * chunk; i < std::min(total, size_t(b + 1) * chunk); ++i)
                        ref.data[i] = std::sqrt(gx.data[i] * gx.data[i] + gy.data[i] * gy.data[i]);
                });
            });
        } else {
            const std::vector<float> w(k.weights.begin(), k.weights.end());
            r.direct = timeMs(opt.directRuns, false, [&] {
                convolveDirect(src, ref, w.data(), k.width, k.height, BorderMode::Clamp, k.absolute, threads);
            });
        }
        r.diffDirect = maxAbsDiff(out, ref);

#ifdef RAYS_BENCH_OPENCV
        cv::Mat dst, tmp, dx, dy;
        std::function<void()> cvOp;
        switch (k.kind) {
            case KernelKind::BoxBlur:
                cvOp = [&] { cv::blur(srcMat, dst, cv::Size(33, 33), cv::Point(-1, -1), cv::BORDER_REPLICATE); };
                break;
            case KernelKind::GaussianBlur:
                cvOp = [&] { cv::GaussianBlur(srcMat, dst, cv::Size(33, 33), k.sigma, k.sigma, cv::BORDER_REPLICATE); };
                break;
            case KernelKind::EdgeDetect2: {
                cv::Mat K(3, 3, CV_32F);
                for (int i = 0; i < 9; ++i) K.at<float>(i / 3, i % 3) = float(k.weights[size_t(8 - i)]);  // filter2D correlates
                cvOp = [&, K] {
                    cv::filter2D(srcMat, tmp, CV_32F, K, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
                    dst = cv::abs(tmp);
                };
                break;
            }
            default:
                cvOp = [&] {
                    cv::Sobel(srcMat, dx, CV_32F, 1, 0, 3, 1, 0, cv::BORDER_REPLICATE);
                    cv::Sobel(srcMat, dy, CV_32F, 0, 1, 3, 1, 0, cv::BORDER_REPLICATE);
                    cv::magnitude(dx, dy, dst);
                };
                break;
        }
        r.opencv = timeMs(opt.runs, true, cvOp);
        r.diffOpencv = maxAbsDiff(out, dst);
#endif
        rows.push_back(r);
        std::printf("  %-17s done\n", spec);
        std::fflush(stdout);
    }

    std::printf("\n%-17s %9s %9s %11s %10s %11s %13s %12s %12s\n", "kernel", "Rays ms", "OpenCV ms", "Rays/OpenCV",
                "direct ms", "direct/Rays", "Rays 8-bit ms", "|Rays-OpenCV|", "|Rays-direct|");
    for (const Row& r : rows) {
        char cvMs[32] = "-", ratio[32] = "-", cvDiff[32] = "-";
        if (r.opencv >= 0) {
            std::snprintf(cvMs, sizeof cvMs, "%.1f", r.opencv);
            std::snprintf(ratio, sizeof ratio, "%.2f", r.rays / r.opencv);
            std::snprintf(cvDiff, sizeof cvDiff, "%.1e", double(r.diffOpencv));
        }
        std::printf("%-17s %9.1f %9s %11s %10.1f %11.1f %13.1f %12s %12.1e\n", r.name.c_str(), r.rays, cvMs, ratio,
                    r.direct, r.direct / r.rays, r.rays8, cvDiff, double(r.diffDirect));
    }
    std::printf("\nRays 8-bit: applyFiltersInPlace on an 8-bit RGB image (to float, filter, round once), end to end,\n"
                "including the first touch of its float buffers; the float columns reuse their buffers.\n");
    return 0;
}
