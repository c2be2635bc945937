#include "rays/image/ssim.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "rays/error.h"

// Numerics. The formula is evaluated in the equivalent form
//   SSIM = (1 − (μa − μb)² / (μa² + μb² + C1)) · (1 − (E[d²] − (μa − μb)²) / (σa² + σb² + C2)),
// d = a − b, since 2μaμb + C1 = (μa² + μb² + C1) − (μa − μb)² and
// 2σab + C2 = (σa² + σb² + C2) − Var(d). The dissimilar parts come from the differences
// themselves rather than from cancelling large moments, so identical images give exactly 1 even
// when the compiler fuses multiply-adds (-march=native), and nearly equal ones lose no precision.
// Sums are in double.
//
// Vectorisation: the build uses -O2, where GCC vectorises only loops with a compile-time trip
// count, so the per-pixel loops run over blocks of kBlock pixels (the last block of a row is
// shifted left to end at the row's end, recomputing a few pixels with identical results).

namespace rays {
namespace {

constexpr int kBlock = 16;
constexpr int kQuantities = 5;  // filtered a, b, a², b², (a − b)²

template <int W>
using Width = std::integral_constant<int, W>;

// f(Width<kBlock>{}, x0) over [0, n) in full blocks, the last one overlapping its neighbour;
// f(Width<1>{}, x) per pixel when n < kBlock. Only for blocks that write their own outputs.
template <class F>
inline void forEachBlock(int n, F&& f) {
    if (n < kBlock) {
        for (int x = 0; x < n; ++x) f(Width<1>{}, x);
        return;
    }
    int x = 0;
    for (; x + kBlock <= n; x += kBlock) f(Width<kBlock>{}, x);
    if (x < n) f(Width<kBlock>{}, n - kBlock);
}

// out[x] = Σ_i w[i] · in[x + i] for x in [0, n).
void filterRow(const double* __restrict in, const double* __restrict w, int taps, int n, double* __restrict out) {
    forEachBlock(n, [&](auto width, int x0) {
        constexpr int N = decltype(width)::value;
        double acc[N] = {};
        for (int i = 0; i < taps; ++i) {
            const double wi = w[i];
            const double* src = in + x0 + i;
            for (int k = 0; k < N; ++k) acc[k] += wi * src[k];
        }
        for (int k = 0; k < N; ++k) out[x0 + k] = acc[k];
    });
}

// The ring of horizontally filtered rows: slot s holds kQuantities rows of n values.
struct Ring {
    int n = 0, rows = 0;
    std::vector<double> data;
    Ring(int n_, int rows_) : n(n_), rows(rows_), data(size_t(n_) * size_t(rows_) * kQuantities) {}
    double* row(int slot, int q) { return data.data() + (size_t(slot) * kQuantities + size_t(q)) * size_t(n); }
};

// map[x] = SSIM at output column x from the ring rows of the window whose top input row is
// `top` (slots (top + j) mod rows), vertical weights wy.
void ssimRow(Ring& ring, int top, const std::vector<double>& wy, double* __restrict map) {
    constexpr double C1 = kSsimK1 * kSsimK1, C2 = kSsimK2 * kSsimK2;
    const int taps = int(wy.size());
    const double* rows[kSsimWindow][kQuantities];
    for (int j = 0; j < taps; ++j)
        for (int q = 0; q < kQuantities; ++q) rows[j][q] = ring.row((top + j) % ring.rows, q);
    forEachBlock(ring.n, [&](auto width, int x0) {
        constexpr int N = decltype(width)::value;
        double s[kQuantities][N] = {};
        for (int j = 0; j < taps; ++j) {
            const double w = wy[size_t(j)];
            for (int q = 0; q < kQuantities; ++q) {
                const double* src = rows[j][q] + x0;
                for (int k = 0; k < N; ++k) s[q][k] += w * src[k];
            }
        }
        for (int k = 0; k < N; ++k) {
            const double ma = s[0][k], mb = s[1][k];
            const double dm = ma - mb, dm2 = dm * dm;
            const double maa = ma * ma, mbb = mb * mb;
            const double luma = maa + mbb + C1, contrast = (s[2][k] - maa) + (s[3][k] - mbb) + C2;
            map[x0 + k] = (1.0 - dm2 / luma) * (1.0 - (s[4][k] - dm2) / contrast);
        }
    });
}

// Mean SSIM of two width×height planes whose rows loadA(y, out) and loadB(y, out) write as
// `width` values in [0, 1].
template <class LoadA, class LoadB>
double ssimRows(int width, int height, LoadA&& loadA, LoadB&& loadB) {
    const std::vector<double> wx = ssimWindow(width), wy = ssimWindow(height);
    const int tapsX = int(wx.size()), tapsY = int(wy.size());
    const int outW = width - tapsX + 1, outH = height - tapsY + 1;

    Ring ring(outW, tapsY);
    const size_t w = static_cast<size_t>(width);
    std::vector<double> a(w), b(w), prod(w), map(static_cast<size_t>(outW));
    double total = 0;
    for (int y = 0; y < height; ++y) {
        loadA(y, a.data());
        loadB(y, b.data());
        const int slot = y % tapsY;
        filterRow(a.data(), wx.data(), tapsX, outW, ring.row(slot, 0));
        filterRow(b.data(), wx.data(), tapsX, outW, ring.row(slot, 1));
        for (size_t x = 0; x < w; ++x) prod[x] = a[x] * a[x];
        filterRow(prod.data(), wx.data(), tapsX, outW, ring.row(slot, 2));
        for (size_t x = 0; x < w; ++x) prod[x] = b[x] * b[x];
        filterRow(prod.data(), wx.data(), tapsX, outW, ring.row(slot, 3));
        for (size_t x = 0; x < w; ++x) prod[x] = (a[x] - b[x]) * (a[x] - b[x]);
        filterRow(prod.data(), wx.data(), tapsX, outW, ring.row(slot, 4));
        if (y < tapsY - 1) continue;
        ssimRow(ring, y - tapsY + 1, wy, map.data());
        double rowSum = 0;
        for (double v : map) rowSum += v;
        total += rowSum;
    }
    return total / (double(outW) * double(outH));
}

// Writes row y of img's colour channel c (0..2; 3 = Rec. 601 luma) as values /255.
void loadChannel(const Image8& img, int y, int c, double* out) {
    const uint8_t* row = img.row(y);
    const size_t n = size_t(img.channels);
    constexpr double kInv = 1.0 / 255.0;
    if (n < 3) {  // grey (+ alpha): R = G = B = luma
        for (size_t x = 0; x < size_t(img.width); ++x) out[x] = double(row[x * n]) * kInv;
        return;
    }
    if (c < 3) {
        for (size_t x = 0; x < size_t(img.width); ++x) out[x] = double(row[x * n + size_t(c)]) * kInv;
        return;
    }
    for (size_t x = 0; x < size_t(img.width); ++x) {
        const uint8_t* p = row + x * n;
        out[x] = (0.299 * double(p[0]) + 0.587 * double(p[1]) + 0.114 * double(p[2])) * kInv;
    }
}

}  // namespace

std::vector<double> ssimWindow(int side) {
    const int n = std::clamp(side, 1, kSsimWindow);
    const double centre = double(n - 1) / 2.0;
    std::vector<double> w(static_cast<size_t>(n));
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const double d = double(i) - centre;
        w[size_t(i)] = std::exp(-d * d / (2.0 * kSsimSigma * kSsimSigma));
        sum += w[size_t(i)];
    }
    for (double& v : w) v /= sum;
    return w;
}

double ssim(const float* a, const float* b, int width, int height) {
    auto rows = [width](const float* plane) {
        return [plane, width](int y, double* out) { std::copy_n(plane + size_t(y) * size_t(width), width, out); };
    };
    return ssimRows(width, height, rows(a), rows(b));
}

SsimRgb ssimRgb(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height)
        throw Error("rays: error: SSIM needs images of the same size (" + std::to_string(a.width) + "x" +
                    std::to_string(a.height) + " and " + std::to_string(b.width) + "x" + std::to_string(b.height) + ")");
    if (a.width <= 0 || a.height <= 0) throw Error("rays: error: SSIM of an empty image");
    SsimRgb out;
    const bool grey = a.channels < 3 && b.channels < 3;  // all four planes are the same
    for (int c = 0; c < (grey ? 1 : 4); ++c) {
        const double s = ssimRows(
            a.width, a.height, [&](int y, double* row) { loadChannel(a, y, c, row); },
            [&](int y, double* row) { loadChannel(b, y, c, row); });
        (c < 3 ? out.channel[c] : out.luma) = s;
    }
    if (grey) out.channel[1] = out.channel[2] = out.luma = out.channel[0];
    return out;
}

}  // namespace rays
