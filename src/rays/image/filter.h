// Image filtering, the public entry points of `rays filter` and `rays render --post`: a list of
// kernels (see kernels.h) applied in order to the colour channels of an image; alpha passes
// through unchanged. Work happens in float; 8-bit images are rounded once, at the end.
#pragma once
#include <string>
#include <vector>

#include "rays/image/convolve.h"
#include "rays/image/image.h"
#include "rays/image/kernels.h"

namespace rays {

/// "clamp", "zero", "white" or "reflect"; throws rays::Error "rays: error: unknown border mode ...".
BorderMode parseBorderMode(const std::string& name);
/// The name parseBorderMode accepts for mode.
const char* borderModeName(BorderMode mode);

/// Applies one kernel to every plane of src (dst is resized; dst must not be src).
void applyKernel(const KernelSpec& kernel, const PlanarImage& src, PlanarImage& dst, BorderMode border, int threads = 0);

/// Applies the kernels in order to every plane, in place (an empty list leaves img as it is).
void applyFilters(PlanarImage& img, const std::vector<KernelSpec>& kernels, BorderMode border, int threads = 0);

/// Filters the colour channels of an 8-bit image (1..4 channels: grey, grey+alpha, RGB, RGBA) in
/// float (value/255) and rounds once at the end, clamping to 0..255; alpha is copied unchanged.
/// threads: 0 = all cores. The result does not depend on the thread count.
Image8 applyFilters(const Image8& img, const std::vector<KernelSpec>& kernels, BorderMode border = BorderMode::Clamp,
                    int threads = 0);

/// The same, filtering img itself (saves a copy of the image; the CLI uses it).
void applyFiltersInPlace(Image8& img, const std::vector<KernelSpec>& kernels, BorderMode border = BorderMode::Clamp,
                         int threads = 0);

/// Filters a linear float RGB image (e.g. a render) in float; no clamping: values may leave 0..1
/// (sharpen, edge kernels, brighten) and the caller quantises (toImage8 clamps).
ImageF applyFilters(const ImageF& img, const std::vector<KernelSpec>& kernels, BorderMode border = BorderMode::Clamp,
                    int threads = 0);

}  // namespace rays
