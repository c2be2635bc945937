#include "rays/accel/huge_pages.h"

#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rays::tribvh {

size_t hugeFootprint(size_t bytes) {
    return bytes >= kHugeThreshold ? (bytes + kHugePage - 1) / kHugePage * kHugePage : bytes;
}

void* hugeAlloc(size_t bytes, size_t align) {
    if (bytes == 0) bytes = 1;
    if (bytes >= kHugeThreshold) {
        const size_t size = hugeFootprint(bytes);
        void* p = std::aligned_alloc(kHugePage, size);
        if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        madvise(p, size, MADV_HUGEPAGE);
#endif
        return p;
    }
    return ::operator new(bytes, std::align_val_t(align));
}

void hugeFree(void* p, size_t bytes, size_t align) noexcept {
    if (!p) return;
    if (bytes == 0) bytes = 1;
    if (bytes >= kHugeThreshold) {
        std::free(p);
        return;
    }
    ::operator delete(p, std::align_val_t(align));
}

}  // namespace rays::tribvh
