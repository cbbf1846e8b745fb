#pragma once
/// `rockfall query DB summary` on a calibration database (`rockfall calibrate drop|heap --db`):
/// one row per shape with its measure over the drops or heaps at the configured parameter and,
/// when identified, the parameter found.

#include "report/query_table.hpp"

#include "db/calibration_run.hpp"

#include <ostream>
#include <string>

namespace rockfall::report {

/// The shapes as a table: label, kind, sphericity, count, the measure's mean, sd and 95 %
/// Student t interval (mean kinematic COR from heights for a drop test, mean angle of repose in
/// deg for a heap test) at the configured parameter, and the identification (target,
/// parameter, value, the consistent range) where there is one.
Table calibration_shapes_table(const db::CalibrationRecord& record);

/// The summary as text (a header naming the experiment, tool and times, then the table), CSV
/// (the table) or JSON (the run and the rows).
void write_calibration_summary(std::ostream& out, QueryFormat format, const std::string& database,
                               const db::CalibrationRecord& record);

}  // namespace rockfall::report
