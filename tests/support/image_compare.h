// Test support: compare 8-bit RGB images with the course tolerance (at most 0.5 % of pixels
// differ by more than 5/255 in any channel, and mean absolute difference at most 1/255), and
// load image files as 8-bit RGB. Header-only. Decoding goes through rays::readImage (stb_image
// inside rays_core): the library compiles stb_image with STB_IMAGE_STATIC, so stbi_load is not
// an exported symbol a test could call directly.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "rays/io/image_io.h"

namespace rays::test {

/// 8-bit RGB image, rows top first, 3 bytes per pixel.
struct RgbImage {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;  ///< width * height * 3 bytes
    std::string error;            ///< set by loadPngRgb when loading failed

    /// True when the image holds pixels (loading succeeded).
    bool ok() const { return error.empty() && width > 0 && height > 0; }
};

/// How far two images are apart.
struct ImageDiff {
    double fractionOver = 0;  ///< fraction of pixels with some channel differing by > 5/255
    double meanAbs = 0;       ///< mean |difference| over all channels, in [0, 1] (1/255 = one level)
    int maxDiff = 0;          ///< largest per-channel difference, in levels 0..255
    bool sameSize = true;     ///< false when the images had different sizes (nothing compared)

    static constexpr int kLevelTolerance = 5;          ///< per-channel difference still "equal"
    static constexpr double kMaxFractionOver = 0.005;  ///< 0.5 % of pixels
    static constexpr double kMaxMeanAbs = 1.0 / 255.0;

    /// True when the images are the same size and within both course limits.
    bool matches() const {
        return sameSize && fractionOver <= kMaxFractionOver + 1e-12 && meanAbs <= kMaxMeanAbs + 1e-12;
    }

    /// One line with both figures and their limits, e.g. for test logs and failure messages.
    std::string describe() const {
        if (!sameSize) return "image sizes differ";
        char buf[256];
        std::snprintf(buf, sizeof buf,
                      "%.4f%% of pixels differ by more than %d/255 (limit %.1f%%); mean |diff| %.4f/255 "
                      "(limit 1/255); max diff %d/255",
                      fractionOver * 100.0, kLevelTolerance, kMaxFractionOver * 100.0, meanAbs * 255.0,
                      maxDiff);
        return buf;
    }
};

/// Compares two RGB buffers of `pixelCount` pixels (3 bytes each, same layout).
inline ImageDiff compareRgb(const uint8_t* a, const uint8_t* b, size_t pixelCount) {
    ImageDiff d;
    if (pixelCount == 0) return d;
    size_t over = 0;
    uint64_t sum = 0;
    for (size_t p = 0; p < pixelCount; ++p) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int diff = std::abs(int(a[3 * p + c]) - int(b[3 * p + c]));
            sum += uint64_t(diff);
            if (diff > worst) worst = diff;
        }
        if (worst > ImageDiff::kLevelTolerance) ++over;
        if (worst > d.maxDiff) d.maxDiff = worst;
    }
    d.fractionOver = double(over) / double(pixelCount);
    d.meanAbs = double(sum) / (double(pixelCount) * 3.0 * 255.0);
    return d;
}

/// Compares two images; sameSize = false (and matches() false) when their sizes differ.
inline ImageDiff compareImages(const RgbImage& expected, const RgbImage& actual) {
    if (expected.width != actual.width || expected.height != actual.height ||
        expected.pixels.size() != actual.pixels.size() ||
        expected.pixels.size() != size_t(expected.width) * size_t(expected.height) * 3) {
        ImageDiff d;
        d.sameSize = false;
        return d;
    }
    return compareRgb(expected.pixels.data(), actual.pixels.data(),
                      size_t(expected.width) * size_t(expected.height));
}

/// Loads an image file (PNG, or any format rays::readImage reads) as 8-bit RGB: grey is
/// replicated, alpha dropped (as stbi_load with 3 channels). On failure error is set.
inline RgbImage loadPngRgb(const std::string& path) {
    RgbImage img;
    Image8 src;
    try {
        src = readImage(path);
    } catch (const std::exception& e) {
        img.error = e.what();
        if (img.error.find(path) == std::string::npos) img.error = path + ": " + img.error;
        return img;
    }
    const int ch = src.channels;
    const size_t count = size_t(src.width) * size_t(src.height);
    if (ch < 1 || ch > 4 || src.pixels.size() != count * size_t(ch)) {
        img.error = path + ": unexpected image layout (" + std::to_string(ch) + " channels)";
        return img;
    }
    img.width = src.width;
    img.height = src.height;
    img.pixels.resize(count * 3);
    for (size_t p = 0; p < count; ++p) {
        const uint8_t* in = src.pixels.data() + p * size_t(ch);
        uint8_t* out = img.pixels.data() + p * 3;
        if (ch >= 3) {
            out[0] = in[0], out[1] = in[1], out[2] = in[2];
        } else {
            out[0] = out[1] = out[2] = in[0];
        }
    }
    return img;
}

}  // namespace rays::test
