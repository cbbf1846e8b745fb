#pragma once
/// Running the samples of a sweep on worker threads, one Bullet world per sample, and the
/// confidence-interval stop rule checked on the completed prefix of samples.

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"
#include "risk/sampling.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace rockfall::risk {

/// Simulates one sample alone: draw_sample, sample_scenario, engine::simulate with the
/// sample's seed. `trajectory_interval` in s; 0 records no trajectory.
SampleResult run_sample(const SweepSpec& spec, const engine::Scenario& base, std::int64_t index,
                        double trajectory_interval = 0.0);

/// Options of a SweepRunner.
struct RunnerOptions {
    /// Worker threads (>= 1); no more start than there are samples to run.
    int threads = 1;
    /// Interval between recorded trajectory samples, s (0: none).
    double trajectory_interval = 0.0;
};

/// Worker threads that take sample indices from a list in list order and simulate them.
/// Results come back through collect() in completion order; which thread ran a sample never
/// changes its result (draw_sample is a pure function of the index). The list is fixed at
/// construction, or grows by add() until close() (an MPI rank fed chunks by the owner).
class SweepRunner {
  public:
    /// Starts min(options.threads, pending.size()) workers (at least one) on `pending` (indices
    /// to run, in the order to take them). The spec and base must outlive the runner. Throws
    /// std::runtime_error, saying how many threads did start, when the system refuses a thread.
    SweepRunner(const SweepSpec& spec, const engine::Scenario& base,
                std::vector<std::int64_t> pending, const RunnerOptions& options);
    /// Starts options.threads workers on an empty list that add() extends; the workers wait
    /// for indices until close(). Throws as the constructor above.
    SweepRunner(const SweepSpec& spec, const engine::Scenario& base, const RunnerOptions& options);
    /// Stops the workers (after their current sample) and joins them.
    ~SweepRunner();
    SweepRunner(const SweepRunner&) = delete;
    SweepRunner& operator=(const SweepRunner&) = delete;

    /// Waits up to `timeout` for at least one finished sample, then moves out everything
    /// finished so far (possibly nothing). Rethrows the first exception a worker raised.
    std::vector<SampleResult> collect(std::chrono::milliseconds timeout);

    /// Workers take no new sample; those running finish and can still be collected.
    void stop();

    /// Appends indices to the list (not after close()).
    void add(const std::vector<std::int64_t>& indices);
    /// No more indices will be added: workers end once the list is done.
    void close();
    /// Indices added that no worker has taken yet.
    std::size_t waiting() const;

    /// True when no worker runs and nothing is left to collect.
    bool finished() const;

  private:
    void start(std::size_t count);
    void work();

    const SweepSpec& spec_;
    const engine::Scenario& base_;
    const RunnerOptions options_;
    // The list and the next index to take, under mutex_; work_ signals an addition.
    std::vector<std::int64_t> pending_;
    std::size_t next_ = 0;
    bool closed_ = false;
    std::atomic<bool> stopping_{false};
    mutable std::mutex mutex_;
    std::condition_variable work_;
    std::condition_variable ready_;
    std::vector<SampleResult> results_;
    int running_ = 0;
    std::exception_ptr error_;
    std::vector<std::thread> workers_;
};

/// The `--until` stop rule: stop once the Wilson interval of a proportion over the first k
/// samples has a half-width at most `half_width`, checked at k = check_every, 2 check_every,
/// ... Using the completed prefix, not whatever finished first, makes the stopping point and
/// hence the result independent of threads, timing and interruptions.
struct UntilRule {
    /// The proportion estimated.
    enum class Statistic {
        wall,    ///< share of samples with a rock that hit the reaction wall
        exceed,  ///< share of samples with a rock whose reach is >= distance
    };
    Statistic statistic = Statistic::wall;
    /// For exceed: horizontal distance past the toe, m.
    double distance = 0.0;
    /// Target half-width of the interval, as a proportion in (0, 0.5].
    double half_width = 0.01;
    /// Confidence level of the interval, in (0, 1).
    double confidence = 0.95;
    /// Samples between checks (>= 1).
    std::int64_t check_every = 100;

    /// Whether one rock's outcome counts as a success of the proportion.
    bool success(const engine::RockOutcome& outcome) const;
    /// Whether a sample counts as a success: any of its rocks does.
    bool success(const std::vector<RockResult>& rocks) const;
    /// Readable form, e.g. "wall probability +-0.01 at 95 %".
    std::string describe() const;
};

/// Tracks which samples have finished and finds the first checkpoint meeting the rule.
class UntilMonitor {
  public:
    explicit UntilMonitor(UntilRule rule) : rule_(rule) {}
    /// Records sample `index`'s success.
    void add(std::int64_t index, bool success);
    /// The first checkpoint k (samples 0 .. k-1 all finished) at which the rule holds, if any
    /// has been reached; never changes once found.
    std::optional<std::int64_t> stop_at();
    /// Length of the completed prefix and its successes.
    std::int64_t prefix() const { return prefix_; }
    std::int64_t prefix_successes() const { return prefix_successes_; }
    /// Current half-width of the interval over the completed prefix (1 when empty).
    double half_width() const;

  private:
    UntilRule rule_;
    std::vector<signed char> state_;  // -1 unknown, 0 failure, 1 success, per index
    std::int64_t prefix_ = 0;
    std::int64_t prefix_successes_ = 0;
    std::optional<std::int64_t> stop_;
};

}  // namespace rockfall::risk
