#pragma once
// The sections of the HTML report of a rock sweep (html_report.cpp writes the document and the
// provenance and convergence sections; html_sweep_sections.cpp and html_station_section.cpp the
// others). Private to the report library.

#include "html_document.hpp"
#include "report/html_report.hpp"

#include "db/queries.hpp"
#include "db/results_db.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rockfall::report::html {

/// What every section of a sweep's report reads, and what they leave out and why.
struct SweepContext {
    const db::ResultsDb& db;
    const HtmlReportOptions& options;
    /// `rockfall query DB summary` at the options' confidence.
    db::Summary summary;
    /// The confidence in percent ("95").
    std::string confidence;
    /// Figures numbered in order over the report.
    int figures = 0;
    /// Sections left out: (what, why).
    std::vector<std::pair<std::string, std::string>> left_out;

    int next_figure() { return ++figures; }
    /// Records a section left out and returns no section.
    std::optional<Section> leave_out(const std::string& what, const std::string& why) {
        left_out.emplace_back(what, why);
        return std::nullopt;
    }
};

/// "95 % Wilson score interval" or "95 % Clopper-Pearson exact interval".
std::string proportion_interval_text(const SweepContext& context);
/// "95 % distribution-free interval from order statistics, Conover 1999".
std::string percentile_interval_text(const SweepContext& context);

/// Reach exceedance curves by shape and by zone, with P(reach >= x) at the convergence
/// distance per group.
std::optional<Section> exceedance_section(SweepContext& context, double distance);
/// Per station: passing share, percentiles, UNI 11211-4 design values.
std::optional<Section> stations_section(SweepContext& context);
/// Wall-impact percentiles of energy, impulse and peak force.
std::optional<Section> wall_section(SweepContext& context);
/// Wall impacts against the design formula's envelope.
std::optional<Section> envelope_section(SweepContext& context);
/// The worst rocks by reach and by peak force, with their replay commands.
std::optional<Section> worst_section(SweepContext& context);

}  // namespace rockfall::report::html
