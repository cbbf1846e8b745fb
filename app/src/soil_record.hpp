#pragma once
/// The database record of a finished soil flow: what `rockfall soil --db` stores and prints.

#include "scenario/soil_file.hpp"

#include "db/soil_run.hpp"
#include "mpm/soil.hpp"

#include <string>

namespace rockfall::app {

/// When a soil flow ran and how long it took.
struct SoilRunTimes {
    /// Start and end, UTC, ISO 8601.
    std::string started_at;
    std::string finished_at;
    /// Wall-clock runtime, s.
    double runtime = 0.0;
};

/// The record of a finished run of `file`: the run (tool, scenario text and hash, settings),
/// the summary and the histories; y components NaN in 2D.
db::SoilRunRecord make_soil_record(const scenario::SoilFile& file, const mpm::SoilOutcome& outcome,
                                   const SoilRunTimes& times);

}  // namespace rockfall::app
