// The stations section of a sweep's HTML report: passing shares, percentiles of speed, bounce
// height and energy at each station, UNI 11211-4 design values (see html_sections.hpp).

#include "html_sections.hpp"
#include "report/query_report.hpp"
#include "report/text_format.hpp"

#include "db/station_values.hpp"
#include "risk/design_values.hpp"

namespace rockfall::report::html {
namespace {

const std::vector<double> levels = {0.5, 0.9, 0.95, 0.99};

struct Measure {
    const char* name;
    const char* unit;
    const std::vector<double> db::StationValues::*values;
};

constexpr Measure measures[] = {{"speed", "m/s", &db::StationValues::speeds},
                                {"bounce height", "m", &db::StationValues::bounce_heights},
                                {"kinetic energy", "J", &db::StationValues::energies}};

std::string station_name(const db::StationValues& s) {
    return "station " + std::to_string(s.station) + " (" + fmt("%g", s.distance_from_toe) +
           " m past the toe)";
}

Table percentile_table(const SweepContext& c, const db::StationValues& s) {
    Table t{"Percentiles at " + station_name(s) + " over the " + std::to_string(s.reached) +
                " rocks that crossed it",
            {"percentile"},
            {}};
    std::vector<db::PercentileGroup> groups;
    for (const Measure& m : measures) {
        const std::vector<double>& values = s.*m.values;
        groups.push_back(
            db::percentiles_of({{"all"}, static_cast<std::int64_t>(values.size()), values}, levels,
                               c.options.confidence));
        t.header.push_back(std::string(m.name) + " (" + m.unit + ")");
        t.header.push_back(confidence_text(c.options.confidence) + " % CI (" + m.unit + ")");
    }
    for (std::size_t l = 0; l < levels.size(); ++l) {
        std::vector<std::string> row = {fmt("p%g", 100.0 * levels[l])};
        for (const db::PercentileGroup& g : groups) {
            if (g.rows.empty()) {
                row.insert(row.end(), {"-", "-"});
                continue;
            }
            const db::PercentileRow& r = g.rows[l];
            row.push_back(fmt("%.4g", r.value));
            row.push_back(value(r.lower, "") + " to " + value(r.upper, ""));
        }
        t.rows.push_back(std::move(row));
    }
    return t;
}

std::string factors_text(const HtmlReportOptions& o) {
    const risk::PartialFactors& f = o.factors;
    return fmt("gamma_Tr %.2f (trajectory simulation), ", f.trajectory) +
           fmt("gamma_Dp %.2f (slope survey), ", f.survey) +
           fmt("gamma_VolF1 %.2f (block volume survey), ", f.volume) +
           fmt("gamma_gamma %.2f (unit weight)", f.unit_weight);
}

Table design_table(const SweepContext& c, const std::vector<db::StationValues>& stations) {
    const HtmlReportOptions& o = c.options;
    const std::string p = fmt("%g", 100.0 * o.design_percentile);
    Table t{
        "UNI 11211-4 design values at each station",
        {"station", "rocks", "v_t = p" + p + " speed (m/s)", "h_t = p" + p + " bounce height (m)",
         "v_d (m/s)", "h_d (m)", "block mass m (kg)", "m_d (kg)", "E_d (kJ)"},
        {}};
    for (const db::StationValues& s : stations) {
        if (s.speeds.empty() || s.bounce_heights.empty()) continue;
        const double mass = o.design_mass ? *o.design_mass : s.max_mass;
        const risk::DesignValues d = risk::uni_design_values(s.speeds, s.bounce_heights, mass,
                                                             o.design_percentile, o.factors);
        t.rows.push_back({std::to_string(s.station), std::to_string(d.speed_count),
                          fmt("%.4g", d.characteristic_speed), fmt("%.4g", d.characteristic_height),
                          fmt("%.4g", d.design_speed), fmt("%.4g", d.design_height),
                          fmt("%.4g", mass), fmt("%.4g", d.design_mass),
                          fmt("%.4g", d.design_energy / 1.0e3)});
    }
    return t;
}

}  // namespace

std::optional<Section> stations_section(SweepContext& c) {
    const std::vector<db::StationValues> stations = db::read_station_values(c.db);
    if (stations.empty()) return c.leave_out("stations", "the scenario has no stations");
    // The summary's shares, as `rockfall query DB summary` prints them: Wilson intervals.
    Table shares{"Rocks past each station, " + c.confidence + " % Wilson score interval",
                 {"station", "distance past the toe (m)", "rocks past it"},
                 {}};
    for (const db::StationShare& s : c.summary.stations) {
        shares.rows.push_back({std::to_string(s.station), fmt("%g", s.distance_from_toe),
                               share_text(s.reached, c.confidence)});
    }
    std::string body = paragraph(
        "Values each rock had as it crossed a station (a vertical plane across the slope), over "
        "the rocks that crossed it; kinetic energy is translational plus rotational. "
        "Percentile intervals: " +
        percentile_interval_text(c) + "; '-' where the sample is too small for a bound.");
    body += table(shares);
    bool any = false;
    for (const db::StationValues& s : stations) {
        if (s.reached == 0) continue;
        any = true;
        body += table(percentile_table(c, s));
    }
    if (any) {
        const HtmlReportOptions& o = c.options;
        body += subheading("Design values in the manner of UNI 11211-4");
        body += paragraph(
            "v_d = v_t gamma_Tr gamma_Dp, h_d = h_t gamma_Tr gamma_Dp, m_d = m gamma_VolF1 "
            "gamma_gamma, E_d = m_d v_d^2 / 2, with v_t and h_t the " +
            fmt("%g", 100.0 * o.design_percentile) +
            "th percentile (type 7) of the speeds and bounce heights at the station, and " +
            factors_text(o) + ". Block mass m: " +
            (o.design_mass ? "given (--design-mass)"
                           : std::string("the largest rock that crossed the station; give the "
                                         "design block's with --design-mass")) +
            ". The resistance side (the barrier's energy class over gamma_E, its height "
            "minus the free margin) is the designer's.");
        body += table(design_table(c, stations));
    }
    return Section{"stations", "Stations", body};
}

}  // namespace rockfall::report::html
