// SSIM, the structural similarity index of Wang, Bovik, Sheikh and Simoncelli, "Image Quality
// Assessment: From Error Visibility to Structural Similarity", IEEE TIP 13(4), 2004: for every
// position of an 11×11 Gaussian window (σ = 1.5, weights summing to 1)
//   SSIM = (2·μa·μb + C1)(2·σab + C2) / ((μa² + μb² + C1)(σa² + σb² + C2)),
// C1 = (K1·L)², C2 = (K2·L)², K1 = 0.01, K2 = 0.03, L = 1 (values in [0, 1]); the image's SSIM is
// the mean over the window positions that lie wholly inside the image (the paper's reference code
// filters with 'valid', as does scikit-image with gaussian_weights and population covariance).
//
// Images narrower or lower than the window: along such a side the window is clipped to the image,
// i.e. it has as many taps as the side has pixels, Gaussian weights (σ = 1.5) about the side's
// middle renormalised to sum 1, and one position. An 8×8 image thus has one 8×8 window; a 1×1
// image compares its two pixels alone (σ = 0).
//
// The window is separable: each row is filtered horizontally once into a ring of 11 rows, and
// each output row sums the ring vertically; cost ≈ 2·5·11 multiply-adds per pixel, in double, on
// blocks of pixels the compiler vectorises (numerics: ssim.cpp).
#pragma once
#include <vector>

#include "rays/image/image.h"

namespace rays {

/// The window of Wang et al. 2004 along one side.
inline constexpr int kSsimWindow = 11;
inline constexpr double kSsimSigma = 1.5;
inline constexpr double kSsimK1 = 0.01, kSsimK2 = 0.03;

/// The 1-D window weights used along a side of `side` pixels (side ≥ 1): min(side, 11) Gaussian
/// taps (σ = 1.5) centred on the middle tap, normalised to sum 1.
std::vector<double> ssimWindow(int side);

/// Mean SSIM of two planes of width×height floats (values in [0, 1], rows top first, same layout).
/// Identical planes give exactly 1; the result lies in [−1, 1]. width, height ≥ 1.
double ssim(const float* a, const float* b, int width, int height);

/// SSIM of two 8-bit images of the same size on the stored values /255 (no gamma change).
struct SsimRgb {
    double channel[3] = {1, 1, 1};  ///< R, G, B
    double luma = 1;                ///< of Y = 0.299·R + 0.587·G + 0.114·B (Rec. 601 weights)
    /// The mean of the three channel SSIMs: the figure `rays compare` reports as "ssim".
    double mean() const { return (channel[0] + channel[1] + channel[2]) / 3.0; }
};

/// SSIM of a and b per channel and of their luma. Grey images (1 or 2 channels) count as R = G = B;
/// alpha is ignored. Throws rays::Error when the sizes differ or an image is empty.
SsimRgb ssimRgb(const Image8& a, const Image8& b);

}  // namespace rays
