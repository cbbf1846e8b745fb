#include "risk/statistics.hpp"
#include "risk/sweep_runner.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>

using namespace rockfall;

namespace {

// The seed slope with a short run-out time limit: a handful of samples run in about a second.
engine::Scenario quick_base() {
    engine::Scenario base;
    base.numerics.max_time = 6.0;
    return base;
}

risk::SweepSpec varied_spec() {
    risk::SweepSpec spec = risk::sweep_defaults(quick_base());
    spec.seed = 42;
    spec.samples = 12;
    spec.kinds = {shapes::RockKind::sphere, shapes::RockKind::massive, shapes::RockKind::planar};
    spec.kind_weights = {1.0, 1.0, 1.0};
    spec.size.family = risk::Distribution::Family::uniform;
    spec.size.min = 0.2;
    spec.size.max = 0.4;
    spec.random_orientation = true;
    return spec;
}

// Runs every sample on `threads` threads and returns the outcomes by index.
std::map<std::int64_t, risk::SampleResult> run_all(const risk::SweepSpec& spec,
                                                   const engine::Scenario& base, int threads,
                                                   std::vector<std::int64_t> order) {
    risk::RunnerOptions options;
    options.threads = threads;
    risk::SweepRunner runner(spec, base, std::move(order), options);
    std::map<std::int64_t, risk::SampleResult> results;
    while (!runner.finished()) {
        for (auto& result : runner.collect(std::chrono::milliseconds(100))) {
            const std::int64_t index = result.inputs.index;
            REQUIRE(results.emplace(index, std::move(result)).second);
        }
    }
    return results;
}

}  // namespace

TEST_CASE("sweep results do not depend on the thread count or the order samples are taken",
          "[risk][sweep]") {
    const engine::Scenario base = quick_base();
    const risk::SweepSpec spec = varied_spec();
    std::vector<std::int64_t> order(static_cast<std::size_t>(spec.samples));
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::int64_t>(i);
    const auto one = run_all(spec, base, 1, order);
    std::reverse(order.begin(), order.end());
    const auto three = run_all(spec, base, 3, order);
    REQUIRE(one.size() == order.size());
    REQUIRE(three.size() == order.size());
    for (const auto& [index, a] : one) {
        const risk::SampleResult& b = three.at(index);
        CHECK(a.inputs.seed == b.inputs.seed);
        CHECK(a.inputs.size == b.inputs.size);
        // Bitwise equal outcomes: the same sample gives the same trajectory on any thread.
        CHECK(a.rocks.at(0).outcome.reach == b.rocks.at(0).outcome.reach);
        CHECK(a.rocks.at(0).outcome.stop_time == b.rocks.at(0).outcome.stop_time);
        CHECK(a.rocks.at(0).outcome.final_state.position ==
              b.rocks.at(0).outcome.final_state.position);
        CHECK(a.rocks.at(0).outcome.wall_hits.size() == b.rocks.at(0).outcome.wall_hits.size());
    }
    // A sample run alone equals the same sample in the sweep.
    const risk::SampleResult alone = risk::run_sample(spec, base, 5);
    CHECK(alone.rocks.at(0).outcome.reach == one.at(5).rocks.at(0).outcome.reach);
}

TEST_CASE("a runner fed chunks until closed runs each index once, as a fixed list does",
          "[risk][sweep]") {
    const engine::Scenario base = quick_base();
    const risk::SweepSpec spec = varied_spec();
    std::vector<std::int64_t> order(static_cast<std::size_t>(spec.samples));
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::int64_t>(i);
    const auto fixed = run_all(spec, base, 2, order);

    risk::RunnerOptions options;
    options.threads = 2;
    risk::SweepRunner runner(spec, base, options);
    CHECK(runner.waiting() == 0);
    // With nothing added the workers wait rather than end.
    CHECK(runner.collect(std::chrono::milliseconds(20)).empty());
    CHECK_FALSE(runner.finished());
    runner.add({0, 1, 2, 3, 4});
    std::map<std::int64_t, risk::SampleResult> fed;
    const auto take = [&] {
        for (auto& result : runner.collect(std::chrono::milliseconds(100))) {
            const std::int64_t index = result.inputs.index;
            REQUIRE(fed.emplace(index, std::move(result)).second);
        }
    };
    while (fed.size() < 5) take();
    runner.add({11, 10, 9, 8, 7, 6, 5});
    runner.close();
    while (!runner.finished()) take();
    REQUIRE(fed.size() == fixed.size());
    for (const auto& [index, a] : fixed) {
        const risk::SampleResult& b = fed.at(index);
        CHECK(a.rocks.at(0).outcome.reach == b.rocks.at(0).outcome.reach);
        CHECK(a.rocks.at(0).outcome.final_state.position ==
              b.rocks.at(0).outcome.final_state.position);
    }
}

TEST_CASE("a stopped runner that waits for chunks ends", "[risk][sweep]") {
    const engine::Scenario base = quick_base();
    risk::RunnerOptions options;
    options.threads = 3;
    risk::SweepRunner runner(varied_spec(), base, options);
    runner.stop();
    while (!runner.finished()) CHECK(runner.collect(std::chrono::milliseconds(100)).empty());
}

TEST_CASE("a worker's exception reaches the caller", "[risk][sweep]") {
    const engine::Scenario base = quick_base();
    risk::SweepSpec spec = varied_spec();
    spec.method = risk::SweepSpec::Method::latin_hypercube;
    // Latin hypercube samples exist only below spec.samples: index 12 is out of range.
    risk::RunnerOptions options;
    options.threads = 2;
    risk::SweepRunner runner(spec, base, {12}, options);
    CHECK_THROWS(runner.collect(std::chrono::milliseconds(5000)));
}

TEST_CASE("the --until rule stops at the first checkpoint of the completed prefix",
          "[risk][sweep]") {
    risk::UntilRule rule;
    rule.half_width = 0.1;
    rule.check_every = 10;
    risk::UntilMonitor monitor(rule);
    // Samples finish out of order: nothing is decided before the prefix is complete.
    for (std::int64_t i = 10; i < 40; ++i) monitor.add(i, i % 4 == 0);
    CHECK(monitor.prefix() == 0);
    CHECK_FALSE(monitor.stop_at());
    for (std::int64_t i = 0; i < 10; ++i) monitor.add(i, i % 4 == 0);
    CHECK(monitor.prefix() == 40);
    // Wilson 95 % half-widths at k = 10, 20, 30, 40 with about a quarter successes: 0.24,
    // 0.18, 0.15, 0.13; none reaches 0.1, so no stop yet.
    CHECK_FALSE(monitor.stop_at());
    std::int64_t k = 40;
    while (!monitor.stop_at()) monitor.add(k, k % 4 == 0), ++k;
    const std::int64_t stop = *monitor.stop_at();
    CHECK(stop % 10 == 0);
    // The stopping point is where the interval first gets narrow enough: check by hand.
    std::int64_t successes = 0;
    for (std::int64_t i = 0; i < stop; ++i) successes += i % 4 == 0 ? 1 : 0;
    const risk::Interval at_stop = risk::wilson_interval(successes, stop, 0.95);
    CHECK(0.5 * (at_stop.upper - at_stop.lower) <= 0.1);
    const std::int64_t before = stop - 10;
    std::int64_t successes_before = 0;
    for (std::int64_t i = 0; i < before; ++i) successes_before += i % 4 == 0 ? 1 : 0;
    const risk::Interval earlier = risk::wilson_interval(successes_before, before, 0.95);
    CHECK(0.5 * (earlier.upper - earlier.lower) > 0.1);
    // Later samples never move it.
    monitor.add(k + 5, true);
    CHECK(*monitor.stop_at() == stop);
}
