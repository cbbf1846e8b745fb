#pragma once
/// Merging results databases of one sweep run in pieces (`rockfall sweep --shard K/N`) into
/// one file, sample rows copied as they are with their sample indices.

#include "db/results_db.hpp"

#include <filesystem>
#include <vector>

namespace rockfall::db {

/// Creates the database `out` holding `run` (its run record and zones) and every sample row of
/// each of `shards` (samples, rocks, outcomes, stations, wall_impacts, trajectories), copied
/// unchanged. The caller has checked that the shards hold the same run with disjoint samples.
/// Each shard must be a rock sweep of this build's schema version passing SQLite's
/// quick_check; else throws DatabaseError (bad_file) naming it. The file is built beside `out`
/// under a hidden temporary name and appears whole at the end or not at all: a failure leaves
/// no `out` (and an existing `out` is refused before anything is read, never replaced).
void merge_runs(const std::filesystem::path& out, const RunRecord& run,
                const std::vector<std::filesystem::path>& shards);

}  // namespace rockfall::db
