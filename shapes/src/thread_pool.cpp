#include "shapes/thread_pool.hpp"

#include <cassert>

namespace rockfall::shapes {
namespace {

// Spin iterations before sleeping (tens of microseconds): enough to catch the next phase of a
// step on an idle machine, short enough not to steal much time on a busy one.
constexpr int kSpins = 1000;

constexpr int kIndexBits = 21;
constexpr std::uint64_t kIndexMask = (std::uint64_t{1} << kIndexBits) - 1;
constexpr std::uint32_t kGenerationMask = (std::uint32_t{1} << 22) - 1;

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

// Ticket layout: generation << 42 | end << 21 | next index.
constexpr std::uint64_t make_ticket(std::uint32_t generation, int next, int end) {
    return (static_cast<std::uint64_t>(generation & kGenerationMask) << (2 * kIndexBits)) |
           (static_cast<std::uint64_t>(end) << kIndexBits) | static_cast<std::uint64_t>(next);
}
constexpr std::uint32_t generation_of(std::uint64_t ticket) {
    return static_cast<std::uint32_t>(ticket >> (2 * kIndexBits));
}
constexpr int next_of(std::uint64_t ticket) { return static_cast<int>(ticket & kIndexMask); }
constexpr int end_of(std::uint64_t ticket) {
    return static_cast<int>((ticket >> kIndexBits) & kIndexMask);
}

}  // namespace

ThreadPool::ThreadPool(int threads) : ranges_(std::make_unique<Range[]>(threads)) {
    assert(threads >= 1);
    for (int i = 1; i < threads; ++i) {
        workers_.emplace_back([this, i] { worker_loop(i); });
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

void ThreadPool::work(std::uint32_t generation, int self) {
    const int n = size();
    generation &= kGenerationMask;
    for (int r = 0; r < n; ++r) {
        Range& range = ranges_[static_cast<std::size_t>((self + r) % n)];
        for (;;) {
            std::uint64_t ticket = range.ticket.load(std::memory_order_acquire);
            if (generation_of(ticket) != generation) {
                return;  // a newer run has started
            }
            if (next_of(ticket) >= end_of(ticket)) {
                break;  // this range is taken: help the next one
            }
            const std::function<void(int)>* task = task_.load(std::memory_order_acquire);
            // The claim fails if another thread took this index or a newer run started; then
            // the task read above may be stale and is not used.
            if (!range.ticket.compare_exchange_weak(ticket, ticket + 1,
                                                    std::memory_order_acq_rel)) {
                continue;
            }
            (*task)(next_of(ticket));
            done_.fetch_add(1, std::memory_order_release);
        }
    }
}

void ThreadPool::worker_loop(int self) {
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
        work(now, self);
    }
}

void ThreadPool::run(const std::vector<int>& split, const std::function<void(int)>& task) {
    const int n = size();
    assert(static_cast<int>(split.size()) == n + 1 && split.front() == 0);
    const int count = split.back();
    assert(count <= kMaxTasks);
    if (workers_.empty() || count <= 1) {
        for (int i = 0; i < count; ++i) {
            task(i);
        }
        return;
    }
    // The previous run is over (every task done), so no thread can claim from these ranges
    // until the new generation is published below.
    const std::uint32_t generation = generation_.load(std::memory_order_relaxed) + 1;
    task_.store(&task, std::memory_order_relaxed);
    done_.store(0, std::memory_order_relaxed);
    for (int k = 0; k < n; ++k) {
        assert(split[static_cast<std::size_t>(k)] <= split[static_cast<std::size_t>(k) + 1]);
        ranges_[static_cast<std::size_t>(k)].ticket.store(
            make_ticket(generation, split[static_cast<std::size_t>(k)],
                        split[static_cast<std::size_t>(k) + 1]),
            std::memory_order_release);
    }
    generation_.store(generation, std::memory_order_seq_cst);
    if (sleepers_.load(std::memory_order_seq_cst) > 0) {
        generation_.notify_all();
    }
    work(generation, 0);
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

void ThreadPool::run(int count, const std::function<void(int)>& task) {
    const int n = size();
    even_split_.resize(static_cast<std::size_t>(n) + 1);
    for (int k = 0; k <= n; ++k) {
        even_split_[static_cast<std::size_t>(k)] =
            static_cast<int>(static_cast<long>(count) * k / n);
    }
    run(even_split_, task);
}

void ThreadPool::split_by_weight(const std::vector<std::int32_t>& prefix,
                                 std::vector<int>& split) const {
    const int n = size();
    const int count = static_cast<int>(prefix.size()) - 1;
    const long total = prefix.back();
    split.assign(static_cast<std::size_t>(n) + 1, count);
    split[0] = 0;
    int i = 0;
    for (int k = 1; k < n; ++k) {
        const long target = total * k / n;
        while (i < count && prefix[static_cast<std::size_t>(i)] < target) {
            ++i;
        }
        split[static_cast<std::size_t>(k)] = i;
    }
}

}  // namespace rockfall::shapes
