#pragma once
/// The database record of a finished calibration experiment: what `rockfall calibrate drop
/// --db` and `calibrate heap --db` store (db/calibration_run.hpp).

#include "calibrate_drop.hpp"
#include "calibrate_heap.hpp"

#include "db/calibration_run.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

namespace rockfall::app {

/// What the command line said and when it ran.
struct CalibrationRun {
    /// The --scenario file's text, when given (else empty).
    std::string scenario_text;
    /// The experiment's settings (options that are not per shape), stored as run.settings_json.
    nlohmann::json settings = nlohmann::json::object();
    /// Start and end, UTC, ISO 8601.
    std::string started_at;
    std::string finished_at;
};

/// The record of a drop test: every shape, its drops at the configured surface and its
/// identification curve.
db::CalibrationRecord drop_record(const DropReport& report, const CalibrationRun& run);

/// The record of a heap test: every shape, its heaps at the configured friction and at each
/// point of its identification curve.
db::CalibrationRecord heap_record(const HeapReport& report, const CalibrationRun& run);

}  // namespace rockfall::app
