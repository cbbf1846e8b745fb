#include "thread_pool.hpp"

#include <cassert>

namespace rockfall::mpm::detail {
namespace {

// Spin iterations before sleeping: a few microseconds, enough to catch the next phase of a
// step on an idle machine.
constexpr int kSpins = 4000;

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

void ThreadPool::work() {
    for (int i = next_.fetch_add(1, std::memory_order_relaxed); i < count_;
         i = next_.fetch_add(1, std::memory_order_relaxed)) {
        (*task_)(i);
    }
}

void ThreadPool::worker_loop() {
    unsigned seen = 0;
    for (;;) {
        unsigned now = generation_.load(std::memory_order_acquire);
        for (int spin = 0; now == seen && spin < kSpins; ++spin) {
            relax();
            now = generation_.load(std::memory_order_acquire);
        }
        while (now == seen) {
            generation_.wait(seen, std::memory_order_acquire);
            now = generation_.load(std::memory_order_acquire);
        }
        seen = now;
        if (stop_.load(std::memory_order_relaxed)) {
            return;
        }
        work();
        if (remaining_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
            remaining_.notify_one();
        }
    }
}

void ThreadPool::run(int count, const std::function<void(int)>& task) {
    if (workers_.empty() || count <= 1) {
        for (int i = 0; i < count; ++i) {
            task(i);
        }
        return;
    }
    task_ = &task;
    count_ = count;
    next_.store(0, std::memory_order_relaxed);
    remaining_.store(static_cast<int>(workers_.size()), std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release);
    generation_.notify_all();
    work();
    int left = remaining_.load(std::memory_order_acquire);
    for (int spin = 0; left != 0 && spin < kSpins; ++spin) {
        relax();
        left = remaining_.load(std::memory_order_acquire);
    }
    while (left != 0) {
        remaining_.wait(left, std::memory_order_acquire);
        left = remaining_.load(std::memory_order_acquire);
    }
}

}  // namespace rockfall::mpm::detail
