#include "render_budget.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "rays/error.h"
#include "rays/npr/edge_classify.h"
#include "rays/render/tracer.h"

namespace rays::cli {

uint64_t bytesPerPixel(const BufferFeatures& f) {
    // The render's float image while the caller's is alive (2 × 24), and the 8-bit output (3).
    uint64_t b = 2 * sizeof(Vec3) + 3;
    if (f.aaEdges) b += sizeof(PathInfo) + 1;
    if (f.lines) b += 2 * sizeof(EdgeRecord) + 3 + sizeof(float);
    if (f.mask) b += 1;
    if (f.post) b += 2 * 3 * sizeof(float) + sizeof(Vec3);
    return b;
}

uint64_t memoryLimit() {
    if (const char* env = std::getenv("RAYS_MEMORY_LIMIT")) {
        char* end = nullptr;
        const double v = std::strtod(env, &end);
        double unit = 1;
        switch (*end) {
            case 'K': case 'k': unit = 1024.0; ++end; break;
            case 'M': case 'm': unit = 1024.0 * 1024; ++end; break;
            case 'G': case 'g': unit = 1024.0 * 1024 * 1024; ++end; break;
            case 'T': case 't': unit = 1024.0 * 1024 * 1024 * 1024; ++end; break;
            default: break;
        }
        if (end != env && *end == '\0' && v > 0 && v * unit < 1.8e19) return uint64_t(v * unit);
        throw Error(std::string("rays: error: RAYS_MEMORY_LIMIT must be a positive number of bytes with an optional K, M, G or T suffix, got '") +
                    env + "'");
    }
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    if (pages > 0 && page > 0) return uint64_t(pages) * uint64_t(page);
    return uint64_t(16) << 30;
}

std::string formatBytes(double bytes) {
    char buf[32];
    if (bytes >= double(uint64_t(1) << 30)) std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / double(uint64_t(1) << 30));
    else std::snprintf(buf, sizeof buf, "%.1f MiB", bytes / double(1 << 20));
    return buf;
}

void checkRenderBudget(int width, int height, int samplesPerPixel, const BufferFeatures& f) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    const double samples = double(width) * double(height) * double(samplesPerPixel);
    if (samples > kMaxSamplesPerImage) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.3g", samples);
        throw Error("rays: error: " + size + " at " + std::to_string(samplesPerPixel) + " samples per pixel is " + buf +
                    " samples, more than the limit of 2^40 (1.1e12) per image");
    }
    const double need = double(width) * double(height) * double(bytesPerPixel(f));
    const uint64_t limit = memoryLimit();
    if (need > double(limit))
        throw Error("rays: error: a " + size + " render with these options needs about " + formatBytes(need) +
                    " of image buffers, more than the memory limit of " + formatBytes(double(limit)) +
                    (std::getenv("RAYS_MEMORY_LIMIT") ? " (RAYS_MEMORY_LIMIT)" : " (physical memory)"));
}

}  // namespace rays::cli
