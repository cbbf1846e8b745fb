// The HTML report of a results database (see html_report.hpp): the document, its provenance
// and convergence sections, and a soil flow's sections; the other sweep sections are in
// html_sweep_sections.cpp and html_station_section.cpp.

#include "report/html_report.hpp"

#include "html_sections.hpp"
#include "report/query_report.hpp"
#include "report/soil_report.hpp"
#include "report/text_format.hpp"

#include "db/soil_run.hpp"
#include "risk/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rockfall::report {
namespace {

using html::Section;
using html::SweepContext;
using Items = std::vector<std::pair<std::string, std::string>>;

// Points of the convergence figure at most: smooth at figure size, small in the file.
constexpr std::int64_t convergence_points = 200;

std::string count_text(std::int64_t n, const std::string& what) {
    return std::to_string(n) + " " + what;
}

Items run_items(const db::RunRecord& run) {
    return {{"tool that ran it", "rockfall " + run.tool_version + " (" + run.build + ")"},
            {"scenario", run.scenario_name},
            {"scenario hash", run.scenario_hash},
            {"seed", std::to_string(run.seed)},
            {"method", run.method},
            {"stop rule", run.stop_rule},
            {"status", run.status},
            {"started (UTC)", run.started_at},
            {"finished (UTC)", run.finished_at.empty() ? "-" : run.finished_at}};
}

Section provenance(const db::RunRecord& run, const Items& counts, const std::string& database) {
    Items rows = {{"database", database}};
    for (const auto& row : run_items(run)) rows.push_back(row);
    rows.insert(rows.begin() + 6, counts.begin(), counts.end());
    if (!run.zones.empty()) {
        std::string zones;
        for (const std::string& z : run.zones) zones += (zones.empty() ? "" : ", ") + z;
        rows.emplace_back("release zones", zones);
    }
    rows.emplace_back("other settings (JSON)", run.settings_json);
    rows.emplace_back("scenario text", "in the appendix, as run");
    return {"provenance", "Provenance", html::items(rows)};
}

// The scenario's full text, last: pages of TOML would push the results back.
Section scenario_appendix(const db::RunRecord& run, const std::string& rerun) {
    return {"scenario", "Appendix: scenario as run",
            html::paragraph("The complete resolved scenario (TOML, " +
                            std::to_string(run.scenario_text.size()) + " bytes, hash " +
                            run.scenario_hash + ") the run stored; " + rerun + ".") +
                html::preformatted(run.scenario_text)};
}

// The distance of the convergence of P(reach >= x): the option, or the 90th percentile of the
// samples' reach to two significant digits (an exceedance of about 10 %, where the estimate
// is still settling after a few hundred samples).
double convergence_distance(const HtmlReportOptions& options,
                            const std::vector<db::StoredOutcome>& outcomes) {
    if (options.distance) return *options.distance;
    std::vector<double> reach;
    for (const db::StoredOutcome& o : outcomes) {
        if (!std::isnan(o.reach)) reach.push_back(o.reach);
    }
    if (reach.empty()) return 0.0;
    std::sort(reach.begin(), reach.end());
    return std::stod(fmt("%.2g", risk::quantile(reach, 0.9)));
}

risk::Interval interval(const SweepContext& c, std::int64_t count, std::int64_t trials) {
    if (trials == 0) return {0.0, 1.0};
    return c.options.method == db::IntervalMethod::wilson
               ? risk::wilson_interval(count, trials, c.options.confidence)
               : risk::clopper_pearson_interval(count, trials, c.options.confidence);
}

// An estimate and its band as three series of one colour.
struct Band {
    Series estimate;
    Series lower;
    Series upper;
};

Band band(const std::string& label, const char* color) {
    Band b;
    b.estimate.label = label;
    b.estimate.color = color;
    b.estimate.line_width = 2.0;
    b.lower.color = color;
    b.lower.line_width = 0.8;
    b.lower.dash = "4 3";
    b.upper = b.lower;
    return b;
}

void add_point(Band& b, double n, const db::Share& s) {
    b.estimate.x.push_back(n);
    b.estimate.y.push_back(static_cast<double>(s.count) / static_cast<double>(s.trials));
    b.lower.x.push_back(n);
    b.lower.y.push_back(s.interval.lower);
    b.upper.x.push_back(n);
    b.upper.y.push_back(s.interval.upper);
}

std::optional<Section> convergence(SweepContext& c, const std::vector<db::StoredOutcome>& outcomes,
                                   double distance) {
    if (outcomes.empty()) return c.leave_out("convergence", "no samples stored");
    const auto n = static_cast<std::int64_t>(outcomes.size());
    const std::int64_t points = std::min(n, convergence_points);
    const std::string x = html::value(distance, "m");
    Band wall = band("share of samples with a rock on the wall", "#1f77b4");
    Band reach = band("P(reach >= " + x + ")", "#d62728");
    Series key = wall.lower;
    key.color = "#555555";
    key.label = html::proportion_interval_text(c);
    html::Table table{
        "Running estimates at a few sample counts",
        {"samples", "share of samples with a rock on the wall", "P(reach >= " + x + ")"},
        {}};
    // Table rows at 10, 25, 50 and 100 % of the samples (those that are distinct).
    std::vector<std::int64_t> rows;
    for (const std::int64_t percent : {10, 25, 50, 100}) {
        const std::int64_t at = std::max<std::int64_t>(1, n * percent / 100);
        if (rows.empty() || rows.back() != at) rows.push_back(at);
    }
    std::int64_t on_wall = 0;
    std::int64_t reaching = 0;
    std::int64_t reach_trials = 0;
    std::int64_t next = 1;
    std::size_t next_row = 0;
    for (std::int64_t i = 0; i < n; ++i) {
        const db::StoredOutcome& o = outcomes[static_cast<std::size_t>(i)];
        on_wall += o.wall_hits > 0 ? 1 : 0;
        if (!std::isnan(o.reach)) {
            ++reach_trials;
            reaching += o.reach >= distance ? 1 : 0;
        }
        const std::int64_t done = i + 1;
        const db::Share w{on_wall, done, interval(c, on_wall, done)};
        const db::Share r{reaching, reach_trials, interval(c, reaching, reach_trials)};
        if (done == next || done == n) {
            add_point(wall, static_cast<double>(done), w);
            if (reach_trials > 0) add_point(reach, static_cast<double>(done), r);
            next = (static_cast<std::int64_t>(wall.estimate.x.size()) + 1) * n / points;
        }
        if (next_row < rows.size() && done == rows[next_row]) {
            table.rows.push_back(
                {std::to_string(done), share_text(w, c.confidence), share_text(r, c.confidence)});
            ++next_row;
        }
    }
    Plot plot;
    plot.title = "Convergence: " + c.summary.run.scenario_name;
    plot.x_label = "samples done";
    plot.y_label = "probability";
    plot.x_min = 0.0;
    plot.y_min = 0.0;
    for (Band* b : {&wall, &reach}) {
        if (b->estimate.x.size() < 3) b->estimate.marker = Marker::circle;
        for (Series* s : {&b->lower, &b->upper, &b->estimate}) {
            if (!s->x.empty()) plot.series.push_back(*s);
        }
    }
    plot.series.push_back(key);
    std::string body = html::paragraph(
        "The running estimate of the share of samples with a rock on the wall, and of the "
        "probability that a sample's reach (its rocks' largest) is at least " +
        x + (c.options.distance ? "" : " (the 90th percentile of the reach, to two digits)") +
        ", after each number of samples in the order they were drawn, with the " +
        html::proportion_interval_text(c) +
        ". A run has converged when the band is as narrow "
        "as the design needs and the estimate no longer drifts.");
    body += html::figure(plot, c.next_figure(),
                         "Running estimates against the samples done (solid) with their " +
                             html::proportion_interval_text(c) + " (dashed).");
    body += html::table(table);
    return Section{"convergence", "Convergence", body};
}

// The soil flow's sections: what it was, its wall load, its deposit.
std::vector<Section> soil_sections(const db::SoilRunRecord& r, const std::string& database) {
    const bool per_metre = r.dimension == 2;
    const std::string force = per_metre ? "N/m" : "N";
    const std::string mass = per_metre ? "kg/m" : "kg";
    const Items counts = {
        {"run", std::string(per_metre ? "2D plane strain (per metre of width)" : "3D") + ", " +
                    count_text(r.particles, "material points") + ", cell " +
                    fmt("%.4g m", r.cell_size) + ", soil mass " + html::value(r.mass, mass)},
        {"outcome", r.outcome + (r.message.empty() ? "" : " (" + r.message + ")")},
        {"simulated", fmt("%.4g s", r.simulated_time) + " in " + count_text(r.steps, "steps") +
                          ", runtime " + fmt("%.4g s", r.runtime)}};
    std::vector<Section> sections = {provenance(r.run, counts, database)};
    int figures = 0;
    if (!std::isnan(r.wall_distance_from_toe) && !r.load.empty()) {
        html::Table peaks{
            "Wall load normal to the wall",
            {"quantity", "value"},
            {{"peak of the load sampled every " + fmt("%g s", r.sample_interval),
              html::value(r.peak_force, force) + " at " + fmt("%.4g s", r.peak_time)},
             {"peak of the load " + filter_text(r), html::value(r.peak_force_filtered, force)},
             {"peak of a single step's load", html::value(r.peak_force_step, force)},
             {"total impulse", html::value(r.impulse, per_metre ? "N s/m" : "N s")},
             {"wall distance past the toe", html::value(r.wall_distance_from_toe, "m")}}};
        sections.push_back(
            {"wall-load", "Wall load",
             html::table(peaks) +
                 html::figure(soil_load_figure(r, r.run.scenario_name, nullptr), ++figures,
                              "Load the soil puts on the wall, normal to it, against time.")});
    }
    html::Table deposit{"Deposit",
                        {"quantity", "value"},
                        {{"runout past the toe", html::value(r.runout_past_toe, "m")},
                         {"runout x", html::value(r.runout_x, "m")}}};
    if (!r.motion.empty()) {
        deposit.rows.push_back({"final front x", html::value(r.motion.back().front_x, "m")});
    }
    sections.push_back({"deposit", "Deposit", html::table(deposit)});
    sections.push_back(
        scenario_appendix(r.run, "saved as a file, `rockfall soil FILE` runs it again"));
    return sections;
}

void write_document(std::ostream& out, const HtmlReportOptions& options, const std::string& title,
                    const std::vector<Section>& sections,
                    const std::vector<std::pair<std::string, std::string>>& left_out) {
    html::write_head(out, title, options.generator);
    out << "<p class=\"subtitle\">" << html::escaped(options.database) << "</p>\n";
    html::write_contents(out, sections, left_out);
    for (const Section& s : sections) html::write_section(out, s);
    html::write_tail(out, "Written by " + options.generator + " from " + options.database +
                              "; every value is read from the database or computed from it.");
}

}  // namespace

namespace html {

std::string proportion_interval_text(const SweepContext& c) {
    return confidence_text(c.options.confidence) + " % " +
           std::string(db::display_name(c.options.method));
}

std::string percentile_interval_text(const SweepContext& c) {
    return confidence_text(c.options.confidence) +
           " % distribution-free interval from order statistics, Conover 1999";
}

}  // namespace html

void validate(const HtmlReportOptions& o) {
    const auto fail = [](const std::string& what) { throw std::invalid_argument(what); };
    if (!(o.confidence > 0.0 && o.confidence < 1.0)) {
        fail(fmt("--confidence = %g: must be in (0, 1)", o.confidence));
    }
    if (o.distance && !std::isfinite(*o.distance)) fail("--distance: must be a finite number of m");
    if (o.curve_points < 2 || o.curve_points > 10000) {
        fail("--points = " + std::to_string(o.curve_points) + ": must be in [2, 10000]");
    }
    if (!(std::isfinite(o.min_velocity) && o.min_velocity >= 0.0)) {
        fail(fmt("--min-velocity = %g m/s: must be finite and >= 0", o.min_velocity));
    }
    if (o.worst < 1) fail("--worst = " + std::to_string(o.worst) + ": must be >= 1");
    if (!(o.design_percentile > 0.0 && o.design_percentile < 1.0)) {
        fail(fmt("--percentile = %g %%: must be in (0, 100)", 100.0 * o.design_percentile));
    }
    if (o.design_mass && !(std::isfinite(*o.design_mass) && *o.design_mass > 0.0)) {
        fail(fmt("--design-mass = %g kg: must be finite and > 0", *o.design_mass));
    }
    if (o.formula.name == "jra" && !o.formula.lambda) {
        fail(
            "--formula jra needs --lambda (Pa), the Lame constant of the wall; seed 000 "
            "identified 5e8 Pa for concrete");
    }
    // The formula's own checks (names, coefficients) before any work.
    for (const risk::ImpactShape shape : risk::all_impact_shapes) {
        risk::envelope_coefficients(o.formula, shape);
    }
    // The factors' checks are uni_design_values' own: run them on a one-value sample.
    risk::uni_design_values({1.0}, {1.0}, 1.0, o.design_percentile, o.factors);
}

void write_html_report(std::ostream& out, const db::ResultsDb& db,
                       const HtmlReportOptions& options) {
    validate(options);
    if (db.kind() == db::RunKind::soil_flow) {
        const db::SoilRunRecord record = db::read_soil_run(db);
        write_document(out, options, "Soil flow report: " + record.run.scenario_name,
                       soil_sections(record, options.database),
                       {{"rock sweep sections", "the database holds one soil flow"}});
        return;
    }
    if (db.kind() != db::RunKind::rock_sweep) {
        // A calibration run: refused as a rock sweep's readers refuse it, naming what it holds.
        db::ResultsDb::open(db.path(), false);
    }
    SweepContext c{db,
                   options,
                   db::summarize(db, options.confidence),
                   html::confidence_text(options.confidence),
                   0,
                   {}};
    const db::Summary& s = c.summary;
    const Items counts = {
        {"samples done / planned",
         std::to_string(s.samples) + " of " + std::to_string(s.run.samples_planned) +
             (s.rocks != s.samples ? " (" + count_text(s.rocks, "rocks") + ")" : "")},
        {"stop reasons", [&] {
             std::string text;
             for (const auto& [reason, count] : s.stop_reasons) {
                 text += (text.empty() ? "" : ", ") + reason + " " + std::to_string(count);
             }
             return text.empty() ? std::string("-") : text + " rocks";
         }()}};
    std::vector<Section> sections = {provenance(s.run, counts, options.database)};
    const std::vector<db::StoredOutcome> outcomes = db::stored_outcomes(db);
    const double distance = convergence_distance(options, outcomes);
    for (std::optional<Section> section :
         {convergence(c, outcomes, distance), html::exceedance_section(c, distance),
          html::stations_section(c), html::wall_section(c), html::envelope_section(c),
          html::worst_section(c)}) {
        if (section) sections.push_back(std::move(*section));
    }
    sections.push_back(scenario_appendix(
        s.run, "`rockfall simulate --from DB --sample i` replays any sample from it"));
    c.left_out.emplace_back("pressure map of the wall's cells",
                            "a results database stores no wall-cell loads; `rockfall simulate` "
                            "draws the map of one run");
    write_document(out, options, "Rockfall sweep report: " + s.run.scenario_name, sections,
                   c.left_out);
}

}  // namespace rockfall::report
