// TaskPool: a small fork-join pool for the triangle BVH builder. run(count, body) calls body(i)
// for every i in [0, count) on the calling thread and the pool's workers (indices handed out
// dynamically) and returns when all calls have finished. With threads == 1 everything runs on
// the caller. Work decomposition never depends on the thread count, so results built with it
// can be made independent of the thread count too.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace rays::tribvh {

class TaskPool {
public:
    /// threads: total threads including the caller; 0 = all hardware threads.
    explicit TaskPool(int threads);
    ~TaskPool();
    TaskPool(const TaskPool&) = delete;
    TaskPool& operator=(const TaskPool&) = delete;

    int threads() const { return int(workers_.size()) + 1; }
    void run(size_t count, const std::function<void(size_t)>& body);

private:
    void workerLoop();
    void drain();

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_, finished_;
    const std::function<void(size_t)>* body_ = nullptr;
    size_t count_ = 0;
    std::atomic<size_t> next_{0};
    uint64_t generation_ = 0;
    size_t pending_ = 0;  ///< workers that have not finished the current generation
    bool stop_ = false;
};

}  // namespace rays::tribvh
