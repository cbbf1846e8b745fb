#pragma once
/// A soil flow's reports: what `rockfall soil` prints and what `rockfall query DB summary|history`
/// prints back from a soil database. One record, so both print the same. Every number carries its
/// unit; in 2D forces, impulses, masses and energies are per metre of width and say so.

#include "report/load_history_figure.hpp"
#include "report/query_table.hpp"
#include "report/svg_plot.hpp"

#include "db/soil_run.hpp"
#include "risk/load_history.hpp"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace rockfall::report {

/// The readable summary: run, wall load (peak of the sampled, filtered and single-step load,
/// when, impulse), deposit (runout, final front and centre of mass, highest point). `origin`
/// says where the run comes from (the scenario file, or a database).
void print_soil_summary(std::ostream& out, const db::SoilRunRecord& record,
                        const std::string& origin);

/// The summary and the sampled history as one JSON document with unit-suffixed keys (ending
/// in `_per_m` in 2D, where `per_metre_of_width` is true).
nlohmann::json soil_json(const db::SoilRunRecord& record);

/// The summary as rows of (item, value), item names carrying their units, for CSV.
Table soil_summary_items(const db::SoilRunRecord& record);

/// The sampled history: time, wall load normal to the wall (mean per interval, filtered),
/// centre of mass x and z, front, kinetic energy; units in the column names.
Table soil_history(const db::SoilRunRecord& record);

/// The sampled wall load normal to the wall (N, or N/m in 2D), as recorded (`filtered`
/// false) or filtered by the run's moving average.
risk::LoadHistory sampled_load(const db::SoilRunRecord& record, bool filtered);

/// The run's filter of the sampled wall load in words ("filtered by a centred moving average
/// over 0.05 s" or "unfiltered").
std::string filter_text(const db::SoilRunRecord& record);

/// The comparison of the run's filtered sampled load with a measured record
/// (risk::compare_histories): peaks, impulses, mean loads before and after the measured peak
/// and the RMS difference, in kN (kN/m in 2D), and the ratios simulated / measured.
void print_measured_comparison(std::ostream& out, const risk::HistoryComparison& comparison,
                               const risk::LoadHistory& measured, const db::SoilRunRecord& record);

/// The same as JSON fields in N (N/m in 2D, keys ending in `_per_m`); a ratio without a
/// measured denominator is null.
nlohmann::json measured_comparison_json(const risk::HistoryComparison& comparison,
                                        const risk::LoadHistory& measured);

/// The wall-load figure of a run named `name`: sampled and filtered load and, when given, a
/// measured record (load_history_plot).
Plot soil_load_figure(const db::SoilRunRecord& record, const std::string& name,
                      const risk::LoadHistory* measured);

/// `rockfall query DB summary` on a soil database: the readable summary with the stored run's
/// times and tool, the JSON document, or CSV items.
void write_soil_summary(std::ostream& out, QueryFormat format, const std::string& database,
                        const db::SoilRunRecord& record);

/// `rockfall query DB history`: the sampled history as a table, CSV or JSON rows.
void write_soil_history(std::ostream& out, QueryFormat format, const std::string& database,
                        const db::SoilRunRecord& record);

}  // namespace rockfall::report
