// Image filters on planar float images: direct 2-D convolution, separable convolution (two 1-D
// passes), box blur by running sums, Sobel gradient magnitude, median, scaling; four border modes.
//
// Every function filters each plane independently into dst (resized to src's shape; dst must not
// be src), splits the planes into tiles (bands of rows, cut into strips of columns for the tall
// windows) and runs them on `threads` threads (0 = all cores) with parallelFor. Tile boundaries do
// not depend on the thread count, so the results are bit-identical for any number of threads.
// Inner loops work on blocks of pixels of a fixed width that the compiler vectorises; borders are
// handled once per row (padded row copies, row pointers), never per pixel.
//
// The linear filters are true convolutions: out(x, y) = Σ K[j][i] · in(x + rx − i, y + ry − j)
// with rx = (kw − 1)/2, ry = (kh − 1)/2, so a single white pixel turns into the kernel itself.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rays/accel/huge_pages.h"

namespace rays {

/// What a filter sees outside the image.
enum class BorderMode : uint8_t {
    Clamp,    ///< the nearest edge pixel (…a a | a b c … x y z | z z…)
    Zero,     ///< 0 (black)
    White,    ///< 1 (white), as the original Julia system padded
    Reflect,  ///< mirrored about the edge pixel, which is not repeated (…c b | a b c … x y z | y x…)
};

/// Allocator of image planes: huge pages for blocks of 4 MiB and more (tribvh::hugeAlloc), which
/// makes first touching them far cheaper — a 4096×4096 float plane (64 MiB) took ~180 ms of page
/// faults with 4 KiB pages on the benchmark VM and ~7 ms with 2 MiB pages. Unlike
/// HugePageAllocator, growing a vector value-initialises (zeroes) the new floats.
template <class T>
struct PlaneAllocator {
    using value_type = T;
    PlaneAllocator() = default;
    template <class U>
    PlaneAllocator(const PlaneAllocator<U>&) noexcept {}
    T* allocate(size_t n) { return static_cast<T*>(tribvh::hugeAlloc(n * sizeof(T), alignof(T))); }
    void deallocate(T* p, size_t n) noexcept { tribvh::hugeFree(p, n * sizeof(T), alignof(T)); }
    template <class U>
    bool operator==(const PlaneAllocator<U>&) const noexcept { return true; }
};

/// Planar float image: `channels` planes of width×height floats, each top row first.
struct PlanarImage {
    int width = 0, height = 0, channels = 0;
    std::vector<float, PlaneAllocator<float>> data;

    PlanarImage() = default;
    PlanarImage(int w, int h, int c) : width(w), height(h), channels(c), data(size_t(w) * size_t(h) * size_t(c)) {}
    size_t planeSize() const { return size_t(width) * size_t(height); }
    float* plane(int c) { return data.data() + size_t(c) * planeSize(); }
    const float* plane(int c) const { return data.data() + size_t(c) * planeSize(); }
    float& at(int c, int x, int y) { return plane(c)[size_t(y) * size_t(width) + size_t(x)]; }
    float at(int c, int x, int y) const { return plane(c)[size_t(y) * size_t(width) + size_t(x)]; }
};

/// For Clamp and Reflect: the coordinate in [0, n) whose value position i (any integer) takes.
/// For Zero and White the caller uses the constant instead (this then returns the Clamp index).
int borderIndex(int i, int n, BorderMode mode);

/// The constant outside the image for Zero (0) and White (1); 0 for the other modes.
float borderConstant(BorderMode mode);

/// Direct 2-D convolution with a kw×kh kernel (row-major, both sizes odd); |result| when absolute.
/// Cost: kw·kh multiply-adds per pixel. Used for non-separable kernels and as the reference.
void convolveDirect(const PlanarImage& src, PlanarImage& dst, const float* kernel, int kw, int kh,
                    BorderMode border, bool absolute, int threads);

/// Convolution with the separable kernel K[j][i] = vertical[j] · horizontal[i] (odd lengths):
/// a vertical 1-D pass into a padded row, then a horizontal one. Symmetric weights are folded
/// (w·(a + b) once per pair). Cost: kw + kh multiply-adds per pixel.
void convolveSeparable(const PlanarImage& src, PlanarImage& dst, const std::vector<float>& horizontal,
                       const std::vector<float>& vertical, BorderMode border, bool absolute, int threads);

/// n×n mean (n odd) by running sums in both directions: constant cost per pixel whatever n.
void boxBlur(const PlanarImage& src, PlanarImage& dst, int n, BorderMode border, int threads);

/// sqrt(Gx² + Gy²) with the 3×3 Sobel kernels (1,2,1 smoothing, −1,0,1 difference), not normalised:
/// a unit step gives 4.
void sobelMagnitude(const PlanarImage& src, PlanarImage& dst, BorderMode border, int threads);

/// Median of each n×n neighbourhood (n odd), per plane. 3×3 uses a min/max network on blocks of
/// pixels; larger n select with std::nth_element per pixel (cost grows with n²).
void medianFilter(const PlanarImage& src, PlanarImage& dst, int n, BorderMode border, int threads);

/// dst = src · factor.
void scaleImage(const PlanarImage& src, PlanarImage& dst, float factor, int threads);

/// If the kw×kh kernel is (to 1e-6 of its largest weight) an outer product vertical ⊗ horizontal,
/// fills both and returns true. An all-zero kernel counts as separable.
bool splitSeparable(const std::vector<double>& kernel, int kw, int kh, std::vector<float>& horizontal,
                    std::vector<float>& vertical);

}  // namespace rays
