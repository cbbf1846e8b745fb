#pragma once
/// Synthetic sweep results for the tests, the CLI test fixture and the database benchmark:
/// plausible inputs and outcomes (about 30 % of the rocks hit the wall) with no engine run.
/// Not part of the rockfall_db library.

#include "db/results_db.hpp"

#include <cstddef>
#include <cstdint>

namespace rockfall::db::testing {

/// What the synthetic records look like.
struct SyntheticOptions {
    /// Seed of the whole set; record i is a pure function of (options, i).
    std::uint64_t seed = 1;
    /// Release zones ("upper", "lower", "zone 3", ...), >= 1.
    std::size_t zones = 2;
    /// Stations at 0, 3, 6, ... m past the toe.
    std::size_t stations = 2;
    /// Trajectory states per record (0: none).
    std::size_t trajectory_points = 0;
    /// Horizontal distance of the wall past the toe, m: rocks whose travel reaches it hit it.
    double wall_distance = 4.0;
};

/// A run record for `samples_planned` synthetic samples.
RunRecord synthetic_run(const SyntheticOptions& options, std::int64_t samples_planned);

/// Sample `index` (>= 0).
SampleRecord synthetic_record(const SyntheticOptions& options, std::int64_t index);

}  // namespace rockfall::db::testing
