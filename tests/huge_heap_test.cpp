// The CLI's heap preparation (apps/rays/huge_pages.cpp): after it, a large malloc lands in memory
// advised for transparent huge pages (VmFlags "hg" in /proc/self/smaps).
#include "../apps/rays/huge_pages.cpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace {

bool thpAvailable() {
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string modes;
    std::getline(in, modes);
    return in && modes.find("[never]") == std::string::npos;
}

// The VmFlags line of the mapping that holds `address`, or "" when none does.
std::string vmFlagsAt(const void* address) {
    const auto a = reinterpret_cast<std::uintptr_t>(address);
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t lo = 0, hi = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
            inside = a >= lo && a < hi;
        } else if (inside && line.rfind("VmFlags:", 0) == 0) {
            return line;
        }
    }
    return "";
}

TEST(HugeHeap, LargeMallocsAfterTheHeapIsPreparedAreAdvisedForHugePages) {
    if (std::getenv("RAYS_NO_HUGEPAGES") != nullptr) GTEST_SKIP() << "RAYS_NO_HUGEPAGES is set";
    if (!thpAvailable()) GTEST_SKIP() << "no transparent huge pages on this machine";
    rays::cli::enableHugePages();
    void* block = std::malloc(size_t(16) << 20);
    ASSERT_NE(block, nullptr);
    // Somewhere in the middle of the block: the advice covers whole 2 MiB pages only.
    const void* probe = static_cast<char*>(block) + (size_t(8) << 20);
    const std::string flags = vmFlagsAt(probe);
    std::free(block);
    ASSERT_FALSE(flags.empty()) << "no mapping found for the block";
    EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
}

// The heap's first stretch below a 2 MiB boundary can never be a huge page; the preparation parks
// it in a block of its own, so that the next blocks (the scene file's text is the first big one)
// start inside the advised range. The compiler must not elide that never-read block.
TEST(HugeHeap, FirstBlockAfterTheHeapIsPreparedIsAdvisedFromItsStart) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "the sanitizers' allocators do not use the program break";
#else
    if (std::getenv("RAYS_NO_HUGEPAGES") != nullptr) GTEST_SKIP() << "RAYS_NO_HUGEPAGES is set";
    if (!thpAvailable()) GTEST_SKIP() << "no transparent huge pages on this machine";
    rays::cli::enableHugePages();
    // Larger than any free chunk a test binary leaves behind: it comes from the top of the heap.
    void* block = std::malloc(size_t(1) << 20);
    ASSERT_NE(block, nullptr);
    // Its chunk header sits just below the boundary; the rest of it lies above.
    const std::string flags = vmFlagsAt(static_cast<char*>(block) + 4096);
    std::free(block);
    ASSERT_FALSE(flags.empty()) << "no mapping found for the block";
    EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
#endif
}

}  // namespace
