// Limits checked before a render allocates or starts (docs/cli.md "Limits"): the number of samples
// per image and the memory the image buffers need, estimated from the size and the features asked
// for, so that an absurd request is refused with one clear line instead of std::bad_alloc, the
// out-of-memory killer or a render that would run for weeks.
#pragma once
#include <cstdint>
#include <string>

#include "rays/npr/edge_settings.h"
#include "rays/render/settings.h"
#include "rays/scene/scene.h"

namespace rays::cli {

/// At most 2^40 (about 1.1e12) samples per image: width × height × samples per pixel.
inline constexpr double kMaxSamplesPerImage = 1099511627776.0;

/// What a render keeps per pixel besides the scene.
struct BufferFeatures {
    bool aaEdges = false;  ///< per-pixel hit records and marks of edge-guided AA
    bool aaColours = false;  ///< with aaEdges: the colours POV-Ray's threshold rule compares
    bool lines = false;    ///< feature-line records, candidates and coverage
    bool mask = false;     ///< --edge-mask greyscale image
    bool post = false;     ///< --post filters (planar float copies)
};

/// Estimated bytes of image buffers per pixel.
uint64_t bytesPerPixel(const BufferFeatures& f);

/// Bytes the loaded scene holds while it renders, estimated: its textures, its meshes with their
/// triangle BVHs, and its objects with the object BVH.
uint64_t sceneBytes(const Scene& scene);

/// Throws Error "rays: error: ..." when width × height × samples exceeds kMaxSamplesPerImage or the
/// estimated buffers plus `heldBytes` (sceneBytes) exceed memoryLimit() (util/memory_limit.h).
void checkRenderBudget(int width, int height, int samplesPerPixel, const BufferFeatures& f, uint64_t heldBytes);

}  // namespace rays::cli
