// The sections of a sweep's HTML report on reach, wall impacts, the envelope and the worst
// samples (see html_sections.hpp).

#include "html_sections.hpp"
#include "report/curve_figure.hpp"
#include "report/fit_figure.hpp"
#include "report/query_report.hpp"
#include "report/text_format.hpp"

#include "db/wall_impacts.hpp"
#include "risk/envelope.hpp"

#include <cctype>
#include <cmath>
#include <string_view>

namespace rockfall::report::html {
namespace {

const std::vector<double> levels = {0.5, 0.9, 0.95, 0.99};

std::string level_text(double p) { return fmt("p%g", 100.0 * p); }

// A quantity's name in words: "peak_force" -> "peak force".
std::string words(std::string_view name) {
    std::string text(name);
    for (char& ch : text) ch = ch == '_' ? ' ' : ch;
    return text;
}

bool has_points(const db::ExceedanceCurve& curve) {
    for (const db::CurveGroup& g : curve.groups) {
        if (!g.points.empty()) return true;
    }
    return false;
}

// The database path as one shell word: quoted unless it is plain.
std::string shell_word(const std::string& text) {
    bool plain = !text.empty();
    for (const char ch : text) {
        plain = plain && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '/' || ch == '.' ||
                          ch == '_' || ch == '-' || ch == '+');
    }
    if (plain) return text;
    std::string quoted = "'";
    for (const char ch : text) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return quoted + "'";
}

}  // namespace

std::optional<Section> exceedance_section(SweepContext& c, double distance) {
    if (c.summary.reach.groups.empty() || c.summary.reach.groups[0].n == 0) {
        return c.leave_out("reach exceedance", "no reach stored");
    }
    const HtmlReportOptions& o = c.options;
    const std::string x = value(distance, "m");
    const db::PercentileRow& median = c.summary.reach.groups[0].rows[0];
    std::string body = paragraph(
        "P(reach >= x): the share of rocks whose furthest horizontal distance past the toe is at "
        "least x, with the " +
        proportion_interval_text(c) + " (dashed). Median reach over all rocks " +
        value(median.value, "m") + ", " + percentile_interval_text(c) + " " +
        value(median.lower, "m") + " to " + value(median.upper, "m") +
        " ('-': too few rocks for a bound); largest " + value(c.summary.max_reach, "m") + ".");
    for (const db::GroupBy by : {db::GroupBy::shape, db::GroupBy::zone}) {
        const std::string name(db::to_string(by));
        const db::Grouping grouping{by, {}, db::Per::rock};
        const db::ExceedanceCurve curve = db::exceedance_curve(
            c.db, db::Quantity::reach, o.curve_points, grouping, o.method, o.confidence);
        if (!has_points(curve)) continue;
        body += subheading("By " + name);
        body += figure(
            curve_figure(curve, "Reach exceedance by " + name + ": " + c.summary.run.scenario_name),
            c.next_figure(),
            "Reach exceedance curves by " + name + ", one line per " + name + " with its " +
                proportion_interval_text(c) + " (dashed).");
        const db::ExceedanceTable at =
            db::exceedance(c.db, db::Quantity::reach, distance, grouping, o.method, o.confidence);
        Table t{"P(reach >= " + x + ") by " + name + ", " + proportion_interval_text(c),
                {name, "rocks", "reaching " + x, "probability", "interval"},
                {}};
        for (const db::ExceedanceGroup& g : at.groups) {
            t.rows.push_back(
                {g.id.label, std::to_string(g.trials), std::to_string(g.exceeding),
                 fmt("%.4g", g.probability),
                 fmt("%.4g", g.interval.lower) + " to " + fmt("%.4g", g.interval.upper)});
        }
        body += table(t);
    }
    return Section{"reach", "Reach exceedance", body};
}

std::optional<Section> wall_section(SweepContext& c) {
    const db::Summary& s = c.summary;
    if (s.wall.count == 0) return c.leave_out("wall impacts", "no rock hit the wall");
    std::string body = paragraph(
        "Rocks that hit the wall: " + share_text(s.wall, c.confidence) + " (" +
        proportion_interval_text(c) + ", of all rocks); samples with a rock on the wall: " +
        share_text(s.wall_samples, c.confidence) + "; " + std::to_string(s.wall_impacts) +
        " impacts in all. Percentiles over the rocks that hit the wall, each rock's largest "
        "value over its hits, with the " +
        percentile_interval_text(c) + "; '-' where the sample is too small for a bound.");
    const db::Quantity quantities[] = {db::Quantity::impact_energy, db::Quantity::impulse,
                                       db::Quantity::peak_force};
    Table t{"Wall loads over the rocks that hit the wall", {"percentile"}, {}};
    std::vector<db::PercentileTable> tables;
    for (const db::Quantity q : quantities) {
        tables.push_back(db::percentiles(c.db, q, levels, {}, c.options.confidence));
        const std::string unit(db::unit_of(q));
        t.header.push_back(words(db::to_string(q)) + " (" + unit + ")");
        t.header.push_back(confidence_text(c.options.confidence) + " % CI (" + unit + ")");
    }
    for (std::size_t l = 0; l < levels.size(); ++l) {
        std::vector<std::string> row = {level_text(levels[l])};
        for (const db::PercentileTable& table : tables) {
            const db::PercentileRow& r = table.groups.at(0).rows.at(l);
            row.push_back(fmt("%.4g", r.value));
            row.push_back(value(r.lower, "") + " to " + value(r.upper, ""));
        }
        t.rows.push_back(std::move(row));
    }
    body += table(t);
    return Section{"wall", "Wall impacts", body};
}

std::optional<Section> envelope_section(SweepContext& c) {
    if (c.summary.wall_impacts == 0) return c.leave_out("envelope comparison", "no wall impacts");
    const HtmlReportOptions& o = c.options;
    ImpactData data = database_rows(db::read_wall_impacts(c.db), o.velocity);
    drop_slow(data, o.min_velocity);
    if (data.rows.empty()) {
        return c.leave_out("envelope comparison",
                           "no wall hit of a sphere, massive or planar rock to compare");
    }
    const std::vector<risk::ComparedImpact> compared =
        risk::compare_with_formula(data.rows, o.formula);
    const risk::EnvelopeStats all =
        risk::envelope_stats(risk::ratios_of(compared, data.rows, std::nullopt), o.confidence);
    std::string body = paragraph(
        "Every wall impact against the design formula P = alpha beta 2.108 (m g)^(2/3) "
        "lambda^(2/5) H^(3/5), H = v^2 / 2g (" +
        std::string(o.formula.name == "seed" ? "seed 000's preset per shape"
                                             : "the handbook formula, alpha = beta = 1") +
        "), evaluated for the rock's mass, shape and " + to_string(o.velocity) +
        " impact velocity; ratio = peak load / formula. Impacts: " +
        describe(data, o.database, o.velocity) + ".");
    body += paragraph("Above the envelope (ratio > 1): " + std::to_string(all.above) + " of " +
                      std::to_string(all.count) + " impacts, " + fmt("%.3g %%", 100.0 * all.share) +
                      " (" + confidence_text(all.confidence) + " % Wilson score interval " +
                      fmt("%.3g", 100.0 * all.interval.lower) + " to " +
                      fmt("%.3g %%", 100.0 * all.interval.upper) + ").");
    Table t{"Ratio peak load / formula by shape",
            {"shape", "alpha", "beta", "lambda (Pa)", "impacts", "above", "share above (%)",
             confidence_text(all.confidence) + " % Wilson interval (%)", "median", "p95", "max"},
            {}};
    const auto add = [&](const std::string& label, const risk::EnvelopeStats& st,
                         const risk::ImpactCoefficients* k) {
        t.rows.push_back({label, k ? fmt("%.3g", k->alpha) : "", k ? fmt("%.3g", k->beta) : "",
                          k ? fmt("%.4g", k->lambda) : "", std::to_string(st.count),
                          std::to_string(st.above), fmt("%.3g", 100.0 * st.share),
                          fmt("%.3g", 100.0 * st.interval.lower) + " to " +
                              fmt("%.3g", 100.0 * st.interval.upper),
                          fmt("%.3g", st.median), fmt("%.3g", st.p95), fmt("%.3g", st.max)});
    };
    for (const risk::ImpactShape shape : risk::all_impact_shapes) {
        const std::vector<double> ratios = risk::ratios_of(compared, data.rows, shape);
        if (ratios.empty()) continue;
        const risk::ImpactCoefficients k = risk::envelope_coefficients(o.formula, shape);
        add(std::string(risk::to_string(shape)), risk::envelope_stats(ratios, o.confidence), &k);
    }
    add("all", all, nullptr);
    body += table(t);
    body += figure(envelope_figure(data, compared, o.formula,
                                   "Wall impacts and the " + o.formula.name + " envelope"),
                   c.next_figure(),
                   "Peak load against impact velocity in the manner of seed 000's Figure 7: "
                   "each impact scaled to its shape's median mass by the formula's m^(2/3), "
                   "and the formula at that mass (solid), so that a point above its curve has "
                   "a ratio above 1.");
    return Section{"envelope", "Envelope comparison", body};
}

std::optional<Section> worst_section(SweepContext& c) {
    if (c.summary.samples == 0) return c.leave_out("worst samples", "no samples stored");
    std::string body = paragraph(
        "The rocks with the largest reach and, when rocks hit the wall, the largest peak force "
        "(`rockfall query " +
        c.options.database +
        " worst`), each with the command below its table that replays it alone, bit for bit. "
        "Wall columns are each rock's largest over its hits; '-' without a hit.");
    const std::string db_word = shell_word(c.options.database);
    for (const db::Quantity by : {db::Quantity::reach, db::Quantity::peak_force}) {
        if (by == db::Quantity::peak_force && c.summary.wall.count == 0) continue;
        const std::string name = words(db::to_string(by));
        Table t{"Worst by " + name + " (" + std::string(db::unit_of(by)) + ")",
                {"rank", "sample", "rock", "kind", "size (m)", "mass (kg)", "zone", "reach (m)",
                 "max speed (m/s)", "wall hits", "peak force (N)", "impact energy (J)"},
                {}};
        std::string commands;
        std::int64_t rank = 0;
        for (const db::WorstSample& w : db::worst_samples(c.db, by, c.options.worst)) {
            t.rows.push_back({std::to_string(++rank), std::to_string(w.sample),
                              std::to_string(w.rock), w.kind, fmt("%.4g", w.size),
                              fmt("%.4g", w.mass), w.zone, fmt("%.4g", w.reach),
                              fmt("%.4g", w.max_speed), std::to_string(w.wall_hits),
                              value(w.peak_force, ""), value(w.impact_energy, "")});
            commands += "# " + std::to_string(rank) + ": sample " + std::to_string(w.sample) +
                        ", engine seed " + std::to_string(w.seed) + "\nrockfall simulate --from " +
                        db_word + " --sample " + std::to_string(w.sample) + "\n";
        }
        body += table(t) + preformatted(commands, "commands");
    }
    return Section{"worst", "Worst samples", body};
}

}  // namespace rockfall::report::html
