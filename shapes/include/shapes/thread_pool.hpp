#pragma once
// A small fork-join pool, here as the lowest library both the MPM solver and the engine's
// collision detection use (engine/src/pair_dispatcher.hpp). Written for the MPM solver's phases.
// Each thread owns a contiguous range of a phase's tasks and runs it first, then takes what is left
// of the other ranges. The solver gives a thread the same particles and grid blocks in every phase
// of a step, so their data stay in that core's cache instead of moving between cores at each phase;
// taking the others' leftovers keeps the threads finishing together. The calling thread takes part
// like the workers; it waits only for tasks a worker has claimed and not finished, never for a
// worker that has not woken up, so a busy or oversubscribed machine degrades towards the
// single-thread speed instead of stalling at barriers. Idle workers spin briefly, then sleep on an
// atomic wait (a futex). Tasks must be independent: which thread runs a task never changes a
// result.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

namespace rockfall::shapes {

class ThreadPool {
  public:
    // Most tasks in one run (21 bits of a range's ticket).
    static constexpr int kMaxTasks = (1 << 21) - 1;

    // `threads` >= 1 counts the calling thread.
    explicit ThreadPool(int threads);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int size() const { return static_cast<int>(workers_.size()) + 1; }

    // Runs task(i) for i in [0, split.back()); thread k owns [split[k], split[k + 1]) (the
    // calling thread is k = 0). `split` has size() + 1 non-decreasing entries from 0.
    void run(const std::vector<int>& split, const std::function<void(int)>& task);

    // As above with the tasks split evenly by count.
    void run(int count, const std::function<void(int)>& task);

    // Runs body(begin, end) over [0, n) in chunks of about `grain` items.
    template <typename Body>
    void parallel_for(int n, int grain, Body&& body) {
        const int chunks = (n + grain - 1) / grain;
        run(chunks, [&](int c) { body(c * grain, std::min(n, (c + 1) * grain)); });
    }

    // Splits [0, n) into size() ranges of about equal weight: `prefix` has n + 1 entries, the
    // running total of the tasks' weights (prefix[0] = 0). Writes size() + 1 entries to split.
    void split_by_weight(const std::vector<std::int32_t>& prefix, std::vector<int>& split) const;

  private:
    // One thread's range: generation (22 bits), next index and end (21 bits each) in one word,
    // so that a claim sees all three from the same run.
    struct alignas(64) Range {
        std::atomic<std::uint64_t> ticket{0};
    };

    // Claims and runs tasks of `generation`, its own range first, until none is left or a newer
    // run has started.
    void work(std::uint32_t generation, int self);
    void worker_loop(int self);

    std::vector<std::thread> workers_;
    std::unique_ptr<Range[]> ranges_;
    std::vector<int> even_split_;
    std::atomic<const std::function<void(int)>*> task_{nullptr};
    std::atomic<int> done_{0};
    std::atomic<std::uint32_t> generation_{0};
    // Workers asleep on generation_ (past their spinning): only then does run() pay for the
    // wake-up system call.
    std::atomic<int> sleepers_{0};
    std::atomic<bool> stop_{false};
};

}  // namespace rockfall::shapes
