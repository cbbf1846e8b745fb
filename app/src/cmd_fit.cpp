// `rockfall fit CSV|DB`: seed 000's identification of the impact formula's coefficients from
// measured (CSV) or simulated (results database) impacts, per shape, with the fit's quality,
// range and a figure.

#include "atomic_file.hpp"
#include "commands.hpp"
#include "impact_source.hpp"
#include "report/fit_figure.hpp"
#include "report/text_format.hpp"

#include "risk/formulas.hpp"
#include "risk/impact_fit.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::app {
namespace {

struct FitArgs {
    std::string input;
    std::optional<std::string> shape;
    std::optional<double> lambda;
    std::string regression = "power";
    std::optional<double> mass;
    std::optional<std::string> velocity;
    double min_velocity = 0.0;
    std::optional<std::string> svg;
    bool json = false;
};

constexpr double kilo = 1.0e3;

// Where lambda comes from, as seed 000 did it: identified on the spheres, then held fixed
// while beta is identified for the other shapes.
enum class LambdaSource { identified, given, spheres };

struct Result {
    report::ShapeFit fit;
    LambdaSource lambda_source = LambdaSource::identified;
};

// Fewest rows a shape needs: the scatter has n - 2 degrees of freedom.
constexpr std::size_t min_rows = 3;

struct Identification {
    std::vector<Result> results;
    // Shapes present with fewer than min_rows rows, not fitted, with their row counts.
    std::vector<std::pair<risk::ImpactShape, std::size_t>> too_few;
};

std::vector<risk::ImpactRow> of_shape(const std::vector<risk::ImpactRow>& rows,
                                      risk::ImpactShape shape) {
    std::vector<risk::ImpactRow> out;
    std::copy_if(rows.begin(), rows.end(), std::back_inserter(out),
                 [&](const risk::ImpactRow& r) { return r.shape == shape; });
    return out;
}

std::string shape_counts(const std::vector<risk::ImpactRow>& rows) {
    std::string out;
    for (const risk::ImpactShape shape : risk::all_impact_shapes) {
        const std::size_t n = of_shape(rows, shape).size();
        if (n > 0) {
            out += (out.empty() ? "" : ", ") + std::string(risk::to_string(shape)) + ' ' +
                   std::to_string(n);
        }
    }
    return out;
}

// Every shape with enough rows, or only --shape; shapes with too few rows are listed.
Identification identify(const FitArgs& args, const std::vector<risk::ImpactRow>& rows) {
    risk::FitOptions base;
    base.form = risk::parse_regression_form(args.regression);
    base.reference_mass = args.mass;

    Identification out;
    std::vector<risk::ImpactShape> shapes;
    for (const risk::ImpactShape shape : risk::all_impact_shapes) {
        const std::size_t n = of_shape(rows, shape).size();
        if (n >= min_rows) {
            shapes.push_back(shape);
        } else if (n > 0) {
            out.too_few.emplace_back(shape, n);
        }
    }
    if (args.shape) {
        const risk::ImpactShape wanted = risk::parse_impact_shape(*args.shape);
        const std::size_t n = of_shape(rows, wanted).size();
        if (n < min_rows) {
            throw std::invalid_argument(args.input + " has " + std::to_string(n) +
                                        " rows of shape " + *args.shape + ": a fit needs " +
                                        std::to_string(min_rows) +
                                        " (it has: " + shape_counts(rows) + ")");
        }
        shapes = {wanted};
        out.too_few.clear();
    }
    if (shapes.empty()) {
        throw std::invalid_argument(args.input + ": no shape has the " + std::to_string(min_rows) +
                                    " rows a fit needs (it has: " + shape_counts(rows) + ")");
    }

    std::optional<double> sphere_lambda;
    const std::vector<risk::ImpactRow> spheres = of_shape(rows, risk::ImpactShape::sphere);
    if (!args.lambda && spheres.size() >= min_rows) {
        sphere_lambda = risk::fit_impacts(spheres, base).coefficients.lambda;
    }
    std::vector<Result>& results = out.results;
    for (const risk::ImpactShape shape : shapes) {
        Result result;
        risk::FitOptions options = base;
        if (args.lambda) {
            options.lambda = args.lambda;
            result.lambda_source = LambdaSource::given;
        } else if (sphere_lambda && shape != risk::ImpactShape::sphere) {
            options.lambda = sphere_lambda;
            result.lambda_source = LambdaSource::spheres;
        }
        result.fit.shape = shape;
        result.fit.rows = of_shape(rows, shape);
        result.fit.fit = risk::fit_impacts(result.fit.rows, options);
        results.push_back(std::move(result));
    }
    return out;
}

std::string too_few_text(const Identification& id) {
    std::string text;
    for (const auto& [shape, n] : id.too_few) {
        text += (text.empty() ? "" : ", ") + std::string(risk::to_string(shape)) + ' ' +
                std::to_string(n);
    }
    return text;
}

const char* lambda_text(LambdaSource source) {
    switch (source) {
        case LambdaSource::identified:
            return "identified on the mean line (beta = 1)";
        case LambdaSource::given:
            return "given (--lambda); beta identified on the mean line";
        case LambdaSource::spheres:
            return "identified on this file's spheres; beta identified on the mean line";
    }
    return "";
}

const char* lambda_key(LambdaSource source) {
    switch (source) {
        case LambdaSource::identified:
            return "identified";
        case LambdaSource::given:
            return "given";
        case LambdaSource::spheres:
            return "spheres";
    }
    return "";
}

std::string line_text(const risk::ImpactRegression& r) {
    if (r.form == risk::RegressionForm::power) {
        return report::fmt("P = %.4g", r.a / kilo) + report::fmt(" v^%.4g kN", r.b) +
               report::fmt(" (v in m/s); R^2 = %.3f on ln P", r.r_squared) +
               report::fmt("; sigma = %.3g (of ln P)", r.sigma);
    }
    return report::fmt("P = %.4g", r.a / kilo) + report::fmt(" + %.4g v kN", r.b / kilo) +
           report::fmt(" (v in m/s); R^2 = %.3f", r.r_squared) +
           report::fmt("; sigma = %.4g kN", r.sigma / kilo);
}

HitVelocity hit_velocity(const FitArgs& args) {
    return parse_hit_velocity(args.velocity.value_or("normal"));
}

void print_text(const FitArgs& args, const ImpactData& data, const Identification& id) {
    std::cout << "impacts: " << describe(data, args.input, hit_velocity(args)) << '\n'
              << "regression: " << args.regression
              << (args.regression == "power"
                      ? ", P = a v^b by least squares on ln P; sigma is the residual sd of ln P"
                      : ", P = a + b v by least squares; sigma is the residual sd of P")
              << '\n';
    for (const Result& result : id.results) {
        const risk::ImpactFit& f = result.fit.fit;
        const risk::ImpactCoefficients& c = f.coefficients;
        const risk::ImpactCoefficients preset = risk::seed_coefficients(result.fit.shape);
        std::cout << '\n'
                  << risk::to_string(result.fit.shape) << ": " << f.count << " rows\n"
                  << "  valid for: impact velocity " << report::fmt("%.4g", f.velocity_min)
                  << " .. " << report::fmt("%.4g m/s", f.velocity_max) << ", mass "
                  << report::fmt("%.4g", f.mass_min) << " .. " << report::fmt("%.4g kg", f.mass_max)
                  << report::fmt(" (regression at %.4g kg)", f.reference_mass) << '\n'
                  << "  mean line: " << line_text(f.regression) << '\n'
                  << "  lambda = " << report::fmt("%.4g Pa", c.lambda)
                  << report::fmt(" (%.4g MN/m2), ", c.lambda / 1e6)
                  << lambda_text(result.lambda_source) << '\n'
                  << "  beta = " << report::fmt("%.3g", c.beta) << '\n'
                  << "  alpha = " << report::fmt("%.3g", c.alpha)
                  << ", identified on the mean + 1 sigma line\n"
                  << "  formula vs lines at the data: mean within "
                  << report::fmt("%.1f %%", 100.0 * f.mean_mismatch) << ", mean + 1 sigma within "
                  << report::fmt("%.1f %%", 100.0 * f.upper_mismatch) << '\n'
                  << "  seed 000 preset: lambda " << report::fmt("%.4g Pa", preset.lambda)
                  << ", alpha " << report::fmt("%.3g", preset.alpha) << ", beta "
                  << report::fmt("%.3g", preset.beta) << '\n';
    }
    if (!id.too_few.empty()) {
        std::cout << "\nnot fitted, fewer than " << min_rows << " rows: " << too_few_text(id)
                  << '\n';
    }
    if (args.svg) std::cout << "\nfigure written to " << *args.svg << '\n';
}

nlohmann::json to_json(const FitArgs& args, const ImpactData& data, const Identification& id) {
    nlohmann::json fits = nlohmann::json::array();
    for (const Result& result : id.results) {
        const risk::ImpactFit& f = result.fit.fit;
        const risk::ImpactCoefficients preset = risk::seed_coefficients(result.fit.shape);
        const bool power = f.regression.form == risk::RegressionForm::power;
        fits.push_back(
            {{"shape", std::string(risk::to_string(result.fit.shape))},
             {"rows", f.count},
             {"velocity_min_m_s", f.velocity_min},
             {"velocity_max_m_s", f.velocity_max},
             {"mass_min_kg", f.mass_min},
             {"mass_max_kg", f.mass_max},
             {"reference_mass_kg", f.reference_mass},
             {"regression",
              {{"form", std::string(risk::to_string(f.regression.form))},
               {"a", f.regression.a},
               {"a_unit", power ? "N (s/m)^b" : "N"},
               {"b", f.regression.b},
               {"b_unit", power ? "1" : "N s/m"},
               {"sigma", f.regression.sigma},
               {"sigma_unit", power ? "1 (of ln P)" : "N"},
               {"r_squared", f.regression.r_squared}}},
             {"lambda_Pa", f.coefficients.lambda},
             {"lambda_source", lambda_key(result.lambda_source)},
             {"alpha", f.coefficients.alpha},
             {"beta", f.coefficients.beta},
             {"mean_mismatch", f.mean_mismatch},
             {"upper_mismatch", f.upper_mismatch},
             {"seed_preset",
              {{"lambda_Pa", preset.lambda}, {"alpha", preset.alpha}, {"beta", preset.beta}}}});
    }
    nlohmann::json not_fitted = nlohmann::json::object();
    for (const auto& [shape, n] : id.too_few) not_fitted[std::string(risk::to_string(shape))] = n;
    return {{"input", args.input},
            {"source", data.from_database ? "database" : "csv"},
            {"rows", data.rows.size()},
            {"skipped", data.skipped},
            {"slow", data.slow},
            {"min_velocity_m_s", args.min_velocity},
            {"not_fitted", not_fitted},
            {"velocity", data.from_database ? nlohmann::json(args.velocity.value_or("normal"))
                                            : nlohmann::json(nullptr)},
            {"regression", args.regression},
            {"fits", fits},
            {"svg", args.svg ? nlohmann::json(*args.svg) : nlohmann::json(nullptr)}};
}

void run(const FitArgs& args) {
    ImpactData data = load_impacts(args.input, hit_velocity(args));
    drop_slow(data, args.min_velocity);
    if (args.velocity && !data.from_database) {
        throw std::invalid_argument("--velocity applies to a results database, not to " +
                                    args.input + " (a CSV file gives velocity_m_s)");
    }
    if (data.rows.empty()) {
        throw std::invalid_argument(args.input +
                                    ": no wall hits of a sphere, massive or planar "
                                    "rock to fit");
    }
    const Identification id = identify(args, data.rows);
    if (args.svg) {
        std::vector<report::ShapeFit> fits;
        for (const Result& r : id.results) fits.push_back(r.fit);
        const std::string name = std::filesystem::path(args.input).filename().string();
        write_svg(*args.svg,
                  report::fit_figure(fits, "Peak load against impact velocity: " + name));
    }
    if (args.json) {
        std::cout << to_json(args, data, id).dump(2) << '\n';
        return;
    }
    print_text(args, data, id);
}

}  // namespace

void register_fit(CLI::App& app) {
    auto args = std::make_shared<FitArgs>();
    CLI::App* cmd = app.add_subcommand(
        "fit",
        "Identify the impact formula's lambda, beta and alpha from impacts (seed 000's "
        "procedure): regression of peak load on impact velocity, mean and mean + 1 sigma");
    cmd->add_option("input", args->input,
                    "Results database of a sweep, or a CSV with columns velocity_m_s, "
                    "peak_force_kN (or peak_force_N), mass_kg, shape")
        ->required();
    cmd->add_option("--velocity", args->velocity,
                    "Database: the hit velocity the formula gets, normal (to the wall, default) "
                    "or total")
        ->check(CLI::IsMember({"normal", "total"}));
    cmd->add_option("--min-velocity", args->min_velocity,
                    "Leave out impacts slower than this (m/s): resting or pushing contacts")
        ->capture_default_str();
    cmd->add_option("--shape", args->shape, "Fit only this shape: sphere, massive or planar");
    cmd->add_option("--lambda", args->lambda,
                    "Hold the Lame constant (Pa) fixed and identify beta; default: identified "
                    "on the file's spheres");
    cmd->add_option("--regression", args->regression, "Regression form: power or linear")
        ->capture_default_str()
        ->check(CLI::IsMember({"power", "linear"}));
    cmd->add_option("--mass", args->mass,
                    "Reference mass (kg) the loads are scaled to by m^(2/3); default: median");
    cmd->add_option("--svg", args->svg, "Write the figure (peak load against velocity) as SVG");
    cmd->add_flag("--json", args->json, "Print one JSON document instead of the summary");
    cmd->callback([args] { run(*args); });
}

}  // namespace rockfall::app
