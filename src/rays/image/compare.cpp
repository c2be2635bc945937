#include "rays/image/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>

#include "rays/error.h"

namespace rays {
namespace {

void checkSizes(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height)
        throw Error("rays: error: images differ in size (" + std::to_string(a.width) + "x" + std::to_string(a.height) +
                    " and " + std::to_string(b.width) + "x" + std::to_string(b.height) + ")");
    if (a.width <= 0 || a.height <= 0) throw Error("rays: error: cannot compare empty images");
}

// R, G, B of pixel i (grey counts as R = G = B).
inline void rgbAt(const Image8& img, size_t i, int rgb[3]) {
    const uint8_t* p = img.pixels.data() + i * size_t(img.channels);
    if (img.channels < 3) {
        rgb[0] = rgb[1] = rgb[2] = p[0];
        return;
    }
    rgb[0] = p[0];
    rgb[1] = p[1];
    rgb[2] = p[2];
}

}  // namespace

ImageComparison compareImages(const Image8& a, const Image8& b, double threshold) {
    checkSizes(a, b);
    ImageComparison r;
    r.width = a.width;
    r.height = a.height;
    r.threshold = threshold;
    const size_t n = size_t(a.width) * size_t(a.height);
    uint64_t sumAbs = 0, sumSq = 0;
    for (size_t i = 0; i < n; ++i) {
        int pa[3], pb[3];
        rgbAt(a, i, pa);
        rgbAt(b, i, pb);
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(pa[c] - pb[c]);
            sumAbs += uint64_t(d);
            sumSq += uint64_t(d * d);
            worst = std::max(worst, d);
        }
        r.maxAbs = std::max(r.maxAbs, worst);
        if (double(worst) > threshold) ++r.pixelsOver;
    }
    const double samples = 3.0 * double(n);
    r.meanAbs = double(sumAbs) / samples;
    r.mse = double(sumSq) / samples;
    r.psnr = sumSq == 0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / r.mse);
    r.ssim = ssimRgb(a, b);
    return r;
}

Image8 differenceImage(const Image8& a, const Image8& b, double scale) {
    checkSizes(a, b);
    Image8 out(a.width, a.height, 3);
    uint8_t table[256];  // |A − B| → scaled, rounded, clamped byte
    for (int d = 0; d < 256; ++d) table[d] = uint8_t(std::lround(std::clamp(double(d) * scale, 0.0, 255.0)));
    const size_t n = size_t(a.width) * size_t(a.height);
    for (size_t i = 0; i < n; ++i) {
        int pa[3], pb[3];
        rgbAt(a, i, pa);
        rgbAt(b, i, pb);
        for (int c = 0; c < 3; ++c) out.pixels[3 * i + size_t(c)] = table[std::abs(pa[c] - pb[c])];
    }
    return out;
}

}  // namespace rays
