#include "rays/accel/huge_pages.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <thread>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rays::tribvh {
namespace {

#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
constexpr bool kCanPrewarm = true;
#else
constexpr bool kCanPrewarm = false;
#endif

// The warm region: [base, base + size), handed out from `used` upwards, populated by a detached
// thread in kHugePage steps. It lives as long as the process (never destroyed: blocks carved
// from it may be freed by static destructors), and so does the mapping.
struct WarmRegion {
    std::mutex lock;
    std::atomic<char*> base{nullptr};  ///< set once, after size
    size_t size = 0;
    size_t used = 0;
    bool claimed = false;
    size_t plannedMin = 0;   ///< requests of at least this size are the ones the region was sized for
    size_t plannedLeft = 0;  ///< bytes kept for them until they come

    bool contains(const void* p) const {
        const char* b = base.load(std::memory_order_acquire);
        const char* c = static_cast<const char*>(p);
        return b && c >= b && c < b + size;
    }

    // A carve of `bytes` aligned to `align` (a power of two), or nullptr when it does not fit.
    void* carve(size_t bytes, size_t align) {
        if (!base.load(std::memory_order_acquire)) return nullptr;
        std::lock_guard<std::mutex> g(lock);
        const size_t a = align < 64 ? 64 : align;
        const size_t start = (used + a - 1) & ~(a - 1);
        const bool planned = bytes >= plannedMin;
        // Other requests take only what the planned buffers leave.
        const size_t room = planned ? size : size - plannedLeft;  // plannedLeft <= size always
        if (start > room || room - start < bytes) return nullptr;
        used = start + bytes;
        if (planned) plannedLeft -= std::min(bytes, plannedLeft);
        return base.load(std::memory_order_relaxed) + start;
    }
};

WarmRegion& warm() {
    static WarmRegion* region = new WarmRegion;  // intentionally never destroyed
    return *region;
}

void populate(char* base, size_t size) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    for (size_t off = 0; off < size; off += kHugePage) {
        const size_t n = size - off < kHugePage ? size - off : kHugePage;
        // Page tables made present and writable without changing the contents: safe while a
        // user already writes to the block. Fails harmlessly on kernels before 5.14.
        if (madvise(base + off, n, MADV_POPULATE_WRITE) != 0) return;
    }
#else
    (void)base;
    (void)size;
#endif
}

}  // namespace

size_t hugeFootprint(size_t bytes) {
    return bytes >= kHugeThreshold ? (bytes + kHugePage - 1) / kHugePage * kHugePage : bytes;
}

bool hugePrewarm(size_t bytes, size_t plannedMin) {
    if (!kCanPrewarm || bytes == 0) return false;
    WarmRegion& w = warm();
    std::lock_guard<std::mutex> g(w.lock);
    if (w.claimed) return false;
    w.claimed = true;
#if defined(__linux__)
    const size_t size = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    // Over-allocate by one huge page to align the region to 2 MiB.
    void* raw = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) return false;
    char* base = reinterpret_cast<char*>((reinterpret_cast<uintptr_t>(raw) + kHugePage - 1) & ~(kHugePage - 1));
#if defined(MADV_HUGEPAGE)
    madvise(base, size, MADV_HUGEPAGE);
#endif
    w.size = size;
    w.plannedMin = plannedMin;
    w.plannedLeft = plannedMin > 0 ? bytes : 0;
    w.base.store(base, std::memory_order_release);
    try {
        std::thread(populate, base, size).detach();
    } catch (...) {
        // No thread: the region still serves requests, faulted by its users.
    }
    return true;
#else
    return false;
#endif
}

size_t hugeWarmUsed() {
    WarmRegion& w = warm();
    std::lock_guard<std::mutex> g(w.lock);
    return w.used;
}

void* hugeAlloc(size_t bytes, size_t align) {
    if (bytes == 0) bytes = 1;
    if (bytes >= kWarmMin && kCanPrewarm)
        if (void* p = warm().carve(bytes, align)) return p;
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
    if (kCanPrewarm && warm().contains(p)) return;  // carved: the region is kept whole
    if (bytes == 0) bytes = 1;
    if (bytes >= kHugeThreshold) {
        std::free(p);
        return;
    }
    ::operator delete(p, std::align_val_t(align));
}

}  // namespace rays::tribvh
