#pragma once
/// What a sweep writes about itself into its results database: the spec as JSON, the hash
/// that ties a database to its scenario and settings (checked by --resume), the run record.

#include "scenario/scenario_file.hpp"

#include "db/results_db.hpp"
#include "risk/sampling.hpp"
#include "risk/sweep_runner.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace rockfall::app {

/// Everything that decides a sweep's results and stopping point: the scenario text (with its
/// [sweep] table), the command line's overrides of it and the --until rule.
struct SweepIdentity {
    std::string scenario_text;
    nlohmann::json overrides;
    std::string stop_rule;
};

/// A share of a sweep's sample indices (`--shard K/N`): the indices i with i % count == index.
struct Shard {
    /// K, in [0, count - 1].
    std::int64_t index = 0;
    /// N, in [1, risk::max_samples].
    std::int64_t count = 1;
    /// Whether sample `sample` is in this shard.
    bool holds(std::int64_t sample) const { return sample % count == index; }
    /// The form `--shard` takes and run.settings_json stores: "K/N".
    std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

/// Reads "K/N" (decimal digits only); throws std::invalid_argument naming `option`, the value
/// and the allowed range for anything else (N < 1, K >= N, a sign, spaces, an overflow).
Shard parse_shard(const std::string& text, const std::string& option);

/// The run's settings (run.settings_json) as a JSON object; throws std::invalid_argument
/// naming `db_path`, after `doing` ("cannot resume: "), when it is not one (a damaged file).
nlohmann::json stored_settings(const db::RunRecord& run, const std::string& db_path,
                               const std::string& doing);

/// The shard a run's settings record ("shard": "K/N"); none for a whole run. Throws
/// std::invalid_argument naming `db_path` when the stored value is malformed.
std::optional<Shard> stored_shard(const nlohmann::json& settings, const std::string& db_path);

/// 64-bit FNV-1a hash (Fowler, Noll and Vo; not cryptographic: it detects a changed scenario,
/// it does not authenticate one) of the identity, as 16 hex digits.
std::string identity_hash(const SweepIdentity& identity);

/// Now, UTC, ISO 8601 to the second ("2026-11-22T10:31:02Z").
std::string utc_now();

/// The run record of a new sweep database.
db::RunRecord make_run_record(const scenario::ScenarioFile& file, const risk::SweepSpec& spec,
                              const std::string& stop_rule, const nlohmann::json& settings);

/// Throws std::invalid_argument naming the database and what differs when `run` was not made
/// from the same scenario, spec and stop rule (--resume with other settings given).
void check_resumable(const db::RunRecord& run, const db::RunRecord& wanted,
                     const std::string& db_path);

}  // namespace rockfall::app
