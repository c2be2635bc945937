// Image filter kernels: the closed set of kinds `rays filter` and `rays render --post` know, parsed
// from specs such as "box_blur_5", "gaussian_blur_9:2.5", "edge_detect_2", "brighten_1.5",
// "median_3" or "kernel:FILE". The file format of custom kernels is described in docs/filters.md.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace rays {

enum class KernelKind : uint8_t {
    BoxBlur,       ///< box_blur_N: N×N mean (running sums)
    GaussianBlur,  ///< gaussian_blur_N[:SIGMA]: N×N Gaussian, σ = N/6 unless given (separable)
    EdgeDetect1,   ///< edge_detect_1: |4-neighbour Laplacian| / 4
    EdgeDetect2,   ///< edge_detect_2: |8-neighbour Laplacian| / 8
    Brighten,      ///< brighten_X: multiply by X
    Sobel,         ///< sobel: sqrt(Gx² + Gy²) of the 3×3 Sobel derivatives (not normalised)
    Sharpen,       ///< sharpen: 0,-1,0 / -1,5,-1 / 0,-1,0
    Emboss,        ///< emboss: -2,-1,0 / -1,1,1 / 0,1,2
    Median,        ///< median_N: per-channel median of the N×N neighbourhood
    Custom,        ///< kernel:FILE: a matrix read from a text file
};

/// One parsed kernel. Linear kinds carry their matrix in `weights` (row-major height×width,
/// divisor applied); the filter is a true convolution, so the image of a single white pixel is the
/// matrix itself (not its 180° rotation, as a correlation would give).
struct KernelSpec {
    KernelKind kind = KernelKind::Brighten;
    std::string text;             ///< the spec as written, for messages ("gaussian_blur_5:1.2")
    int width = 1, height = 1;    ///< matrix size: N for blurs and median, 3 for 3×3 kernels, 1 for brighten
    double sigma = 0;             ///< GaussianBlur: standard deviation in pixels
    double factor = 1;            ///< Brighten: the scale factor
    bool absolute = false;        ///< output |result| (edge kernels; custom files with `absolute`)
    std::vector<double> weights;  ///< linear kinds: the matrix; empty for Sobel and Median
    std::string file;             ///< Custom: the kernel file's path
};

/// Largest N accepted for box_blur_N, gaussian_blur_N and for custom kernel sides.
inline constexpr int kMaxKernelSize = 1001;
/// Largest kernel file read (64 MiB): room for 1001 × 1001 numbers of up to 60 characters.
inline constexpr size_t kMaxKernelFileBytes = size_t(64) << 20;
/// Largest N accepted for median_N (the cost grows with N²).
inline constexpr int kMaxMedianSize = 51;

/// The valid kernel names, for messages: "box_blur_N, gaussian_blur_N[:SIGMA], ...".
std::string validKernelNames();

/// Parses one spec. Throws rays::Error "rays: error: ..." for an unknown name or a bad size, sigma
/// or factor (the message lists the valid names), and "FILE:LINE:COL: error: ..." for a bad kernel file.
KernelSpec parseKernelSpec(const std::string& spec);

/// Parses every spec in order; throws on the first bad one (see parseKernelSpec).
std::vector<KernelSpec> parseKernelList(const std::vector<std::string>& specs);

/// Splits "box_blur_3,sobel" at commas into specs (for `--post`); empty items are an error.
std::vector<std::string> splitKernelList(const std::string& commaSeparated);

/// Parses the text of a custom kernel file; `file` names it in messages and in the result.
KernelSpec parseKernelText(const std::string& text, const std::string& file);

/// Reads and parses a custom kernel file ("FILE: error: cannot read kernel file: ..." when unreadable).
KernelSpec loadKernelFile(const std::string& path);

/// The n normalised 1-D Gaussian weights exp(-i²/2σ²), i = -(n-1)/2 .. (n-1)/2, summing to 1.
std::vector<double> gaussianWeights(int n, double sigma);

/// True for the kinds that are a convolution with `weights` (everything but Brighten, Sobel, Median;
/// the edge kernels count, their absolute value being taken afterwards).
bool isConvolution(const KernelSpec& k);

}  // namespace rays
