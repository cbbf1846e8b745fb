// `rockfall envelope DB`: every wall impact of a sweep against the design formula for that
// rock's mass, shape and impact velocity; the ratio's distribution, the share above the
// envelope with its interval, and the worst impacts with their seeds.

#include "commands.hpp"
#include "impact_source.hpp"
#include "report/envelope_report.hpp"
#include "report/text_format.hpp"

#include "risk/envelope.hpp"

#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::app {
namespace {

struct EnvelopeArgs {
    std::string input;
    risk::EnvelopeFormula formula;
    std::string velocity = "normal";
    ImpactFilter filter;
    int worst = 10;
    double confidence = 0.95;
    bool json = false;
};

void run(const EnvelopeArgs& args) {
    if (!(args.confidence > 0.0 && args.confidence < 1.0)) {
        throw std::invalid_argument(
            report::fmt("--confidence = %g: must be in (0, 1)", args.confidence));
    }
    if (args.worst < 0) throw std::invalid_argument("--worst must be >= 0");
    if (args.formula.name == "jra" && !args.formula.lambda) {
        throw std::invalid_argument(
            "--formula jra needs --lambda (Pa), the Lame constant of the wall; seed 000 "
            "identified 5e8 Pa for concrete");
    }
    report::EnvelopeView view;
    view.impacts.input = args.input;
    view.impacts.velocity = report::parse_hit_velocity(args.velocity);
    report::ImpactData data = load_impacts(args.input, view.impacts.velocity);
    apply_impact_filter(data, args.filter, view.impacts);
    if (data.rows.empty()) {
        throw std::invalid_argument(args.input +
                                    ": no wall hits of a sphere, massive or planar rock to "
                                    "compare");
    }
    view.impacts.data = &data;
    view.formula = args.formula;
    view.compared = risk::compare_with_formula(data.rows, args.formula);
    view.confidence = args.confidence;
    view.worst = risk::worst_impacts(view.compared, static_cast<std::size_t>(args.worst));
    if (args.json) {
        std::cout << report::envelope_json(view).dump(2) << '\n';
        return;
    }
    report::print_envelope_text(std::cout, view);
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
    cmd->add_option("--formula", args->formula.name,
                    "seed (seed 000's preset per shape) or jra (handbook, needs --lambda)")
        ->capture_default_str()
        ->check(CLI::IsMember({"seed", "jra"}));
    cmd->add_option("--lambda", args->formula.lambda, "Lame constant of the wall (Pa); seed: 5e8");
    cmd->add_option("--alpha", args->formula.alpha, "Load scatter factor for every shape");
    cmd->add_option("--beta", args->formula.beta, "Shape factor for every shape");
    cmd->add_option("--velocity", args->velocity,
                    "Hit velocity the formula gets: normal (to the wall) or total")
        ->capture_default_str()
        ->check(CLI::IsMember({"normal", "total"}));
    add_impact_filter_options(*cmd, args->filter);
    cmd->add_option("--worst", args->worst, "Number of worst impacts listed")
        ->capture_default_str();
    cmd->add_option("--confidence", args->confidence, "Confidence of the intervals, in (0, 1)")
        ->capture_default_str();
    cmd->add_flag("--json", args->json, "Print one JSON document instead of the summary");
    cmd->callback([args] { run(*args); });
}

}  // namespace rockfall::app
