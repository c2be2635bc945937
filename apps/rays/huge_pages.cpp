#include "huge_pages.h"

#include <malloc.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>

#include "rays/accel/huge_pages.h"

namespace rays::cli {

void enableHugePages() {
    // Large blocks come from the heap and stay there when freed, so a later buffer of the
    // render reuses pages that are already mapped instead of faulting in fresh (zeroed) ones.
    // The mmap threshold must stay above kHugeHeapBytes so the block below comes from the heap.
    mallopt(M_MMAP_THRESHOLD, 512 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    if (std::getenv("RAYS_NO_HUGEPAGES") != nullptr) return;
    void* block = std::malloc(kHugeHeapBytes);
    if (block == nullptr) return;
    constexpr std::uintptr_t kHuge = tribvh::kHugePage;
    const auto start = reinterpret_cast<std::uintptr_t>(block);
    const std::uintptr_t begin = (start + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t end = (start + kHugeHeapBytes) & ~(kHuge - 1);
    // Best effort: without THP support the advice fails and the heap simply uses normal pages.
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
    std::free(block);
}

}  // namespace rays::cli
