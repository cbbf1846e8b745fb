#pragma once
/// The runs of `rockfall validate`'s seed 001 reproduction (docs/validation.md): the six flume
/// cases of samples/seed_flume/ as shipped (the physical rows of Table 2: a blocky cluster with
/// the four painted rocks) and with every rock, marked ones included, of one of Table 2's four
/// numerical shapes, each over several seeds.

#include "risk/parallel.hpp"
#include "risk/seed001.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace rockfall::app {

/// What to run.
struct Seed001Options {
    /// The folder with flume.toml and c1_30.toml ... c2_60.toml.
    std::filesystem::path flume_dir;
    /// The shape catalogue with the tetrahedron, cube and octahedron entries.
    std::filesystem::path catalogue;
    /// Cluster seeds first_seed, first_seed + 1, ... (seeds >= 1).
    int seeds = 3;
    std::uint64_t first_seed = 1;
    /// Worker threads (>= 1): runs are independent.
    int threads = 1;
    /// Replaces every case's [wall_cells] sample_interval, s, when set (the sensitivity study).
    std::optional<double> sample_interval;
    /// Replaces every case's numerics.max_time, s, when set: the marked rocks' impacts are over
    /// well before their deposit comes to rest.
    std::optional<double> max_time;
    /// Which runs: the physical rows, the numerical rows, or both.
    bool physical = true;
    bool numerical = true;
    /// Called with runs done and planned.
    risk::ParallelProgress progress;
};

/// Runs every case for every seed (in parallel; the records come back in a fixed order:
/// cluster, angle, physical then the four shapes, seed). Throws scenario::ScenarioError when a
/// case file does not load.
std::vector<risk::seed001::RunRecord> run_seed001(const Seed001Options& options);

}  // namespace rockfall::app
