#include "rays/accel/huge_pages.h"

#include <cstdint>
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

void adviseHugePages(void* p, size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const auto begin = (reinterpret_cast<uintptr_t>(p) + kHugePage - 1) / kHugePage * kHugePage;
    const auto end = (reinterpret_cast<uintptr_t>(p) + bytes) / kHugePage * kHugePage;
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)p, (void)bytes;
#endif
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
