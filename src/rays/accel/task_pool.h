// TaskPool: fork-join for the BVH builder. run(count, body) calls body(i) for every i in
// [0, count) on the calling thread and threads() − 1 workers of the process's worker pool
// (util/worker_pool.h; indices handed out dynamically) and returns when all calls have finished.
// With threads == 1 everything runs on the caller. Work decomposition never depends on the thread
// count, so results built with it can be made independent of the thread count too.
#pragma once

#include <cstddef>
#include <functional>

namespace rays::tribvh {

class TaskPool {
public:
    /// threads: total threads including the caller; 0 = all hardware threads.
    explicit TaskPool(int threads);

    int threads() const { return threads_; }
    void run(size_t count, const std::function<void(size_t)>& body);

private:
    int threads_;
};

}  // namespace rays::tribvh
