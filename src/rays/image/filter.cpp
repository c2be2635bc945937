#include "rays/image/filter.h"

#include <algorithm>
#include <type_traits>

#include "rays/error.h"
#include "rays/image/parallel.h"

namespace rays {
namespace {

std::vector<float> toFloats(const std::vector<double>& v) { return std::vector<float>(v.begin(), v.end()); }

// Rows per work item of the 8-bit conversions.
constexpr int kConvertRows = 64;
// Pixels per block of the conversion loops (a constant trip count, which -O2 vectorises).
constexpr int kConvertBlock = 64;

void runRows(int height, int threads, auto&& rowFn) {
    const int bands = (height + kConvertRows - 1) / kConvertRows;
    parallelFor(bands, threads, [&](int b) {
        const int y1 = std::min(height, (b + 1) * kConvertRows);
        for (int y = b * kConvertRows; y < y1; ++y) rowFn(y);
    });
}

// Calls f(x0, n) on blocks of kConvertBlock pixels (n a compile-time constant), then on the rest
// one pixel at a time.
template <class F>
inline void forBlocks(int w, F&& f) {
    int x = 0;
    for (; x + kConvertBlock <= w; x += kConvertBlock) f(x, std::integral_constant<int, kConvertBlock>{});
    for (; x < w; ++x) f(x, std::integral_constant<int, 1>{});
}

inline uint8_t quantise(float v) {
    // round(v·255) clamped to 0..255; NaN gives 0. Branch-free so that blocks vectorise.
    const float q = std::min(std::max(v * 255.0f + 0.5f, 0.0f), 255.0f);
    return uint8_t(q == q ? q : 0.0f);
}

// Channel c of the interleaved 8-bit row (CH channels) to floats in 0..1, and back. The blocks
// are functions with __restrict parameters so that GCC vectorises them at -O2.
template <int CH, int N>
inline void unpackBlock(const uint8_t* __restrict in, float* __restrict out) {
    for (int b = 0; b < N; ++b) out[b] = float(in[b * CH]) / 255.0f;
}

template <int CH, int N>
inline void packBlock(const float* __restrict in, uint8_t* __restrict out) {
    for (int b = 0; b < N; ++b) out[b * CH] = quantise(in[b]);
}

template <int CH>
void unpackRow(const uint8_t* row, int w, int c, float* plane) {
    forBlocks(w, [&](int x0, auto n) { unpackBlock<CH, decltype(n)::value>(row + size_t(x0) * CH + size_t(c), plane + x0); });
}

template <int CH>
void packRow(const float* plane, int w, int c, uint8_t* row) {
    forBlocks(w, [&](int x0, auto n) { packBlock<CH, decltype(n)::value>(plane + x0, row + size_t(x0) * CH + size_t(c)); });
}

template <int CH>
void filterInterleaved(Image8& img, const std::vector<KernelSpec>& kernels, BorderMode border, int threads) {
    constexpr int colour = CH >= 3 ? 3 : 1;  // grey+alpha and RGBA keep their last channel
    const int w = img.width;
    PlanarImage p(w, img.height, colour);
    runRows(img.height, threads, [&](int y) {
        for (int c = 0; c < colour; ++c) unpackRow<CH>(img.row(y), w, c, p.plane(c) + size_t(y) * size_t(w));
    });
    applyFilters(p, kernels, border, threads);
    runRows(img.height, threads, [&](int y) {
        for (int c = 0; c < colour; ++c) packRow<CH>(p.plane(c) + size_t(y) * size_t(w), w, c, img.row(y));
    });
}

}  // namespace

BorderMode parseBorderMode(const std::string& name) {
    if (name == "clamp") return BorderMode::Clamp;
    if (name == "zero") return BorderMode::Zero;
    if (name == "white") return BorderMode::White;
    if (name == "reflect") return BorderMode::Reflect;
    throw Error("rays: error: unknown border mode '" + name + "' (use clamp, zero, white or reflect)");
}

const char* borderModeName(BorderMode mode) {
    switch (mode) {
        case BorderMode::Clamp: return "clamp";
        case BorderMode::Zero: return "zero";
        case BorderMode::White: return "white";
        case BorderMode::Reflect: return "reflect";
    }
    return "clamp";
}

void applyKernel(const KernelSpec& k, const PlanarImage& src, PlanarImage& dst, BorderMode border, int threads) {
    switch (k.kind) {
        case KernelKind::BoxBlur:
            boxBlur(src, dst, k.width, border, threads);
            return;
        case KernelKind::GaussianBlur: {
            const std::vector<float> g = toFloats(gaussianWeights(k.width, k.sigma));
            convolveSeparable(src, dst, g, g, border, false, threads);
            return;
        }
        case KernelKind::EdgeDetect1:
        case KernelKind::EdgeDetect2:
        case KernelKind::Sharpen:
        case KernelKind::Emboss: {
            const std::vector<float> w = toFloats(k.weights);
            convolveDirect(src, dst, w.data(), k.width, k.height, border, k.absolute, threads);
            return;
        }
        case KernelKind::Custom: {
            std::vector<float> h, v;
            // Two 1-D passes pay off from 5×5 on (3×3: 6 taps plus a padded row against 9 taps).
            if (k.width * k.height > 2 * (k.width + k.height) && splitSeparable(k.weights, k.width, k.height, h, v)) {
                convolveSeparable(src, dst, h, v, border, k.absolute, threads);
            } else {
                const std::vector<float> w = toFloats(k.weights);
                convolveDirect(src, dst, w.data(), k.width, k.height, border, k.absolute, threads);
            }
            return;
        }
        case KernelKind::Brighten:
            scaleImage(src, dst, float(k.factor), threads);
            return;
        case KernelKind::Sobel:
            sobelMagnitude(src, dst, border, threads);
            return;
        case KernelKind::Median:
            medianFilter(src, dst, k.width, border, threads);
            return;
    }
}

void applyFilters(PlanarImage& img, const std::vector<KernelSpec>& kernels, BorderMode border, int threads) {
    PlanarImage tmp;
    for (const KernelSpec& k : kernels) {
        applyKernel(k, img, tmp, border, threads);
        std::swap(img, tmp);
    }
}

void applyFiltersInPlace(Image8& img, const std::vector<KernelSpec>& kernels, BorderMode border, int threads) {
    if (img.channels < 1 || img.channels > 4 || img.width <= 0 || img.height <= 0 ||
        img.pixels.size() != size_t(img.width) * size_t(img.height) * size_t(img.channels))
        throw Error("rays: error: cannot filter an image of " + std::to_string(img.width) + "x" +
                    std::to_string(img.height) + " pixels with " + std::to_string(img.channels) + " channels");
    if (kernels.empty()) return;
    switch (img.channels) {
        case 1: filterInterleaved<1>(img, kernels, border, threads); break;
        case 2: filterInterleaved<2>(img, kernels, border, threads); break;
        case 3: filterInterleaved<3>(img, kernels, border, threads); break;
        default: filterInterleaved<4>(img, kernels, border, threads); break;
    }
}

Image8 applyFilters(const Image8& img, const std::vector<KernelSpec>& kernels, BorderMode border, int threads) {
    Image8 out = img;
    applyFiltersInPlace(out, kernels, border, threads);
    return out;
}

ImageF applyFilters(const ImageF& img, const std::vector<KernelSpec>& kernels, BorderMode border, int threads) {
    if (img.width <= 0 || img.height <= 0 || kernels.empty()) return img;
    const int w = img.width;
    PlanarImage p(w, img.height, 3);
    runRows(img.height, threads, [&](int y) {
        for (int x = 0; x < w; ++x) {
            const Vec3& v = img.at(x, y);
            for (int c = 0; c < 3; ++c) p.at(c, x, y) = float(v[c]);
        }
    });
    applyFilters(p, kernels, border, threads);
    ImageF out(w, img.height);
    runRows(img.height, threads, [&](int y) {
        for (int x = 0; x < w; ++x) out.at(x, y) = Vec3(p.at(0, x, y), p.at(1, x, y), p.at(2, x, y));
    });
    return out;
}

}  // namespace rays
