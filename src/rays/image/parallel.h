// parallelFor: a tiny fork-join loop over independent work items (rows, bands of rows, tiles) on
// the process's worker pool (util/worker_pool.h). Generic: nothing in it is specific to images.
#pragma once
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <functional>
#include <thread>

#include "rays/util/worker_pool.h"

namespace rays {

/// Worker count for a requested number of threads: requested when positive, otherwise every
/// hardware thread (at least 1).
inline int parallelThreadCount(int requested) {
    if (requested > 0) return requested;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : int(hw);
}

/// Calls body(i) once for every i in [0, count), on up to `threads` threads (0 = all cores; the
/// calling thread is one of them). Indices are handed out in increasing order from a shared
/// counter, so uneven items balance themselves. Which thread runs an index is unspecified: for
/// results that do not depend on the thread count, body(i) must only write outputs owned by i.
/// If a body throws, the remaining indices are skipped and the first exception is rethrown here
/// once every thread has stopped.
template <class Body>
void parallelFor(int count, int threads, Body&& body) {
    if (count <= 0) return;
    const int workers = std::min(parallelThreadCount(threads), count);
    if (workers == 1) {
        for (int i = 0; i < count; ++i) body(i);
        return;
    }
    std::atomic<int> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr error;
    std::mutex errorMutex;
    auto work = [&] {
        for (;;) {
            const int i = next.fetch_add(1, std::memory_order_relaxed);
            if (i >= count || failed.load(std::memory_order_relaxed)) return;
            try {
                body(i);
            } catch (...) {
                std::lock_guard<std::mutex> lock(errorMutex);
                if (!error) error = std::current_exception();
                failed.store(true, std::memory_order_relaxed);
                return;
            }
        }
    };
    const std::function<void(int)> worker = [&](int) { work(); };
    runAlongside(1, workers - 1, worker, work);
    if (error) std::rethrow_exception(error);
}

}  // namespace rays
