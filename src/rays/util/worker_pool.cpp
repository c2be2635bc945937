#include "rays/util/worker_pool.h"

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace rays {
namespace {

// Threads wait for a new generation; thread i takes part when i < count and runs work(first + i).
class WorkerPool {
public:
    std::mutex owner;  // held by the caller whose job is running

    void start(int first, int count, const std::function<void(int)>& work) {
        std::unique_lock<std::mutex> lock(m_);
        while (int(threads_.size()) < count) {
            const int index = int(threads_.size());
            threads_.emplace_back([this, index] { loop(index); });
        }
        work_ = &work;
        first_ = first;
        count_ = count;
        running_ = count;
        ++generation_;
        lock.unlock();
        wake_.notify_all();
    }

    void wait() {
        std::unique_lock<std::mutex> lock(m_);
        finished_.wait(lock, [this] { return running_ == 0; });
        work_ = nullptr;
    }

private:
    void loop(int index) {
        uint64_t seen = 0;
        std::unique_lock<std::mutex> lock(m_);
        for (;;) {
            wake_.wait(lock, [&] { return generation_ != seen; });
            seen = generation_;
            if (index >= count_) continue;
            const std::function<void(int)>* work = work_;
            const int w = first_ + index;
            lock.unlock();
            (*work)(w);
            lock.lock();
            if (--running_ == 0) finished_.notify_all();
        }
    }

    std::mutex m_;
    std::condition_variable wake_, finished_;
    std::vector<std::thread> threads_;  // never joined: they live as long as the process
    uint64_t generation_ = 0;
    const std::function<void(int)>* work_ = nullptr;
    int first_ = 0, count_ = 0, running_ = 0;
};

WorkerPool& pool() {
    static WorkerPool* p = new WorkerPool;  // intentionally never destroyed (its threads never end)
    return *p;
}

}  // namespace

bool PoolJob::begin(int first, int count, const std::function<void(int)>& work) {
    if (holding_ || count <= 0) return false;
    if (!pool().owner.try_lock()) return false;
    holding_ = true;
    try {
        pool().start(first, count, work);
    } catch (...) {
        // No new thread could be started: run nothing here, let the caller fall back.
        holding_ = false;
        pool().owner.unlock();
        return false;
    }
    return true;
}

void PoolJob::wait() {
    if (!holding_) return;
    pool().wait();
    holding_ = false;
    pool().owner.unlock();
}

void runAlongside(int first, int count, const std::function<void(int)>& work,
                  const std::function<void()>& alongside) {
    PoolJob job;
    std::vector<std::thread> own;
    struct JoinOwn {  // also when alongside() throws: a joinable std::thread must not be destroyed
        std::vector<std::thread>& threads;
        ~JoinOwn() {
            for (std::thread& t : threads) t.join();
        }
    } joinOwn{own};
    if (count > 0 && !job.begin(first, count, work))
        for (int w = first; w < first + count; ++w) own.emplace_back(work, w);
    alongside();
    job.wait();
}

}  // namespace rays
