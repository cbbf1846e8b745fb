#pragma once
// A small fork-join pool for the solver's phases. The calling thread takes part and claims
// tasks like the workers; it waits only for tasks a worker has claimed and not finished, never
// for a worker that has not woken up, so a busy or oversubscribed machine degrades towards the
// single-thread speed instead of stalling at barriers. Idle workers spin briefly, then sleep on
// an atomic wait (a futex). Tasks must be independent: which thread runs a task never changes
// a result.

#include <algorithm>
#include <atomic>
#include <cstdint>
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
    // Claims and runs tasks of `generation` until none is left or a newer run has started.
    void work(std::uint32_t generation);
    void worker_loop();

    std::vector<std::thread> workers_;
    std::atomic<const std::function<void(int)>*> task_{nullptr};
    std::atomic<int> count_{0};
    // Generation in the high 32 bits, next task index in the low 32 bits: a claim succeeds
    // only for the generation its thread was woken for.
    std::atomic<std::uint64_t> ticket_{0};
    std::atomic<int> done_{0};
    std::atomic<std::uint32_t> generation_{0};
    // Workers asleep on generation_ (past their spinning): only then does run() pay for the
    // wake-up system call.
    std::atomic<int> sleepers_{0};
    std::atomic<bool> stop_{false};
};

}  // namespace rockfall::mpm::detail
