// Independent jobs on worker threads (risk/parallel.hpp).

#include "risk/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rockfall::risk {

void run_parallel(std::int64_t count, int threads, const std::function<void(std::int64_t)>& job,
                  std::int64_t done_before, std::int64_t total, const ParallelProgress& progress) {
    if (count <= 0) return;
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

}  // namespace rockfall::risk
