#pragma once
// Independent jobs of a virtual experiment (drops, heaps) on worker threads. Private to risk.

#include "risk/parameter_search.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rockfall::risk::detail {

// Runs job(i) for i in [0, count) on `threads` workers; the calling thread reports progress
// (done_before + jobs done, of total). Each result lands at its own index, so the output does
// not depend on the threads. The first exception stops the remaining jobs and is rethrown.
template <class Job>
void run_parallel(std::int64_t count, int threads, const Job& job, std::int64_t done_before,
                  std::int64_t total, const BatchProgress& progress) {
    std::atomic<std::int64_t> next{0};
    std::atomic<std::int64_t> done{0};
    std::mutex mutex;
    std::condition_variable finished;
    std::exception_ptr error;
    int running = 0;
    const auto work = [&] {
        for (std::int64_t i = next++; i < count; i = next++) {
            try {
                job(i);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(mutex);
                if (!error) error = std::current_exception();
                next = count;
            }
            ++done;
        }
        const std::lock_guard<std::mutex> lock(mutex);
        --running;
        finished.notify_all();
    };
    const int workers = static_cast<int>(std::min<std::int64_t>(std::max(threads, 1), count));
    std::vector<std::thread> pool;
    running = workers;
    for (int t = 0; t < workers; ++t) pool.emplace_back(work);
    {
        std::unique_lock<std::mutex> lock(mutex);
        while (running > 0) {
            finished.wait_for(lock, std::chrono::milliseconds(200));
            if (progress) {
                lock.unlock();
                progress(done_before + done, total);
                lock.lock();
            }
        }
    }
    for (std::thread& t : pool) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace rockfall::risk::detail
