// Comparing two 8-bit images of the same size, as `rays compare` does: SSIM (ssim.h), PSNR, mean
// and largest absolute difference, the pixels that differ by more than a threshold, and a
// difference image |A − B|·scale as OpenImageIO's `idiff -abs -scale K` writes it.
//
// Every figure works on the stored R, G, B values (no gamma change): grey images (1 or 2
// channels) count as R = G = B, alpha is ignored, so a grey image and its RGB copy are identical.
#pragma once
#include <cstddef>

#include "rays/image/image.h"
#include "rays/image/ssim.h"

namespace rays {

/// The figures of one comparison; differences are in 0..255 units.
struct ImageComparison {
    int width = 0, height = 0;
    SsimRgb ssim;                 ///< per channel and luma; ssim.mean() is the headline figure
    double mse = 0;               ///< mean squared difference over all pixels and R, G, B
    double psnr = 0;              ///< 10·log10(255² / mse) in dB; +infinity when mse = 0
    double meanAbs = 0;           ///< mean |A − B| over all pixels and R, G, B
    int maxAbs = 0;               ///< largest |A − B| of any channel
    double threshold = 5;         ///< the threshold pixelsOver was counted with
    size_t pixelsOver = 0;        ///< pixels whose largest channel difference exceeds threshold
    /// pixelsOver as a percentage of all pixels.
    double percentOver() const { return 100.0 * double(pixelsOver) / (double(width) * double(height)); }
};

/// Compares a and b (same width and height, any channel counts 1..4). threshold is in 0..255 units.
/// Throws rays::Error ("rays: error: ...") when the sizes differ or an image is empty.
ImageComparison compareImages(const Image8& a, const Image8& b, double threshold = 5);

/// RGB image of round(|A − B|·scale) per channel, clamped to 0..255 (scale ≥ 0). Same size rules
/// as compareImages.
Image8 differenceImage(const Image8& a, const Image8& b, double scale = 1);

}  // namespace rays
