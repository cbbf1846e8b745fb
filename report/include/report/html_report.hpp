#pragma once
/// `rockfall report DB --html FILE`: one self-contained HTML file of a results database (inline
/// CSS with a print style sheet, inline SVG figures, no script, nothing fetched), readable in
/// any browser and printable to PDF. Its bytes depend only on the database and the options:
/// no time of writing, no absolute paths other than those given.
///
/// A rock sweep's sections, each only when the database has its data: provenance; convergence
/// of the share of samples reaching the wall and of P(reach >= x) against the samples done;
/// reach exceedance curves by shape and by zone; per station the passing share, percentiles
/// of speed, bounce height and energy and the UNI 11211-4 design values; wall-impact
/// percentiles; the comparison with a design-formula envelope; the worst samples with the
/// command that replays each. A soil flow's: provenance, wall-load history and its peaks, the
/// deposit. Every number carries its unit, every interval its method and level.

#include "report/impact_data.hpp"

#include "db/queries.hpp"
#include "db/results_db.hpp"
#include "risk/design_values.hpp"
#include "risk/envelope.hpp"

#include <optional>
#include <ostream>
#include <string>

namespace rockfall::report {

/// What the report computes beyond what the database holds.
struct HtmlReportOptions {
    /// The database as named on the command line: shown, and used in the replay commands.
    std::string database;
    /// The program writing the report, e.g. "rockfall 0.9.0 (RelWithDebInfo, GNU 12.2.0)".
    std::string generator;
    /// Confidence of every interval, in (0, 1).
    double confidence = 0.95;
    /// Interval of the proportions (convergence, exceedance).
    db::IntervalMethod method = db::IntervalMethod::wilson;
    /// Distance past the toe of the convergence of P(reach >= x), m; unset: the 90th
    /// percentile of the samples' reach rounded to two significant digits.
    std::optional<double> distance;
    /// Thresholds of each exceedance curve, in [2, 10000].
    int curve_points = 200;
    /// Envelope comparison: the formula, the velocity it gets and the slowest impact kept (m/s).
    risk::EnvelopeFormula formula;
    HitVelocity velocity = HitVelocity::normal;
    double min_velocity = 0.0;
    /// Rows of each worst-samples table (>= 1).
    int worst = 10;
    /// UNI 11211-4: characteristic percentile (fraction in (0, 1)), partial factors and the
    /// design block's mass (kg, > 0); unset: the largest rock that crossed the station.
    double design_percentile = 0.95;
    risk::PartialFactors factors;
    std::optional<double> design_mass;
};

/// Throws std::invalid_argument naming the option and its value when an option is out of
/// range: a check before the database is read.
void validate(const HtmlReportOptions& options);

/// Writes the report of `db` (a rock sweep or a soil flow, ResultsDb::open_any) to `out`.
/// Throws db::DatabaseError for a damaged file and std::invalid_argument for bad options.
void write_html_report(std::ostream& out, const db::ResultsDb& db,
                       const HtmlReportOptions& options);

}  // namespace rockfall::report
