#include "rays/util/memory_limit.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "rays/error.h"

namespace rays {

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

const char* memoryLimitSource() { return std::getenv("RAYS_MEMORY_LIMIT") ? " (RAYS_MEMORY_LIMIT)" : " (physical memory)"; }

std::string formatBytes(double bytes) {
    char buf[32];
    if (bytes >= double(uint64_t(1) << 30)) std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / double(uint64_t(1) << 30));
    else std::snprintf(buf, sizeof buf, "%.1f MiB", bytes / double(1 << 20));
    return buf;
}

}  // namespace rays
