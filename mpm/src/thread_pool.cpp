#include "thread_pool.hpp"

#include <cassert>

namespace rockfall::mpm::detail {
namespace {

// Spin iterations before sleeping (tens of microseconds): enough to catch the next phase of a
// step on an idle machine, short enough not to steal much time on a busy one.
constexpr int kSpins = 1000;

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

}  // namespace

ThreadPool::ThreadPool(int threads) {
    assert(threads >= 1);
    for (int i = 1; i < threads; ++i) {
        workers_.emplace_back([this] { worker_loop(); });
    }
}

ThreadPool::~ThreadPool() {
    stop_.store(true, std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release);
    generation_.notify_all();
    for (std::thread& t : workers_) {
        t.join();
    }
}

void ThreadPool::work(std::uint32_t generation) {
    for (;;) {
        std::uint64_t ticket = ticket_.load(std::memory_order_acquire);
        if (static_cast<std::uint32_t>(ticket >> 32) != generation) {
            return;
        }
        const auto index = static_cast<int>(ticket & 0xffffffffu);
        const std::function<void(int)>* task = task_.load(std::memory_order_acquire);
        if (index >= count_.load(std::memory_order_acquire)) {
            return;
        }
        // The claim fails if another thread took this index or a newer run started; then the
        // task and count read above may be stale and are not used.
        if (!ticket_.compare_exchange_weak(ticket, ticket + 1, std::memory_order_acq_rel)) {
            continue;
        }
        (*task)(index);
        done_.fetch_add(1, std::memory_order_release);
    }
}

void ThreadPool::worker_loop() {
    std::uint32_t seen = 0;
    for (;;) {
        std::uint32_t now = generation_.load(std::memory_order_acquire);
        for (int spin = 0; now == seen && spin < kSpins; ++spin) {
            relax();
            now = generation_.load(std::memory_order_acquire);
        }
        if (now == seen) {
            sleepers_.fetch_add(1, std::memory_order_seq_cst);
            // Re-read after announcing the sleep: a run() that started before the announcement
            // may have skipped the notification.
            now = generation_.load(std::memory_order_seq_cst);
            while (now == seen) {
                generation_.wait(seen, std::memory_order_acquire);
                now = generation_.load(std::memory_order_acquire);
            }
            sleepers_.fetch_sub(1, std::memory_order_relaxed);
        }
        seen = now;
        if (stop_.load(std::memory_order_relaxed)) {
            return;
        }
        work(now);
    }
}

void ThreadPool::run(int count, const std::function<void(int)>& task) {
    if (workers_.empty() || count <= 1) {
        for (int i = 0; i < count; ++i) {
            task(i);
        }
        return;
    }
    const std::uint32_t generation = generation_.load(std::memory_order_relaxed) + 1;
    task_.store(&task, std::memory_order_relaxed);
    count_.store(count, std::memory_order_relaxed);
    done_.store(0, std::memory_order_relaxed);
    ticket_.store(static_cast<std::uint64_t>(generation) << 32, std::memory_order_release);
    generation_.store(generation, std::memory_order_seq_cst);
    if (sleepers_.load(std::memory_order_seq_cst) > 0) {
        generation_.notify_all();
    }
    work(generation);
    // Every index is claimed; wait for the claimed tasks still running on workers.
    for (int spin = 0; done_.load(std::memory_order_acquire) < count; ++spin) {
        if (spin < kSpins) {
            relax();
        } else {
            // The worker holding a task may be descheduled: let it run.
            std::this_thread::yield();
        }
    }
}

}  // namespace rockfall::mpm::detail
