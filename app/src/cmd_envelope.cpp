// `rockfall envelope DB`: every wall impact of a sweep against the design formula for that
// rock's mass, shape and impact velocity; the ratio's distribution, the share above the
// envelope with its interval, and the worst impacts with their seeds.

#include "commands.hpp"
#include "impact_source.hpp"
#include "report/text_format.hpp"

#include "risk/envelope.hpp"
#include "risk/formulas.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::app {
namespace {

struct EnvelopeArgs {
    std::string input;
    std::string formula = "seed";
    std::optional<double> lambda;
    std::optional<double> alpha;
    std::optional<double> beta;
    std::string velocity = "normal";
    double min_velocity = 0.0;
    int worst = 10;
    double confidence = 0.95;
    bool json = false;
};

constexpr double kilo = 1.0e3;

// One impact compared: the formula's load (N) and the ratio load / formula.
struct Compared {
    std::size_t row = 0;
    double formula = 0.0;
    double ratio = 0.0;
};

// seed: each shape's preset; jra: the handbook formula with the given lambda. Explicit
// values replace the preset's for every shape.
risk::ImpactCoefficients coefficients_for(const EnvelopeArgs& args, risk::ImpactShape shape) {
    risk::ImpactCoefficients c;
    if (args.formula == "jra") {
        if (!args.lambda) {
            throw std::invalid_argument(
                "--formula jra needs --lambda (Pa), the Lame constant of the wall; seed 000 "
                "identified 5e8 Pa for concrete");
        }
        c = risk::jra_coefficients(*args.lambda);
    } else {
        c = risk::seed_coefficients(shape);
    }
    if (args.lambda) c.lambda = *args.lambda;
    if (args.alpha) c.alpha = *args.alpha;
    if (args.beta) c.beta = *args.beta;
    return c;
}

std::vector<Compared> compare(const EnvelopeArgs& args, const ImpactData& data) {
    std::vector<Compared> out;
    for (std::size_t i = 0; i < data.rows.size(); ++i) {
        const risk::ImpactRow& row = data.rows[i];
        const double formula =
            risk::jra_impact_force(row.mass, row.velocity, coefficients_for(args, row.shape));
        out.push_back({i, formula, row.peak_force / formula});
    }
    return out;
}

std::vector<double> ratios_of(const std::vector<Compared>& compared, const ImpactData& data,
                              std::optional<risk::ImpactShape> shape) {
    std::vector<double> ratios;
    for (const Compared& c : compared) {
        if (!shape || data.rows[c.row].shape == *shape) ratios.push_back(c.ratio);
    }
    return ratios;
}

std::string percent(double share) { return report::fmt("%.1f %%", 100.0 * share); }

std::string stats_text(const risk::EnvelopeStats& s) {
    return "n = " + std::to_string(s.count) + ", above " + std::to_string(s.above) + " (" +
           percent(s.share) + ", " + report::fmt("%.0f %% CI ", 100.0 * s.confidence) +
           percent(s.interval.lower) + " .. " + percent(s.interval.upper) + "); ratio min " +
           report::fmt("%.3g", s.min) + ", median " + report::fmt("%.3g", s.median) + ", mean " +
           report::fmt("%.3g", s.mean) + ", p95 " + report::fmt("%.3g", s.p95) + ", p99 " +
           report::fmt("%.3g", s.p99) + ", max " + report::fmt("%.3g", s.max);
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

// Indices into `compared` of the largest ratios, largest first.
std::vector<std::size_t> worst_of(const std::vector<Compared>& compared, int count) {
    std::vector<std::size_t> order(compared.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const std::size_t n = std::min(order.size(), static_cast<std::size_t>(count));
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n), order.end(),
                      [&](std::size_t a, std::size_t b) {
                          return compared[a].ratio > compared[b].ratio ||
                                 (compared[a].ratio == compared[b].ratio && a < b);
                      });
    order.resize(n);
    return order;
}

nlohmann::json worst_json(const Compared& c, const ImpactData& data) {
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
        j["hit"] = hit.hit;
        j["seed"] = hit.seed;
    } else {
        j["row"] = c.row + 1;
    }
    return j;
}

void print_worst(const std::vector<Compared>& compared, const ImpactData& data,
                 const std::vector<std::size_t>& worst) {
    std::cout << "\nworst impacts (largest load / formula):\n"
              << (data.from_database ? "  rank  sample  hit                  seed"
                                     : "  rank     row")
              << "  shape     mass_kg  v_m_s  peak_kN  formula_kN  ratio\n";
    for (std::size_t rank = 0; rank < worst.size(); ++rank) {
        const Compared& c = compared[worst[rank]];
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
        std::cout << line;
        std::snprintf(line, sizeof line, "  %-8s %8.4g %6.3g %8.4g %11.4g %6.3f",
                      std::string(risk::to_string(row.shape)).c_str(), row.mass, row.velocity,
                      row.peak_force / kilo, c.formula / kilo, c.ratio);
        std::cout << line << '\n';
    }
}

std::string formula_text(const EnvelopeArgs& args) {
    std::string text;
    for (const risk::ImpactShape shape : risk::all_impact_shapes) {
        const risk::ImpactCoefficients c = coefficients_for(args, shape);
        text += std::string(text.empty() ? "" : "; ") + std::string(risk::to_string(shape)) +
                report::fmt(" alpha %.3g", c.alpha) + report::fmt(" beta %.3g", c.beta) +
                report::fmt(" lambda %.4g Pa", c.lambda);
    }
    return args.formula + " (" + text + ")";
}

void run(const EnvelopeArgs& args) {
    if (!(args.confidence > 0.0 && args.confidence < 1.0)) {
        throw std::invalid_argument(
            report::fmt("--confidence = %g: must be in (0, 1)", args.confidence));
    }
    if (args.worst < 0) throw std::invalid_argument("--worst must be >= 0");
    const HitVelocity velocity = parse_hit_velocity(args.velocity);
    ImpactData data = load_impacts(args.input, velocity);
    drop_slow(data, args.min_velocity);
    if (data.rows.empty()) {
        throw std::invalid_argument(args.input +
                                    ": no wall hits of a sphere, massive or planar rock to "
                                    "compare");
    }
    const std::vector<Compared> compared = compare(args, data);
    const risk::EnvelopeStats all =
        risk::envelope_stats(ratios_of(compared, data, std::nullopt), args.confidence);
    const std::vector<std::size_t> worst = worst_of(compared, args.worst);

    if (args.json) {
        nlohmann::json shapes = nlohmann::json::object();
        nlohmann::json worst_list = nlohmann::json::array();
        for (const risk::ImpactShape shape : risk::all_impact_shapes) {
            const std::vector<double> ratios = ratios_of(compared, data, shape);
            if (!ratios.empty()) {
                shapes[std::string(risk::to_string(shape))] =
                    stats_json(risk::envelope_stats(ratios, args.confidence));
            }
        }
        for (const std::size_t i : worst) worst_list.push_back(worst_json(compared[i], data));
        std::cout << nlohmann::json{{"input", args.input},
                                    {"source", data.from_database ? "database" : "csv"},
                                    {"velocity", args.velocity},
                                    {"formula", args.formula},
                                    {"skipped", data.skipped},
                                    {"slow", data.slow},
                                    {"min_velocity_m_s", args.min_velocity},
                                    {"confidence", args.confidence},
                                    {"all", stats_json(all)},
                                    {"by_shape", shapes},
                                    {"worst", worst_list}}
                         .dump(2)
                  << '\n';
        return;
    }
    std::cout << "impacts: " << describe(data, args.input, velocity)
              << "\nformula: " << formula_text(args)
              << "\nratio = peak load / formula for the rock's mass, shape and velocity\n"
              << "all: " << stats_text(all) << '\n';
    for (const risk::ImpactShape shape : risk::all_impact_shapes) {
        const std::vector<double> ratios = ratios_of(compared, data, shape);
        if (ratios.empty()) continue;
        std::cout << risk::to_string(shape) << ": "
                  << stats_text(risk::envelope_stats(ratios, args.confidence)) << '\n';
    }
    if (!worst.empty()) print_worst(compared, data, worst);
}

}  // namespace

void register_envelope(CLI::App& app) {
    auto args = std::make_shared<EnvelopeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "envelope",
        "Compare every wall impact of a sweep with the design formula for its rock: ratio "
        "load / formula, share above the envelope with its interval, worst impacts");
    cmd->add_option("input", args->input,
                    "Results database of a sweep (or a CSV of impacts, as for fit)")
        ->required();
    cmd->add_option("--formula", args->formula,
                    "seed (seed 000's preset per shape) or jra (handbook, needs --lambda)")
        ->capture_default_str()
        ->check(CLI::IsMember({"seed", "jra"}));
    cmd->add_option("--lambda", args->lambda, "Lame constant of the wall (Pa); seed: 5e8");
    cmd->add_option("--alpha", args->alpha, "Load scatter factor for every shape");
    cmd->add_option("--beta", args->beta, "Shape factor for every shape");
    cmd->add_option("--velocity", args->velocity,
                    "Hit velocity the formula gets: normal (to the wall) or total")
        ->capture_default_str()
        ->check(CLI::IsMember({"normal", "total"}));
    cmd->add_option("--min-velocity", args->min_velocity,
                    "Leave out impacts slower than this (m/s): resting or pushing contacts")
        ->capture_default_str();
    cmd->add_option("--worst", args->worst, "Number of worst impacts listed")
        ->capture_default_str();
    cmd->add_option("--confidence", args->confidence, "Confidence of the intervals, in (0, 1)")
        ->capture_default_str();
    cmd->add_flag("--json", args->json, "Print one JSON document instead of the summary");
    cmd->callback([args] { run(*args); });
}

}  // namespace rockfall::app
