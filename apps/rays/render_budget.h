// Limits checked before a render allocates or starts (docs/cli.md "Limits"): the number of samples
// per image and the memory the image buffers need, estimated from the size and the features asked
// for, so that an absurd request is refused with one clear line instead of std::bad_alloc, the
// out-of-memory killer or a render that would run for weeks.
#pragma once
#include <cstdint>
#include <string>

#include "rays/npr/edge_settings.h"
#include "rays/render/settings.h"

namespace rays::cli {

/// At most 2^40 (about 1.1e12) samples per image: width × height × samples per pixel.
inline constexpr double kMaxSamplesPerImage = 1099511627776.0;

/// What a render keeps per pixel besides the scene.
struct BufferFeatures {
    bool aaEdges = false;  ///< per-pixel hit records and marks of edge-guided AA
    bool lines = false;    ///< feature-line records, candidates and coverage
    bool mask = false;     ///< --edge-mask greyscale image
    bool post = false;     ///< --post filters (planar float copies)
};

/// Estimated bytes of image buffers per pixel.
uint64_t bytesPerPixel(const BufferFeatures& f);

/// The memory limit in bytes: $RAYS_MEMORY_LIMIT when set (a number with an optional K, M, G or T
/// suffix, powers of 1024), else the machine's physical memory (16 GiB when unknown).
uint64_t memoryLimit();

/// "1.5 GiB", "312.0 MiB".
std::string formatBytes(double bytes);

/// Throws Error "rays: error: ..." when width × height × samples exceeds kMaxSamplesPerImage or the
/// estimated buffers exceed memoryLimit().
void checkRenderBudget(int width, int height, int samplesPerPixel, const BufferFeatures& f);

}  // namespace rays::cli
