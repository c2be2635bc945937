#include "rays/image/convolve.h"


#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#include "rays/image/parallel.h"

// Vectorisation notes. The build uses -O2, where GCC vectorises only loops whose trip count is a
// known multiple of the vector width and that need no run-time alias check. So every hot loop runs
// over a block of kBlock pixels (a compile-time constant): accumulators live in the separate
// arrays of Chunks (kept in vector registers across the loop over taps), and loops that store to
// memory are small functions with __restrict parameters. Borders never reach those loops: each row
// of a window is copied once into a buffer padded with the border values, and rows outside the
// image are replaced by pointers to clamped, mirrored or constant rows. Work items are tiles of
// kBandRows × kStripCols pixels with fixed boundaries.

namespace rays {
namespace {

constexpr int kBlock = 64;       // pixels per vectorised block
constexpr int kChunks = 4;       // accumulator arrays per block (see Chunks)
constexpr int kBandRows = 128;   // rows per work item; fixed, so results never depend on the thread count
constexpr int kStripCols = 512;  // columns per work item of the filters with tall windows

template <int W>
using Width = std::integral_constant<int, W>;

// Calls f(Width<kBlock>{}, x0) on the full blocks of [0, w), then f(Width<1>{}, x) on the rest.
template <class F>
inline void forEachBlock(int w, F&& f) {
    int x = 0;
    for (; x + kBlock <= w; x += kBlock) f(Width<kBlock>{}, x);
    for (; x < w; ++x) f(Width<1>{}, x);
}

// For blocks that only write their own outputs: full blocks, the last one shifted left to end at
// w (recomputing a few outputs, with identical results) instead of a scalar tail; f(Width<1>{}, x)
// per pixel only when w < kBlock.
template <class F>
inline void forEachBlockOverlapping(int w, F&& f) {
    if (w < kBlock) {
        for (int x = 0; x < w; ++x) f(Width<1>{}, x);
        return;
    }
    int x = 0;
    for (; x + kBlock <= w; x += kBlock) f(Width<kBlock>{}, x);
    if (x < w) f(Width<kBlock>{}, w - kBlock);
}

// Runs f(plane, y0, y1) for every band of rows of every plane, in parallel.
template <class F>
void forEachBand(const PlanarImage& src, int bandRows, int threads, F&& f) {
    const int bands = (src.height + bandRows - 1) / bandRows;
    parallelFor(src.channels * bands, threads, [&](int item) {
        const int c = item / bands;
        const int y0 = (item % bands) * bandRows;
        f(c, y0, std::min(src.height, y0 + bandRows));
    });
}

// Runs f(plane, y0, y1, x0, x1) for every tile of bandRows × stripCols pixels of every plane, in
// parallel. Filters whose window spans many rows work on strips of columns so that the rows of
// the window stay in the core's cache (33 full rows of a 4096-wide plane do not fit in L2 twice).
template <class F>
void forEachTile(const PlanarImage& src, int bandRows, int stripCols, int threads, F&& f) {
    const int bands = (src.height + bandRows - 1) / bandRows;
    const int strips = (src.width + stripCols - 1) / stripCols;
    parallelFor(src.channels * bands * strips, threads, [&](int item) {
        const int c = item / (bands * strips);
        const int rest = item % (bands * strips);
        const int y0 = (rest / strips) * bandRows, x0 = (rest % strips) * stripCols;
        f(c, y0, std::min(src.height, y0 + bandRows), x0, std::min(src.width, x0 + stripCols));
    });
}

void prepareDst(const PlanarImage& src, PlanarImage& dst) {
    dst.width = src.width;
    dst.height = src.height;
    dst.channels = src.channels;
    dst.data.resize(src.data.size());
}

bool isConstant(BorderMode m) { return m == BorderMode::Zero || m == BorderMode::White; }

// Rows of one plane by (possibly outside) row index: clamped or mirrored rows, or a constant row.
class RowSource {
public:
    RowSource(const PlanarImage& img, int c, BorderMode mode, float constant)
        : plane_(img.plane(c)), w_(img.width), h_(img.height), mode_(mode) {
        if (isConstant(mode)) constantRow_.assign(size_t(w_), constant);
    }
    const float* row(int y) const {
        if (y >= 0 && y < h_) return plane_ + size_t(y) * size_t(w_);
        if (!constantRow_.empty()) return constantRow_.data();
        return plane_ + size_t(borderIndex(y, h_, mode_)) * size_t(w_);
    }

private:
    const float* plane_;
    int w_, h_;
    BorderMode mode_;
    std::vector<float> constantRow_;
};

// pad holds r + w + r floats with the row already in pad[r, r + w); fills the r cells each side.
void fillRowBorders(float* pad, int w, int r, BorderMode mode, float constant) {
    float* row = pad + r;
    if (isConstant(mode)) {
        std::fill(pad, row, constant);
        std::fill(row + w, row + w + r, constant);
        return;
    }
    for (int i = 1; i <= r; ++i) {
        row[-i] = row[borderIndex(-i, w, mode)];
        row[w - 1 + i] = row[borderIndex(w - 1 + i, w, mode)];
    }
}

// The first element of v (which has 16 floats to spare) on a 64-byte boundary: aligned vector
// loads never straddle two cache lines.
float* alignedStart(std::vector<float>& v) {
    const size_t misalign = (reinterpret_cast<uintptr_t>(v.data()) / sizeof(float)) % 16;
    return v.data() + (16 - misalign) % 16;
}

// The kh rows y − ry … y + ry around the current output row y, each cut to the strip of columns
// [x0 − r, x1 + r) (pad index 0 is x = x0 − r; outside the image by border mode). advance() moves
// to y + 1, reading one new row.
class PaddedRows {
public:
    PaddedRows(const RowSource& src, int w, int x0, int x1, int r, int kh, BorderMode mode, float constant, int y)
        : src_(src), w_(w), x0_(x0), x1_(x1), r_(r), mode_(mode), constant_(constant),
          stride_(paddedStride(x1 - x0 + 2 * r)), storage_(stride_ * size_t(kh) + 16), rows_(size_t(kh)) {
        const int ry = kh / 2;
        float* base = alignedStart(storage_);
        for (int j = 0; j < kh; ++j) {
            rows_[size_t(j)] = base + stride_ * size_t(j);
            load(rows_[size_t(j)], y - ry + j);
        }
        next_ = y + ry + 1;
    }
    const float* const* rows() const { return rows_.data(); }
    void advance() {
        float* recycled = rows_[0];
        std::rotate(rows_.begin(), rows_.begin() + 1, rows_.end());
        rows_.back() = recycled;
        load(recycled, next_++);
    }

private:
    // Row stride in floats: a whole number of 64-byte lines plus one, so that the rows of a window
    // fall into different cache sets even when the strip is a power of two wide.
    static size_t paddedStride(int n) { return size_t((n + 15) / 16 * 16 + 16); }

    void load(float* dst, int y) {
        const float* row = src_.row(y);
        const int lo = x0_ - r_, hi = x1_ + r_;  // columns wanted
        const int a = std::max(0, lo), b = std::min(w_, hi);
        std::memcpy(dst + (a - lo), row + a, sizeof(float) * size_t(b - a));
        for (int x = lo; x < a; ++x) dst[x - lo] = isConstant(mode_) ? constant_ : row[borderIndex(x, w_, mode_)];
        for (int x = b; x < hi; ++x) dst[x - lo] = isConstant(mode_) ? constant_ : row[borderIndex(x, w_, mode_)];
    }

    const RowSource& src_;
    int w_, x0_, x1_, r_;
    BorderMode mode_;
    float constant_;
    size_t stride_;
    std::vector<float> storage_;
    std::vector<float*> rows_;
    int next_ = 0;
};

// Accumulators of one block of W pixels: Q separate arrays ("chunks") of C lanes each (W = 64:
// four chunks of 16 floats, one AVX-512 or two AVX2 registers each; W = 1: one float). Separate
// arrays, not one array of W, are what GCC at -O2 keeps in vector registers across a runtime loop
// over taps (one array of 64 stays in memory and the loop becomes load/store bound).
template <int W>
struct Chunks {
    static constexpr int Q = W >= kChunks ? kChunks : 1;
    static constexpr int C = W / Q;
    static_assert(Q * C == W && (Q == 1 || Q == 4 || Q == 8));
    float a0[C], a1[C], a2[C], a3[C], a4[C], a5[C], a6[C], a7[C];

    // op(chunk, offset) for each chunk; offset is the chunk's first pixel within the block.
    template <class Op>
    [[gnu::always_inline]] inline void each(Op&& op) {
        op(a0, 0);
        if constexpr (Q >= 4) {
            op(a1, C);
            op(a2, 2 * C);
            op(a3, 3 * C);
        }
        if constexpr (Q == 8) {
            op(a4, 4 * C);
            op(a5, 5 * C);
            op(a6, 6 * C);
            op(a7, 7 * C);
        }
    }
    [[gnu::always_inline]] inline void store(float* out, bool absolute) {
        each([&](float* a, int off) {
            if (absolute)
                for (int b = 0; b < C; ++b) out[off + b] = std::fabs(a[b]);
            else
                for (int b = 0; b < C; ++b) out[off + b] = a[b];
        });
    }
};

// acc = Σ_i k[i] · tap(i)[pixel] over one block, tap(i) pointing at tap i's source for the
// block's first pixel. A symmetric kernel adds each mirrored pair of sources first (half the
// multiplications).
template <class Acc, class Tap>
[[gnu::always_inline]] inline void accumulateTaps(Acc& acc, const std::vector<float>& k, bool symmetric, Tap&& tap) {
    constexpr int C = Acc::C;
    const int n = int(k.size());
    if (symmetric) {
        const int mid = n / 2;
        const float* centre = tap(mid);
        const float kc = k[size_t(mid)];
        acc.each([&](float* __restrict v, int off) {
            for (int l = 0; l < C; ++l) v[l] = kc * centre[off + l];
        });
        for (int j = 0; j < mid; ++j) {
            const float* u = tap(j);
            const float* z = tap(n - 1 - j);
            const float kj = k[size_t(j)];
            acc.each([&](float* __restrict v, int off) {
                for (int l = 0; l < C; ++l) v[l] += kj * (u[off + l] + z[off + l]);
            });
        }
    } else {
        acc.each([&](float* __restrict v, int) {
            for (int l = 0; l < C; ++l) v[l] = 0.0f;
        });
        for (int j = 0; j < n; ++j) {
            const float* u = tap(j);
            const float kj = k[size_t(j)];
            acc.each([&](float* __restrict v, int off) {
                for (int l = 0; l < C; ++l) v[l] += kj * u[off + l];
            });
        }
    }
}

bool isSymmetric(const std::vector<float>& k) {
    for (size_t i = 0; i < k.size() / 2; ++i)
        if (k[i] != k[k.size() - 1 - i]) return false;
    return true;
}

// One non-zero tap of a direct kernel: weight at row j, pad offset i.
struct Tap {
    float weight;
    int j, i;
};

// Square root by Newton iteration on 1/sqrt (the libm call GCC emits for std::sqrt keeps the loop
// scalar unless -fno-math-errno): three steps from the classic bit-level first guess reach float
// precision (within 2 ulp) for s ≥ 1e-30; smaller s give 0.
inline float sqrtNewton(float s) {
    const float t = s < 1e-30f ? 0.0f : s;
    float y = std::bit_cast<float>(0x5f375a86u - (std::bit_cast<uint32_t>(t) >> 1));
    const float half = 0.5f * t;
    y = y * (1.5f - half * y * y);
    y = y * (1.5f - half * y * y);
    y = y * (1.5f - half * y * y);
    return t * y;
}

}  // namespace


int borderIndex(int i, int n, BorderMode mode) {
    if (i >= 0 && i < n) return i;
    if (mode != BorderMode::Reflect || n == 1) return i < 0 ? 0 : n - 1;
    const int period = 2 * (n - 1);
    int m = i % period;
    if (m < 0) m += period;
    return m < n ? m : period - m;
}

float borderConstant(BorderMode mode) { return mode == BorderMode::White ? 1.0f : 0.0f; }

void convolveDirect(const PlanarImage& src, PlanarImage& dst, const float* kernel, int kw, int kh,
                    BorderMode border, bool absolute, int threads) {
    prepareDst(src, dst);
    const int w = src.width, rx = kw / 2;
    // Correlation with the kernel rotated by 180° is the convolution; zero taps are skipped.
    std::vector<Tap> taps;
    for (int j = 0; j < kh; ++j)
        for (int i = 0; i < kw; ++i) {
            const float v = kernel[size_t(kh - 1 - j) * size_t(kw) + size_t(kw - 1 - i)];
            if (v != 0.0f) taps.push_back({v, j, i});
        }
    const float constant = borderConstant(border);
    forEachTile(src, kBandRows, kStripCols, threads, [&](int c, int y0, int y1, int xs, int xe) {
        const RowSource rows(src, c, border, constant);
        PaddedRows pad(rows, w, xs, xe, rx, kh, border, constant, y0);
        for (int y = y0; y < y1; ++y, pad.advance()) {
            const float* const* p = pad.rows();
            float* out = dst.plane(c) + size_t(y) * size_t(w) + size_t(xs);
            forEachBlockOverlapping(xe - xs, [&](auto width, int x0) {
                Chunks<decltype(width)::value> acc;
                constexpr int C = decltype(acc)::C;
                acc.each([&](float* __restrict a, int) {
                    for (int b = 0; b < C; ++b) a[b] = 0.0f;
                });
                for (const Tap& t : taps) {
                    const float* s = p[t.j] + x0 + t.i;
                    const float k = t.weight;
                    acc.each([&](float* __restrict a, int off) {
                        for (int b = 0; b < C; ++b) a[b] += k * s[off + b];
                    });
                }
                acc.store(out + x0, absolute);
            });
        }
    });
}

void convolveSeparable(const PlanarImage& src, PlanarImage& dst, const std::vector<float>& horizontal,
                       const std::vector<float>& vertical, BorderMode border, bool absolute, int threads) {
    prepareDst(src, dst);
    const int w = src.width;
    const int kw = int(horizontal.size()), kh = int(vertical.size());
    const int rx = kw / 2;
    // Convolution = correlation with the reversed weights.
    const std::vector<float> hf(horizontal.rbegin(), horizontal.rend());
    const std::vector<float> vf(vertical.rbegin(), vertical.rend());
    const bool hSym = isSymmetric(hf), vSym = isSymmetric(vf);
    const float constant = borderConstant(border);

    forEachTile(src, kBandRows, kStripCols, threads, [&](int c, int y0, int y1, int xs, int xe) {
        const RowSource rows(src, c, border, constant);
        // The kh source rows of the window, cut to the columns [xs − rx, xe + rx) with the border
        // already applied; their vertical pass is then the padded input of the horizontal pass
        // (for a constant border, the constant rows and columns give constant · Σ vertical).
        PaddedRows in(rows, w, xs, xe, rx, kh, border, constant, y0);
        const int padWidth = xe - xs + 2 * rx;
        std::vector<float> padStore(static_cast<size_t>(padWidth + 16));
        float* pad = alignedStart(padStore);
        for (int y = y0; y < y1; ++y, in.advance()) {
            const float* const* r = in.rows();
            forEachBlockOverlapping(padWidth, [&](auto width, int x) {
                Chunks<decltype(width)::value> acc;
                accumulateTaps(acc, vf, vSym, [&](int j) { return r[j] + x; });
                acc.store(pad + x, false);
            });
            // Horizontal pass from the padded row.
            float* out = dst.plane(c) + size_t(y) * size_t(w) + size_t(xs);
            forEachBlockOverlapping(xe - xs, [&](auto width, int x0) {
                Chunks<decltype(width)::value> acc;
                const float* s = pad + x0;
                accumulateTaps(acc, hf, hSym, [&](int i) { return s + i; });
                acc.store(out + x0, absolute);
            });
        }
    });
}

namespace {

// out[x] = scale · Σ_{i<n} pad[x + i] for x in [0, w), by running sums. The row is cut into S
// segments with independent sums so the additions of S chains overlap; S shrinks for wide windows
// so that starting the segments stays cheaper than the row itself. The chains are spelled out
// with fold expressions (constant indices) so the S sums live in registers.
template <size_t... K>
inline void runningSumStart(const float* pad, int len, int n, float scale, float* out, float* s,
                            std::index_sequence<K...>) {
    ((s[K] = 0.0f), ...);
    for (int i = 0; i < n; ++i) ((s[K] += pad[int(K) * len + i]), ...);
    ((out[int(K) * len] = s[K] * scale), ...);
}

template <size_t... K>
inline void runningSumStep(const float* pad, int len, int n, float scale, float* out, float* s, int i,
                           std::index_sequence<K...>) {
    ((s[K] += pad[int(K) * len + i + n - 1] - pad[int(K) * len + i - 1], out[int(K) * len + i] = s[K] * scale), ...);
}

template <int S>
void runningSumRow(const float* pad, int w, int n, float scale, float* out) {
    const int len = w / S;
    float s[S];
    runningSumStart(pad, len, n, scale, out, s, std::make_index_sequence<S>{});
    for (int i = 1; i < len; ++i) runningSumStep(pad, len, n, scale, out, s, i, std::make_index_sequence<S>{});
    float last = s[S - 1];
    for (int x = S * len; x < w; ++x) {  // the remainder continues the last chain
        last += pad[x + n - 1] - pad[x - 1];
        out[x] = last * scale;
    }
}

// The blocks of the loops that write memory they might read, as far as the compiler knows: small
// functions with __restrict parameters (GCC ignores __restrict on block-scope pointers, and at -O2
// it does not vectorise loops that would need a run-time alias check).
template <int W>
inline void addBlock(float* __restrict acc, const float* __restrict in) {
    for (int b = 0; b < W; ++b) acc[b] += in[b];
}

template <int W>
inline void addDifferenceBlock(float* __restrict acc, const float* __restrict plus, const float* __restrict minus) {
    for (int b = 0; b < W; ++b) acc[b] += plus[b] - minus[b];
}

template <int W>
inline void scaleBlock(const float* __restrict in, float factor, float* __restrict out) {
    for (int b = 0; b < W; ++b) out[b] = in[b] * factor;
}

// a, m, z: rows above, at and below, padded by one (index b is pixel b − 1).
template <int W>
inline void sobelBlock(const float* __restrict a, const float* __restrict m, const float* __restrict z,
                       float* __restrict out) {
    for (int b = 0; b < W; ++b) {
        const float left = a[b] + 2.0f * m[b] + z[b];
        const float right = a[b + 2] + 2.0f * m[b + 2] + z[b + 2];
        const float gx = right - left;
        const float gy = (z[b] - a[b]) + 2.0f * (z[b + 1] - a[b + 1]) + (z[b + 2] - a[b + 2]);
        out[b] = sqrtNewton(gx * gx + gy * gy);
    }
}

// Median of each 3x3 window: sort each column of three; the median of nine is then the median of
// the largest of the three minima, the median of the three middles and the smallest maximum.
template <int W>
inline void median3Block(const float* __restrict r0, const float* __restrict r1, const float* __restrict r2,
                         float* __restrict out) {
    constexpr int C = W + 2;
    float lo[C], mi[C], hi[C];
    for (int b = 0; b < C; ++b) {
        const float u = r0[b], v = r1[b], t = r2[b];
        const float l1 = std::min(u, v), h1 = std::max(u, v);
        hi[b] = std::max(h1, t);
        const float m1 = std::min(h1, t);
        lo[b] = std::min(l1, m1);
        mi[b] = std::max(l1, m1);
    }
    for (int b = 0; b < W; ++b) {
        const float maxLo = std::max(std::max(lo[b], lo[b + 1]), lo[b + 2]);
        const float minHi = std::min(std::min(hi[b], hi[b + 1]), hi[b + 2]);
        const float m0 = mi[b], m1 = mi[b + 1], m2 = mi[b + 2];
        const float medMid = std::max(std::min(m0, m1), std::min(std::max(m0, m1), m2));
        out[b] = std::max(std::min(maxLo, medMid), std::min(std::max(maxLo, medMid), minHi));
    }
}

void runningSum(const float* pad, int w, int n, float scale, float* out) {
    const int segments = std::clamp(w / std::max(1, 4 * n), 1, 8);
    if (segments >= 8) runningSumRow<8>(pad, w, n, scale, out);
    else if (segments >= 4) runningSumRow<4>(pad, w, n, scale, out);
    else if (segments >= 2) runningSumRow<2>(pad, w, n, scale, out);
    else runningSumRow<1>(pad, w, n, scale, out);
}

}  // namespace

void boxBlur(const PlanarImage& src, PlanarImage& dst, int n, BorderMode border, int threads) {
    prepareDst(src, dst);
    const int w = src.width, r = n / 2;
    const float constant = borderConstant(border);
    const float scale = 1.0f / (float(n) * float(n));
    // Each band restarts its column sums (n rows); bands of at least 2n rows keep that cheap.
    const int band = std::max(2 * kBandRows, 2 * n);
    forEachBand(src, band, threads, [&](int c, int y0, int y1) {
        const RowSource rows(src, c, border, constant);
        std::vector<float> padStore(size_t(w + 2 * r));
        float* pad = padStore.data();
        float* col = pad + r;  // the column sums live in the middle of the padded row
        std::fill(col, col + w, 0.0f);
        for (int j = -r; j <= r; ++j) {
            const float* a = rows.row(y0 + j);
            forEachBlock(w, [&](auto width, int x0) { addBlock<decltype(width)::value>(col + x0, a + x0); });
        }
        for (int y = y0; y < y1; ++y) {
            if (y > y0) {
                const float* add = rows.row(y + r);
                const float* sub = rows.row(y - r - 1);
                forEachBlock(w, [&](auto width, int x0) {
                    addDifferenceBlock<decltype(width)::value>(col + x0, add + x0, sub + x0);
                });
            }
            fillRowBorders(pad, w, r, border, constant * float(n));
            runningSum(pad, w, n, scale, dst.plane(c) + size_t(y) * size_t(w));
        }
    });
}

void sobelMagnitude(const PlanarImage& src, PlanarImage& dst, BorderMode border, int threads) {
    prepareDst(src, dst);
    const int w = src.width;
    const float constant = borderConstant(border);
    forEachTile(src, kBandRows, kStripCols, threads, [&](int c, int y0, int y1, int xs, int xe) {
        const RowSource rows(src, c, border, constant);
        PaddedRows pad(rows, w, xs, xe, 1, 3, border, constant, y0);
        for (int y = y0; y < y1; ++y, pad.advance()) {
            const float* const* p = pad.rows();
            float* out = dst.plane(c) + size_t(y) * size_t(w) + size_t(xs);
            forEachBlockOverlapping(xe - xs, [&](auto width, int x0) {
                sobelBlock<decltype(width)::value>(p[0] + x0, p[1] + x0, p[2] + x0, out + x0);
            });
        }
    });
}

void medianFilter(const PlanarImage& src, PlanarImage& dst, int n, BorderMode border, int threads) {
    prepareDst(src, dst);
    const int w = src.width, r = n / 2;
    const float constant = borderConstant(border);
    forEachTile(src, kBandRows, kStripCols, threads, [&](int c, int y0, int y1, int xs, int xe) {
        const RowSource rows(src, c, border, constant);
        PaddedRows pad(rows, w, xs, xe, r, n, border, constant, y0);
        std::vector<float> window(size_t(n) * size_t(n));
        const size_t half = window.size() / 2;
        for (int y = y0; y < y1; ++y, pad.advance()) {
            const float* const* p = pad.rows();
            float* out = dst.plane(c) + size_t(y) * size_t(w) + size_t(xs);
            if (n == 1) {
                std::memcpy(out, p[0], sizeof(float) * size_t(xe - xs));
            } else if (n == 3) {
                forEachBlockOverlapping(xe - xs, [&](auto width, int x0) {
                    median3Block<decltype(width)::value>(p[0] + x0, p[1] + x0, p[2] + x0, out + x0);
                });
            } else {
                for (int x = 0; x < xe - xs; ++x) {
                    size_t k = 0;
                    for (int j = 0; j < n; ++j)
                        for (int i = 0; i < n; ++i) window[k++] = p[j][x + i];
                    std::nth_element(window.begin(), window.begin() + std::ptrdiff_t(half), window.end());
                    out[x] = window[half];
                }
            }
        }
    });
}

void scaleImage(const PlanarImage& src, PlanarImage& dst, float factor, int threads) {
    prepareDst(src, dst);
    const int w = src.width;
    forEachBand(src, kBandRows, threads, [&](int c, int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const float* in = src.plane(c) + size_t(y) * size_t(w);
            float* out = dst.plane(c) + size_t(y) * size_t(w);
            forEachBlockOverlapping(w, [&](auto width, int x0) { scaleBlock<decltype(width)::value>(in + x0, factor, out + x0); });
        }
    });
}

bool splitSeparable(const std::vector<double>& kernel, int kw, int kh, std::vector<float>& horizontal,
                    std::vector<float>& vertical) {
    if (kw <= 0 || kh <= 0 || kernel.size() != size_t(kw) * size_t(kh)) return false;
    size_t pivot = 0;
    for (size_t i = 1; i < kernel.size(); ++i)
        if (std::fabs(kernel[i]) > std::fabs(kernel[pivot])) pivot = i;
    const double peak = kernel[pivot];
    horizontal.assign(size_t(kw), 0.0f);
    vertical.assign(size_t(kh), 0.0f);
    if (peak == 0) {
        vertical[size_t(kh / 2)] = 1.0f;
        return true;
    }
    const int pr = int(pivot / size_t(kw)), pc = int(pivot % size_t(kw));
    // K ≈ column(pc) ⊗ row(pr) / peak.
    std::vector<double> col(static_cast<size_t>(kh)), row(static_cast<size_t>(kw));
    for (int j = 0; j < kh; ++j) col[size_t(j)] = kernel[size_t(j) * size_t(kw) + size_t(pc)];
    for (int i = 0; i < kw; ++i) row[size_t(i)] = kernel[size_t(pr) * size_t(kw) + size_t(i)] / peak;
    const double tol = 1e-6 * std::fabs(peak);
    for (int j = 0; j < kh; ++j)
        for (int i = 0; i < kw; ++i)
            if (std::fabs(kernel[size_t(j) * size_t(kw) + size_t(i)] - col[size_t(j)] * row[size_t(i)]) > tol)
                return false;
    for (int j = 0; j < kh; ++j) vertical[size_t(j)] = float(col[size_t(j)]);
    for (int i = 0; i < kw; ++i) horizontal[size_t(i)] = float(row[size_t(i)]);
    return true;
}

}  // namespace rays
