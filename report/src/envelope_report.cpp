// The text and JSON of a comparison with a design-formula envelope (see envelope_report.hpp).

#include "report/envelope_report.hpp"

#include "report/text_format.hpp"

#include <cstdio>
#include <optional>

namespace rockfall::report {
namespace {

constexpr double kilo = 1.0e3;

std::string percent(double share) { return fmt("%.1f %%", 100.0 * share); }

std::string stats_text(const risk::EnvelopeStats& s) {
    return "n = " + std::to_string(s.count) + ", above " + std::to_string(s.above) + " (" +
           percent(s.share) + ", " + fmt("%.0f %% CI ", 100.0 * s.confidence) +
           percent(s.interval.lower) + " .. " + percent(s.interval.upper) + "); ratio min " +
           fmt("%.3g", s.min) + ", median " + fmt("%.3g", s.median) + ", mean " +
           fmt("%.3g", s.mean) + ", p95 " + fmt("%.3g", s.p95) + ", p99 " + fmt("%.3g", s.p99) +
           ", max " + fmt("%.3g", s.max);
}

nlohmann::json stats_json(const risk::EnvelopeStats& s) {
    return {{"impacts", s.count},
            {"above", s.above},
            {"share_above", s.share},
            {"ci_lower", s.interval.lower},
            {"ci_upper", s.interval.upper},
            {"ratio_min", s.min},
            {"ratio_median", s.median},
            {"ratio_mean", s.mean},
            {"ratio_p95", s.p95},
            {"ratio_p99", s.p99},
            {"ratio_max", s.max}};
}

nlohmann::json worst_json(const risk::ComparedImpact& c, const ImpactData& data) {
    const risk::ImpactRow& row = data.rows[c.row];
    nlohmann::json j = {{"shape", std::string(risk::to_string(row.shape))},
                        {"mass_kg", row.mass},
                        {"velocity_m_s", row.velocity},
                        {"peak_force_N", row.peak_force},
                        {"formula_N", c.formula},
                        {"ratio", c.ratio}};
    if (data.from_database) {
        const db::WallImpact& hit = data.hits[c.row];
        j["sample"] = hit.sample;
        j["rock"] = hit.rock;
        j["hit"] = hit.hit;
        j["seed"] = hit.seed;
    } else {
        j["row"] = c.row + 1;
    }
    return j;
}

void print_worst(std::ostream& out, const std::vector<risk::ComparedImpact>& compared,
                 const ImpactData& data, const std::vector<std::size_t>& worst) {
    out << "\nworst impacts (largest load / formula):\n"
        << (data.from_database ? "  rank  sample  hit                  seed" : "  rank     row")
        << "  shape     mass_kg  v_m_s  peak_kN  formula_kN  ratio\n";
    for (std::size_t rank = 0; rank < worst.size(); ++rank) {
        const risk::ComparedImpact& c = compared[worst[rank]];
        const risk::ImpactRow& row = data.rows[c.row];
        char line[256];
        if (data.from_database) {
            const db::WallImpact& hit = data.hits[c.row];
            std::snprintf(line, sizeof line, "  %4zu  %6lld  %3lld  %20llu", rank + 1,
                          static_cast<long long>(hit.sample), static_cast<long long>(hit.hit),
                          static_cast<unsigned long long>(hit.seed));
        } else {
            std::snprintf(line, sizeof line, "  %4zu  %6zu", rank + 1, c.row + 1);
        }
        out << line;
        std::snprintf(line, sizeof line, "  %-8s %8.4g %6.3g %8.4g %11.4g %6.3f",
                      std::string(risk::to_string(row.shape)).c_str(), row.mass, row.velocity,
                      row.peak_force / kilo, c.formula / kilo, c.ratio);
        out << line << '\n';
    }
}

std::string formula_text(const risk::EnvelopeFormula& formula) {
    std::string text;
    for (const risk::ImpactShape shape : risk::all_impact_shapes) {
        const risk::ImpactCoefficients c = risk::envelope_coefficients(formula, shape);
        text += std::string(text.empty() ? "" : "; ") + std::string(risk::to_string(shape)) +
                fmt(" alpha %.3g", c.alpha) + fmt(" beta %.3g", c.beta) +
                fmt(" lambda %.4g Pa", c.lambda);
    }
    return formula.name + " (" + text + ")";
}

}  // namespace

void print_envelope_text(std::ostream& out, const EnvelopeView& view) {
    const ImpactData& data = *view.impacts.data;
    const risk::EnvelopeStats all = risk::envelope_stats(
        risk::ratios_of(view.compared, data.rows, std::nullopt), view.confidence);
    out << "impacts: " << describe(data, view.impacts.input, view.impacts.velocity)
        << "\nformula: " << formula_text(view.formula)
        << "\nratio = peak load / formula for the rock's mass, shape and velocity\n"
        << "all: " << stats_text(all) << '\n';
    for (const risk::ImpactShape shape : risk::all_impact_shapes) {
        const std::vector<double> ratios = risk::ratios_of(view.compared, data.rows, shape);
        if (ratios.empty()) continue;
        out << risk::to_string(shape) << ": "
            << stats_text(risk::envelope_stats(ratios, view.confidence)) << '\n';
    }
    if (!view.worst.empty()) print_worst(out, view.compared, data, view.worst);
}

nlohmann::json envelope_json(const EnvelopeView& view) {
    const ImpactData& data = *view.impacts.data;
    const risk::EnvelopeStats all = risk::envelope_stats(
        risk::ratios_of(view.compared, data.rows, std::nullopt), view.confidence);
    nlohmann::json shapes = nlohmann::json::object();
    nlohmann::json worst_list = nlohmann::json::array();
    for (const risk::ImpactShape shape : risk::all_impact_shapes) {
        const std::vector<double> ratios = risk::ratios_of(view.compared, data.rows, shape);
        if (!ratios.empty()) {
            shapes[std::string(risk::to_string(shape))] =
                stats_json(risk::envelope_stats(ratios, view.confidence));
        }
    }
    for (const std::size_t i : view.worst) worst_list.push_back(worst_json(view.compared[i], data));
    return {{"input", view.impacts.input},
            {"source", data.from_database ? "database" : "csv"},
            {"velocity", to_string(view.impacts.velocity)},
            {"formula", view.formula.name},
            {"skipped", data.skipped},
            {"slow", data.slow},
            {"min_velocity_m_s", view.impacts.min_velocity},
            {"later_hits", data.later},
            {"first_hits_only", view.impacts.first_hits},
            {"confidence", view.confidence},
            {"all", stats_json(all)},
            {"by_shape", shapes},
            {"worst", worst_list}};
}

}  // namespace rockfall::report
