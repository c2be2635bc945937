// The render loops' parallelFor on the process's worker pool: every index once, worker indices
// in range, repeated use, loops nested in a loop body and loops started from two threads at once
// (the pool is taken: those fall back to threads of their own).
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "rays/render/renderer.h"
#include "rays/util/worker_pool.h"

using namespace rays;

namespace { namespace RAYS_TEST_UNIT {

// Runs parallelFor(count, threads) and checks each index ran once on a worker in [0, threads).
void expectEachIndexOnce(int count, int threads, const ProgressFn& progress = {}) {
    std::vector<std::atomic<int>> hits(static_cast<size_t>(count));
    std::atomic<bool> badWorker{false};
    parallelFor(count, threads, [&](int i, int w) {
        hits[size_t(i)]++;
        if (w < 0 || w >= threads) badWorker = true;
    }, progress);
    for (int i = 0; i < count; ++i) ASSERT_EQ(hits[size_t(i)].load(), 1) << "index " << i;
    EXPECT_FALSE(badWorker.load());
}

TEST(WorkerPool, EveryIndexOnceOnValidWorkers) {
    for (int round = 0; round < 20; ++round) {
        expectEachIndexOnce(1000, 4);
        expectEachIndexOnce(7, 3);
        expectEachIndexOnce(1, 2);
    }
    double last = -1;
    expectEachIndexOnce(500, 3, [&](double f) { last = f; });
    EXPECT_EQ(last, 1.0);
}

TEST(WorkerPool, NestedLoopsFallBackToTheirOwnThreads) {
    std::atomic<int> total{0};
    parallelFor(8, 2, [&](int, int) {
        parallelFor(100, 2, [&](int, int) { total++; });
    });
    EXPECT_EQ(total.load(), 800);
}

TEST(WorkerPool, LoopsFromTwoThreadsAtOnce) {
    std::atomic<int> total{0};
    auto run = [&] {
        for (int k = 0; k < 50; ++k) parallelFor(64, 2, [&](int, int) { total++; });
    };
    std::thread a(run), b(run);
    a.join();
    b.join();
    EXPECT_EQ(total.load(), 2 * 50 * 64);
}

TEST(WorkerPool, JobIsExclusiveUntilWaitedFor) {
    std::atomic<int> ran{0};
    const std::function<void(int)> work = [&](int) { ran++; };
    PoolJob first;
    ASSERT_TRUE(first.begin(1, 2, work));
    PoolJob second;
    EXPECT_FALSE(second.begin(1, 2, work));  // taken
    first.wait();
    EXPECT_EQ(ran.load(), 2);
    EXPECT_TRUE(second.begin(1, 3, work));
    second.wait();
    EXPECT_EQ(ran.load(), 5);
}

}}  // namespace RAYS_TEST_UNIT, namespace
