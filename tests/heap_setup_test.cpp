// The CLI's malloc settings (apps/rays/heap_setup.cpp): after prepareHeap, large blocks come from
// the main heap (the "[heap]" mapping of /proc/self/maps), where freed memory is kept for reuse,
// and worker threads allocate from the arenas there are (malloc_info), without one of their own.
#include "../apps/rays/heap_setup.cpp"

#include <gtest/gtest.h>

#include <malloc.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace { namespace RAYS_TEST_UNIT {

// The name of the mapping that holds `address` ("[heap]", a path, or "" for an anonymous one),
// or "?" when no mapping does.
std::string mappingOf(const void* address) {
    const auto a = reinterpret_cast<std::uintptr_t>(address);
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line)) {
        std::uintptr_t lo = 0, hi = 0;
        char dash = 0;
        std::istringstream fields(line);
        if (!(fields >> std::hex >> lo >> dash >> hi) || dash != '-' || a < lo || a >= hi) continue;
        std::string perms, offset, device, inode, name;
        fields >> perms >> offset >> device >> inode >> name;
        return name;
    }
    return "?";
}

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SKIP_UNDER_SANITIZERS() GTEST_SKIP() << "the sanitizers' allocators do not use malloc's heap"
#else
#define SKIP_UNDER_SANITIZERS() (void)0
#endif

// glibc maps blocks of 32 MiB and more apart by default, each freed back to the kernel.
TEST(HeapSetup, LargeBlocksComeFromTheHeap) {
    SKIP_UNDER_SANITIZERS();
    rays::cli::prepareHeap();
    void* block = std::malloc(size_t(64) << 20);
    ASSERT_NE(block, nullptr);
    const std::string name = mappingOf(block);
    std::free(block);
    EXPECT_EQ(name, "[heap]");
}

// malloc's arenas, as malloc_info lists them (one <heap nr="..."> element each).
int arenaCount() {
    char* text = nullptr;
    size_t size = 0;
    FILE* out = open_memstream(&text, &size);
    if (!out) return -1;
    malloc_info(0, out);
    std::fclose(out);
    int count = 0;
    for (const char* p = text; (p = std::strstr(p, "<heap nr=")) != nullptr; ++p) ++count;
    std::free(text);
    return count;
}

// A new thread gets an arena of its own by default, mapped apart from the heap (also when this
// binary runs every test in one process: the arenas made before stay, no new one is made).
TEST(HeapSetup, WorkerThreadsGetNoArenaOfTheirOwn) {
    SKIP_UNDER_SANITIZERS();
    rays::cli::prepareHeap();
    const int before = arenaCount();
    ASSERT_GE(before, 1);
    std::thread([] {
        void* block = std::malloc(4096);
        std::free(block);
    }).join();
    EXPECT_EQ(arenaCount(), before);
}

}}  // namespace RAYS_TEST_UNIT, namespace
