#include "render_budget.h"

#include <cstdio>
#include <cstdlib>

#include "rays/error.h"
#include "rays/npr/edge_classify.h"
#include "rays/render/tracer.h"
#include "rays/util/memory_limit.h"

namespace rays::cli {

uint64_t bytesPerPixel(const BufferFeatures& f) {
    // The render's float image while the caller's is alive (2 × 24), and the 8-bit output (3).
    uint64_t b = 2 * sizeof(Vec3) + 3;
    if (f.aaEdges) b += sizeof(PathInfo) + 1;
    if (f.aaEdges && f.aaColours) b += sizeof(Vec3);
    if (f.lines) b += 2 * sizeof(EdgeRecord) + 3 + sizeof(float);
    if (f.mask) b += 1;
    if (f.post) b += 2 * 3 * sizeof(float) + sizeof(Vec3);
    return b;
}

uint64_t sceneBytes(const Scene& scene) {
    // Per object of the scene's BVH (built after this check): its share of the 8-wide nodes, the
    // leaf slots and the build's bins (accel/object_bvh.h, triangle_bvh.h), generously.
    constexpr uint64_t kBvhPerObject = 160;
    uint64_t b = scene.objects.size() * (sizeof(Object) + kBvhPerObject);
    for (const Texture& t : scene.textures) b += t.bytes();
    for (const auto& m : scene.meshes) b += m->memoryBytes();  // its own BVH included
    for (const Camera& c : scene.cameras)
        if (c.mesh) b += c.mesh->memoryBytes();  // a mesh_camera's faces
    return b;
}

void checkRenderBudget(int width, int height, int samplesPerPixel, const BufferFeatures& f, uint64_t heldBytes) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    const double samples = double(width) * double(height) * double(samplesPerPixel);
    if (samples > kMaxSamplesPerImage) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.3g", samples);
        throw Error("rays: error: " + size + " at " + std::to_string(samplesPerPixel) + " samples per pixel is " + buf +
                    " samples, more than the limit of 2^40 (1.1e12) per image");
    }
    const double buffers = double(width) * double(height) * double(bytesPerPixel(f));
    const uint64_t limit = memoryLimit();
    if (buffers + double(heldBytes) > double(limit))
        throw Error("rays: error: a " + size + " render with these options needs about " + formatBytes(buffers) +
                    " of image buffers and " + formatBytes(double(heldBytes)) + " for the scene, more than the memory limit of " +
                    formatBytes(double(limit)) + memoryLimitSource());
}

}  // namespace rays::cli
