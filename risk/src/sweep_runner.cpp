#include "risk/sweep_runner.hpp"

#include "engine/simulation.hpp"
#include "risk/statistics.hpp"

#include <algorithm>
#include <cassert>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

namespace rockfall::risk {

SampleResult run_sample(const SweepSpec& spec, const engine::Scenario& base, std::int64_t index,
                        double trajectory_interval) {
    SampleResult result;
    result.inputs = draw_sample(spec, base, index);
    const engine::Scenario scenario = sample_scenario(base, result.inputs);
    engine::RunOptions options;
    std::vector<std::vector<engine::RockState>> trajectories;
    if (trajectory_interval > 0.0) {
        options.trajectory_interval = trajectory_interval;
        options.trajectory = [&trajectories](int rock, const engine::RockState& state) {
            const auto slot = static_cast<std::size_t>(rock);
            if (slot >= trajectories.size()) trajectories.resize(slot + 1);
            trajectories[slot].push_back(state);
        };
    }
    engine::Outcome outcome = engine::simulate(scenario, result.inputs.seed, options);
    assert(scenario.cluster || outcome.rocks.size() == 1);
    std::vector<RockInputs> inputs = rock_inputs(scenario, result.inputs, outcome.rocks);
    trajectories.resize(outcome.rocks.size());
    result.rocks.reserve(outcome.rocks.size());
    double mass = 0.0;
    for (std::size_t i = 0; i < outcome.rocks.size(); ++i) {
        mass += inputs[i].mass;
        result.rocks.push_back(
            {std::move(inputs[i]), std::move(outcome.rocks[i]), std::move(trajectories[i])});
    }
    if (scenario.cluster) result.inputs.mass = mass;
    return result;
}

SweepRunner::SweepRunner(const SweepSpec& spec, const engine::Scenario& base,
                         std::vector<std::int64_t> pending, const RunnerOptions& options)
    : spec_(spec), base_(base), options_(options), pending_(std::move(pending)), closed_(true) {
    assert(options.threads >= 1);
    // A worker beyond one per sample would find nothing to take; not starting it also keeps
    // `--threads 1024 --samples 4` to 4 threads.
    start(std::min(static_cast<std::size_t>(options.threads),
                   std::max<std::size_t>(pending_.size(), 1)));
}

SweepRunner::SweepRunner(const SweepSpec& spec, const engine::Scenario& base,
                         const RunnerOptions& options)
    : spec_(spec), base_(base), options_(options) {
    assert(options.threads >= 1);
    start(static_cast<std::size_t>(options.threads));
}

void SweepRunner::start(std::size_t count) {
    running_ = static_cast<int>(count);
    workers_.reserve(count);
    try {
        for (std::size_t i = 0; i < count; ++i) workers_.emplace_back([this] { work(); });
    } catch (const std::system_error& error) {
        // The system refused a thread (its limit on threads or memory): the started workers
        // are joined, as a std::thread may not be destroyed while it runs.
        const std::size_t started = workers_.size();
        stop();
        for (std::thread& worker : workers_) worker.join();
        throw std::runtime_error("the system refused worker thread " + std::to_string(started + 1) +
                                 " of " + std::to_string(count) + " (" + error.what() +
                                 "): use at most " + std::to_string(started) +
                                 " worker threads here");
    }
}

SweepRunner::~SweepRunner() {
    stop();
    for (std::thread& worker : workers_) worker.join();
}

void SweepRunner::work() {
    for (;;) {
        std::int64_t index = 0;
        {
            std::unique_lock lock(mutex_);
            work_.wait(lock,
                       [this] { return stopping_.load() || next_ < pending_.size() || closed_; });
            if (stopping_.load() || next_ >= pending_.size()) break;
            index = pending_[next_++];
        }
        try {
            SampleResult result = run_sample(spec_, base_, index, options_.trajectory_interval);
            const std::lock_guard lock(mutex_);
            results_.push_back(std::move(result));
        } catch (...) {
            const std::lock_guard lock(mutex_);
            if (!error_) error_ = std::current_exception();
            stopping_.store(true);
            work_.notify_all();
        }
        ready_.notify_all();
    }
    const std::lock_guard lock(mutex_);
    --running_;
    ready_.notify_all();
}

std::vector<SampleResult> SweepRunner::collect(std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    ready_.wait_for(lock, timeout, [this] { return !results_.empty() || running_ == 0 || error_; });
    if (error_) std::rethrow_exception(error_);
    return std::exchange(results_, {});
}

void SweepRunner::stop() {
    {
        const std::lock_guard lock(mutex_);
        stopping_.store(true);
    }
    work_.notify_all();
}

void SweepRunner::add(const std::vector<std::int64_t>& indices) {
    {
        const std::lock_guard lock(mutex_);
        assert(!closed_ && "no indices after close()");
        pending_.insert(pending_.end(), indices.begin(), indices.end());
    }
    work_.notify_all();
}

void SweepRunner::close() {
    {
        const std::lock_guard lock(mutex_);
        closed_ = true;
    }
    work_.notify_all();
}

std::size_t SweepRunner::waiting() const {
    const std::lock_guard lock(mutex_);
    return pending_.size() - next_;
}

bool SweepRunner::finished() const {
    const std::lock_guard lock(mutex_);
    return running_ == 0 && results_.empty();
}

bool UntilRule::success(const engine::RockOutcome& outcome) const {
    switch (statistic) {
        case Statistic::wall:
            return !outcome.wall_hits.empty();
        case Statistic::exceed:
            return outcome.reach >= distance;
    }
    return false;
}

bool UntilRule::success(const std::vector<RockResult>& rocks) const {
    return std::any_of(rocks.begin(), rocks.end(),
                       [this](const RockResult& rock) { return success(rock.outcome); });
}

std::string UntilRule::describe() const {
    char text[160];
    if (statistic == Statistic::wall) {
        std::snprintf(text, sizeof text,
                      "until the wall probability is known to +-%g at %g %% (checked every %lld "
                      "samples)",
                      half_width, 100.0 * confidence, static_cast<long long>(check_every));
    } else {
        std::snprintf(text, sizeof text,
                      "until P(reach >= %g m) is known to +-%g at %g %% (checked every %lld "
                      "samples)",
                      distance, half_width, 100.0 * confidence,
                      static_cast<long long>(check_every));
    }
    return text;
}

void UntilMonitor::add(std::int64_t index, bool success) {
    assert(index >= 0);
    const auto slot = static_cast<std::size_t>(index);
    if (slot >= state_.size()) state_.resize(slot + 1, -1);
    assert(state_[slot] == -1 && "a sample is recorded once");
    state_[slot] = success ? 1 : 0;
    while (static_cast<std::size_t>(prefix_) < state_.size() &&
           state_[static_cast<std::size_t>(prefix_)] != -1) {
        prefix_successes_ += state_[static_cast<std::size_t>(prefix_)];
        ++prefix_;
        if (!stop_ && prefix_ % rule_.check_every == 0 && half_width() <= rule_.half_width) {
            stop_ = prefix_;
        }
    }
}

std::optional<std::int64_t> UntilMonitor::stop_at() { return stop_; }

double UntilMonitor::half_width() const {
    if (prefix_ == 0) return 1.0;
    const Interval interval = wilson_interval(prefix_successes_, prefix_, rule_.confidence);
    return 0.5 * (interval.upper - interval.lower);
}

}  // namespace rockfall::risk
