#pragma once
/// A sweep over MPI ranks (docs/cluster.md): rank 0 owns the database, the stop rule and the
/// progress, and runs samples on its own threads too; every other rank takes chunks of sample
/// indices from it, runs them on all its threads and sends the finished samples back
/// (db/sample_codec.hpp). mpi.h stays inside sweep_mpi.cpp; a build without MPI compiles
/// sweep_mpi_none.cpp instead, whose Session refuses to start.

#include "engine/scenario.hpp"
#include "risk/sampling.hpp"
#include "risk/sweep_runner.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rockfall::app {

/// For the signal tests (the hidden --pause-after): stops this process (SIGSTOP to itself) when
/// a count of samples passes `pause_after` on going from `before` to `now`, so that the test's
/// signal, sent while it is stopped and delivered on SIGCONT, lands mid-run however fast the
/// machine is. Negative `pause_after`: never.
inline void pause_after_samples(std::int64_t pause_after, std::int64_t before, std::int64_t now) {
    if (pause_after >= 0 && before < pause_after && now >= pause_after) std::raise(SIGSTOP);
}

/// Where a sweep's finished samples come from: this process's threads, or every rank's.
class SampleSource {
  public:
    virtual ~SampleSource() = default;
    /// As risk::SweepRunner::collect: waits up to `timeout` for a finished sample, then
    /// returns every one finished so far.
    virtual std::vector<risk::SampleResult> collect(std::chrono::milliseconds timeout) = 0;
    /// No sample is started anywhere any more; those running finish and are still collected.
    virtual void stop() = 0;
    /// Nothing runs anywhere and nothing is left to collect.
    virtual bool finished() const = 0;
};

namespace mpi {

/// True when the environment says this process is one of several ranks started by mpirun or
/// srun (OMPI_COMM_WORLD_SIZE or PMI_SIZE above 1).
inline bool launched_as_ranks() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
        const char* value = std::getenv(name);
        if (value != nullptr && std::atoi(value) > 1) return true;
    }
    return false;
}

/// What the owner sends every other rank before the samples: the scenario as the database
/// stores it and the options that decide the samples.
struct Setup {
    std::string scenario_text;
    /// The scenario's path as the owner names it (messages, relative paths).
    std::string scenario_path;
    std::uint64_t seed = 0;
    std::int64_t samples = 0;
    std::string method;
    /// Trajectory interval, s (0: none).
    double trajectory_interval = 0.0;
};

/// MPI from MPI_Init_thread to MPI_Finalize on MPI_COMM_WORLD; only the thread that made it
/// calls MPI. Rank 0 that never sent a Setup tells the other ranks to end when it is
/// destroyed, so that an owner refusing its command line ends the whole job.
class Session {
  public:
    /// Starts MPI; throws std::runtime_error in a build without MPI, saying so.
    Session();
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    /// This process's rank, in [0, size()), and the number of ranks.
    int rank() const { return rank_; }
    int size() const { return size_; }

    /// Rank 0: sends `setup` to every other rank (once).
    void send_setup(const Setup& setup);
    /// Other ranks: the owner's setup; none when the owner ends without starting a sweep.
    std::optional<Setup> receive_setup();

    /// Rank 0, after send_setup: a source over `options.threads` threads here and every other
    /// rank, handing out `pending` in order in chunks; a rank's interrupt sets `interrupt`.
    std::unique_ptr<SampleSource> owner_source(const risk::SweepSpec& spec,
                                               const engine::Scenario& base,
                                               std::vector<std::int64_t> pending,
                                               const risk::RunnerOptions& options,
                                               std::atomic<int>& interrupt);

    /// Other ranks, after receive_setup: runs the chunks rank 0 hands out on options.threads
    /// threads and sends the samples back, until rank 0 has no more or says stop; a signal
    /// (`interrupt` set) is passed on to rank 0. Returns the exit code.
    int serve(const risk::SweepSpec& spec, const engine::Scenario& base,
              const risk::RunnerOptions& options, const std::atomic<int>& interrupt);

    /// For the signal tests: serve() pauses once it has sent `samples` samples
    /// (pause_after_samples); negative: never.
    void pause_after(std::int64_t samples) { pause_after_ = samples; }

    /// Whether rank 0 sent its setup and the other ranks have not all ended yet.
    bool others_running() const;
    /// Ends every rank at once (MPI_Abort) with `code`; for a rank that cannot go on.
    [[noreturn]] void abort(int code);

  private:
    int rank_ = 0;
    int size_ = 1;
    bool setup_sent_ = false;
    std::int64_t pause_after_ = -1;
    // Set by the owner source once every other rank has said it is done.
    std::shared_ptr<bool> others_done_ = std::make_shared<bool>(false);
};

}  // namespace mpi
}  // namespace rockfall::app
