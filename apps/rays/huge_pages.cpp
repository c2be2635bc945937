#include "huge_pages.h"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>

#include "rays/accel/huge_pages.h"

namespace rays::cli {
namespace {
// The parked block. Volatile: a block whose pointer is never read again may be elided by the
// compiler (GCC removes such a malloc), and the parking would silently not happen.
void* volatile gParkedHeap = nullptr;
}  // namespace

void enableHugePages() {
    // Large blocks come from the heap and stay there when freed, so a later buffer of the
    // render reuses pages that are already mapped instead of faulting in fresh (zeroed) ones.
    // The mmap threshold must stay above kHugeHeapBytes so the block below comes from the heap.
    mallopt(M_MMAP_THRESHOLD, 512 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    if (std::getenv("RAYS_NO_HUGEPAGES") != nullptr) return;
    // Worker threads would otherwise get arenas of their own (mapped apart, normal pages, a 4 KB
    // fault each ~11 µs on the VMs measured): one arena keeps every thread's blocks in this heap.
    // The render's hot loops do not allocate, so the shared arena's lock is not contended.
    mallopt(M_ARENA_MAX, 1);
    constexpr std::uintptr_t kHuge = tribvh::kHugePage;
    // The heap starts wherever the program break was put, mid-way through a 2 MiB range that can
    // never be a huge page. Park that stretch in a block that is never freed (nor touched beyond
    // malloc's header, so it costs no memory), so that later blocks start on the huge range.
    // The top chunk (the unused end of the heap) ends at the break, keepcost bytes long.
    const auto brk = reinterpret_cast<std::uintptr_t>(sbrk(0));
    const std::uintptr_t top = brk - mallinfo2().keepcost;
    const std::uintptr_t headroom = ((top + kHuge - 1) & ~(kHuge - 1)) - top;
    if (brk != std::uintptr_t(-1) && headroom > 4096) gParkedHeap = std::malloc(headroom - 64);
    void* block = std::malloc(kHugeHeapBytes);
    if (block == nullptr) return;
    const auto start = reinterpret_cast<std::uintptr_t>(block);
    const std::uintptr_t begin = (start + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t end = (start + kHugeHeapBytes) & ~(kHuge - 1);
    // Best effort: without THP support the advice fails and the heap simply uses normal pages.
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
    std::free(block);
}

}  // namespace rays::cli
