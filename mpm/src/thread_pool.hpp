#pragma once
// A small fork-join pool for the solver's phases. Workers spin briefly, then sleep on an
// atomic wait (a futex), so a busy or oversubscribed machine does not stall the step the way
// long barrier spins do. Tasks must be independent: which thread runs a task never changes a
// result.

#include <atomic>
#include <functional>
#include <thread>
#include <vector>

namespace rockfall::mpm::detail {

class ThreadPool {
  public:
    // `threads` >= 1 counts the calling thread.
    explicit ThreadPool(int threads);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int size() const { return static_cast<int>(workers_.size()) + 1; }

    // Runs task(i) for i in [0, count) on all threads; returns when every task is done.
    void run(int count, const std::function<void(int)>& task);

    // Runs body(begin, end) over [0, n) in chunks of about `grain` items.
    template <typename Body>
    void parallel_for(int n, int grain, Body&& body) {
        const int chunks = (n + grain - 1) / grain;
        run(chunks, [&](int c) { body(c * grain, std::min(n, (c + 1) * grain)); });
    }

  private:
    void work();
    void worker_loop();

    std::vector<std::thread> workers_;
    const std::function<void(int)>* task_ = nullptr;
    int count_ = 0;
    std::atomic<int> next_{0};
    std::atomic<int> remaining_{0};
    std::atomic<unsigned> generation_{0};
    std::atomic<bool> stop_{false};
};

}  // namespace rockfall::mpm::detail
