// The solver's fork-join pool: every task runs exactly once per run, whatever the split, and
// back-to-back runs never mix their tasks (a stale claim from an earlier run would show up as a
// task run twice, or a task missed).
#include "shapes/thread_pool.hpp"

#include <catch2/catch.hpp>

#include <atomic>
#include <vector>

using rockfall::shapes::ThreadPool;

TEST_CASE("Thread pool runs every task once, whatever the split", "[mpm][pool]") {
    for (const int threads : {1, 2, 3}) {
        ThreadPool pool(threads);
        std::vector<std::atomic<int>> hits(1000);
        std::vector<int> split(static_cast<std::size_t>(threads) + 1, 0);
        for (int run = 0; run < 2000; ++run) {
            const int count = run % 997;
            // Uneven and empty ranges, the last owning the rest.
            for (int k = 1; k < threads; ++k) {
                split[static_cast<std::size_t>(k)] = (run * 7 * k) % (count + 1);
                if (split[static_cast<std::size_t>(k)] < split[static_cast<std::size_t>(k) - 1]) {
                    split[static_cast<std::size_t>(k)] = split[static_cast<std::size_t>(k) - 1];
                }
            }
            split.back() = count;
            for (auto& h : hits) {
                h.store(0);
            }
            pool.run(split, [&](int i) { hits[static_cast<std::size_t>(i)].fetch_add(1); });
            for (int i = 0; i < 1000; ++i) {
                REQUIRE(hits[static_cast<std::size_t>(i)].load() == (i < count ? 1 : 0));
            }
        }
    }
}

TEST_CASE("Thread pool splits where the running weight reaches each thread's share",
          "[mpm][pool]") {
    ThreadPool pool(2);
    // Weights 1, 1, 1, 1, 10, 1, 1, 1 as a running total.
    const std::vector<std::int32_t> prefix{0, 1, 2, 3, 4, 14, 15, 16, 17};
    std::vector<int> split;
    pool.split_by_weight(prefix, split);
    REQUIRE(split == std::vector<int>{0, 5, 8});
    std::vector<int> even;
    ThreadPool one(1);
    one.split_by_weight(prefix, even);
    REQUIRE(even == std::vector<int>{0, 8});
}
