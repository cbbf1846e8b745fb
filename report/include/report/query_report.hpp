#pragma once
/// The results of `rockfall query` as text, CSV or JSON. Every number carries its unit: in
/// text after the value or in the column header, in CSV and JSON as a name suffix.

#include "report/query_table.hpp"

#include "db/queries.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace rockfall::report {

/// `percentiles`: one row per group and level; `by` names the group column, `per` what an
/// observation is (the column counting them is named "rocks" or "samples").
void write_percentiles(std::ostream& out, QueryFormat format, const std::string& database,
                       const db::PercentileTable& table, db::GroupBy by,
                       db::Per per = db::Per::rock);

/// `exceed`: one row per group.
void write_exceedance(std::ostream& out, QueryFormat format, const std::string& database,
                      const db::ExceedanceTable& table, db::GroupBy by,
                      db::Per per = db::Per::rock);

/// `curve`: one row per group and threshold.
void write_curve(std::ostream& out, QueryFormat format, const std::string& database,
                 const db::ExceedanceCurve& curve, db::GroupBy by, db::Per per = db::Per::rock);

/// Which rocks or samples an exceedance probability is over, in words.
std::string exceedance_trials(db::Quantity quantity, db::Per per = db::Per::rock);

/// `worst`: one row per rock (sample and rock index) or, per sample, per sample (no rock
/// index), worst first, ranked by `by`.
void write_worst(std::ostream& out, QueryFormat format, const std::string& database,
                 db::Quantity by, const std::vector<db::WorstSample>& worst,
                 db::Per per = db::Per::rock);

/// `summary`: the run, stop reasons, reach, wall and station shares, wall load percentiles.
void write_summary(std::ostream& out, QueryFormat format, const std::string& database,
                   const db::Summary& summary);

/// A share as the summary's text prints it, `confidence` in percent ("95"):
/// "12 of 40, 30 % (95 % CI 17.9 to 45.6 %)"; "none" without trials.
std::string share_text(const db::Share& share, const std::string& confidence);

/// The quantity's output column name with its unit ("reach_m", "impact_energy_J").
std::string quantity_column(db::Quantity quantity);

/// Which rocks or samples a quantity is taken over, in words, for text and JSON.
std::string population_of(db::Quantity quantity, db::Per per = db::Per::rock);

}  // namespace rockfall::report
