// Worker threads kept for the whole process: starting a thread costs 0.2-1 ms on the virtual
// machines Rays runs on (stack mapping, first faults, scheduling), and a render with feature
// lines runs half a dozen parallel loops. Both parallelFor loops (render/renderer.h, image/parallel.h)
// and the BVH builder's TaskPool (accel/task_pool.h) run their workers here through runAlongside.
#pragma once
#include <functional>

namespace rays {

/// Runs work(first), ..., work(first + count - 1) on pool threads while the caller carries on,
/// then wait() returns once all have finished. One job at a time: begin() returns false (and
/// runs nothing) when another job holds the pool, e.g. a parallel loop nested in a loop body or
/// started from a second thread; the caller then starts threads of its own.
class PoolJob {
public:
    PoolJob() = default;
    PoolJob(const PoolJob&) = delete;
    PoolJob& operator=(const PoolJob&) = delete;
    ~PoolJob() { wait(); }

    /// work is used by reference: it must stay alive until wait() returns.
    bool begin(int first, int count, const std::function<void(int)>& work);
    void wait();

private:
    bool holding_ = false;
};

/// Runs work(first), ..., work(first + count - 1) on pool threads, or on threads of their own when
/// the pool is taken, while the calling thread runs alongside(); returns when all have finished.
void runAlongside(int first, int count, const std::function<void(int)>& work,
                  const std::function<void()>& alongside);

}  // namespace rays
