// `rockfall fit CSV|DB`: seed 000's identification of the impact formula's coefficients from
// measured (CSV) or simulated (results database) impacts, per shape, with the fit's quality,
// range and a figure.

#include "commands.hpp"
#include "impact_source.hpp"
#include "output_file.hpp"
#include "report/fit_figure.hpp"
#include "report/fit_report.hpp"

#include "risk/impact_identification.hpp"

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
    ImpactFilter filter;
    std::optional<std::string> svg;
    bool json = false;
};

void run(const FitArgs& args) {
    report::FitView view;
    view.impacts.input = args.input;
    view.impacts.velocity = report::parse_hit_velocity(args.velocity.value_or("normal"));
    report::ImpactData data = load_impacts(args.input, view.impacts.velocity);
    apply_impact_filter(data, args.filter, view.impacts);
    if (args.velocity && !data.from_database) {
        throw std::invalid_argument("--velocity applies to a results database, not to " +
                                    args.input + " (a CSV file gives velocity_m_s)");
    }
    if (data.rows.empty()) {
        throw std::invalid_argument(args.input +
                                    ": no wall hits of a sphere, massive or planar "
                                    "rock to fit");
    }
    risk::IdentificationOptions options;
    options.shape = args.shape;
    options.lambda = args.lambda;
    options.form = risk::parse_regression_form(args.regression);
    options.reference_mass = args.mass;
    view.impacts.data = &data;
    view.regression = args.regression;
    view.identification = risk::identify_shapes(data.rows, options, args.input);
    view.svg = args.svg;
    if (args.svg) {
        const std::string name = std::filesystem::path(args.input).filename().string();
        write_svg(*args.svg, report::fit_figure(view.identification.fits,
                                                "Peak load against impact velocity: " + name));
    }
    if (args.json) {
        std::cout << report::fit_json(view).dump(2) << '\n';
        return;
    }
    report::print_fit_text(std::cout, view);
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
    add_impact_filter_options(*cmd, args->filter);
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
