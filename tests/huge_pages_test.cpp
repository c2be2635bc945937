// The warm memory region (accel/huge_pages.h): requests of at least kWarmMin bytes are carved from
// it while it lasts, smaller or larger ones are not, carved blocks stay valid and separate, and
// allocation from several threads while the region is being populated is safe. Each test runs in
// its own process (ctest), so hugePrewarm's once-per-process rule holds per test.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <thread>
#include <vector>

#include "rays/accel/huge_pages.h"

using namespace rays::tribvh;

TEST(HugePages, WarmRegionServesLargeRequestsOnly) {
#if defined(__linux__)
    const size_t region = size_t(8) << 20;
    ASSERT_TRUE(hugePrewarm(region));
    EXPECT_FALSE(hugePrewarm(region));  // once per process
    EXPECT_EQ(hugeWarmUsed(), 0u);

    void* small = hugeAlloc(1024, 16);
    EXPECT_EQ(hugeWarmUsed(), 0u);
    const size_t a = size_t(3) << 20, b = kWarmMin;
    auto* pa = static_cast<uint8_t*>(hugeAlloc(a, 64));
    EXPECT_GE(hugeWarmUsed(), a);
    auto* pb = static_cast<uint8_t*>(hugeAlloc(b, 64));
    EXPECT_GE(hugeWarmUsed(), a + b);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(pa) % 64, 0u);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(pb) % 64, 0u);
    // Separate blocks: writing one leaves the other alone.
    std::memset(pa, 0xAB, a);
    std::memset(pb, 0xCD, b);
    EXPECT_EQ(pa[a - 1], 0xAB);
    EXPECT_EQ(pb[0], 0xCD);
    // Too big for what is left: ordinary memory, the region untouched.
    const size_t before = hugeWarmUsed();
    auto* pc = static_cast<uint8_t*>(hugeAlloc(region, 64));
    EXPECT_EQ(hugeWarmUsed(), before);
    pc[region - 1] = 1;
    hugeFree(pc, region, 64);
    hugeFree(pb, b, 64);  // carved: kept, no harm
    hugeFree(pa, a, 64);
    hugeFree(small, 1024, 16);
#else
    GTEST_SKIP() << "warm memory needs Linux";
#endif
}

TEST(HugePages, AllocationFromSeveralThreadsWhilePopulating) {
#if defined(__linux__)
    ASSERT_TRUE(hugePrewarm(size_t(32) << 20));
    std::vector<std::thread> threads;
    std::vector<uint8_t*> blocks(8);
    for (int t = 0; t < 8; ++t)
        threads.emplace_back([t, &blocks] {
            auto* p = static_cast<uint8_t*>(hugeAlloc(size_t(3) << 20, 64));
            std::memset(p, t + 1, size_t(3) << 20);
            blocks[size_t(t)] = p;
        });
    for (std::thread& th : threads) th.join();
    for (int t = 0; t < 8; ++t) {
        EXPECT_EQ(blocks[size_t(t)][0], t + 1);
        EXPECT_EQ(blocks[size_t(t)][(size_t(3) << 20) - 1], t + 1);
        hugeFree(blocks[size_t(t)], size_t(3) << 20, 64);
    }
    EXPECT_GE(hugeWarmUsed(), size_t(24) << 20);  // all eight came from the region
#else
    GTEST_SKIP() << "warm memory needs Linux";
#endif
}

// A region sized for planned buffers (the render image) keeps them room: smaller requests that
// come first (a BVH's arrays) get only the rest, and the planned buffer is still carved from it.
TEST(HugePages, PlannedBuffersKeepTheirRoom) {
#if defined(__linux__)
    const size_t planned = (size_t(7) << 20) + (size_t(1) << 19);  // 7.5 MiB: the region is 8 MiB
    ASSERT_TRUE(hugePrewarm(planned, planned));
    void* a = hugeAlloc(size_t(256) << 10, 64);  // fits in the 0.5 MiB the plan leaves
    EXPECT_EQ(hugeWarmUsed(), size_t(256) << 10);
    void* b = hugeAlloc(size_t(384) << 10, 64);  // would eat into the plan: fresh memory
    EXPECT_EQ(hugeWarmUsed(), size_t(256) << 10);
    auto* image = static_cast<uint8_t*>(hugeAlloc(planned, 64));
    EXPECT_EQ(hugeWarmUsed(), (size_t(256) << 10) + planned);
    image[planned - 1] = 1;
    // The plan is served: later requests take whatever is left.
    hugeFree(image, planned, 64);
    hugeFree(b, size_t(384) << 10, 64);
    hugeFree(a, size_t(256) << 10, 64);
#else
    GTEST_SKIP() << "warm memory needs Linux";
#endif
}
