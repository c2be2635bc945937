#include "rays/accel/task_pool.h"

#include <algorithm>
#include <atomic>
#include <thread>

#include "rays/util/worker_pool.h"

namespace rays::tribvh {

TaskPool::TaskPool(int threads)
    : threads_(threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()))) {}

void TaskPool::run(size_t count, const std::function<void(size_t)>& body) {
    if (threads_ == 1 || count <= 1) {
        for (size_t i = 0; i < count; ++i) body(i);
        return;
    }
    std::atomic<size_t> next{0};
    const std::function<void(int)> drain = [&](int) {
        for (size_t i = next.fetch_add(1, std::memory_order_relaxed); i < count;
             i = next.fetch_add(1, std::memory_order_relaxed))
            body(i);
    };
    runAlongside(1, threads_ - 1, drain, [&] { drain(0); });
}

}  // namespace rays::tribvh
