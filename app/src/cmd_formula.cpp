// `rockfall formula NAME`: one impact design formula evaluated, with every input echoed in SI.

#include "commands.hpp"
#include "report/formula_report.hpp"
#include "scenario/impact_csv.hpp"

#include "risk/design_values.hpp"

#include <nlohmann/json.hpp>

#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rockfall::app {
namespace {

struct FormulaArgs {
    report::FormulaInputs inputs;
    std::optional<std::string> sample;
    bool json = false;
};

// The options that only some formulas read; any other formula rejects them.
const std::map<std::string, std::set<std::string>>& option_owners() {
    static const std::map<std::string, std::set<std::string>> owners = {
        {"--velocity", {"jra", "seed", "labiouse", "astra"}},
        {"--height", {"jra", "seed", "labiouse", "astra"}},
        {"--alpha", {"jra", "seed"}},
        {"--beta", {"jra", "seed"}},
        {"--lambda", {"jra", "seed"}},
        {"--shape", {"seed"}},
        {"--radius", {"labiouse", "astra"}},
        {"--density", {"labiouse", "astra"}},
        {"--modulus", {"labiouse", "astra"}},
        {"--thickness", {"astra"}},
        {"--friction-angle", {"astra"}},
        {"--sample", {"uni"}},
        {"--percentile", {"uni"}},
        {"--gamma-tr", {"uni"}},
        {"--gamma-dp", {"uni"}},
        {"--gamma-vol", {"uni"}},
        {"--gamma-unit-weight", {"uni"}}};
    return owners;
}

void reject_foreign_options(const CLI::App& cmd, const std::string& formula) {
    for (const auto& [option, formulas] : option_owners()) {
        if (cmd.count(option) == 0 || formulas.count(formula) != 0) continue;
        std::string owners;
        for (const std::string& f : formulas) owners += (owners.empty() ? "" : ", ") + f;
        throw std::invalid_argument(option + " does not apply to the " + formula +
                                    " formula (it is for: " + owners + ")");
    }
}

// uni's sample file, which must be given.
risk::DesignSample read_sample(const std::optional<std::string>& path) {
    if (!path) {
        throw std::invalid_argument(
            "give --sample FILE.csv with columns velocity_m_s and bounce_height_m");
    }
    return scenario::read_design_sample(*path);
}

void add_partial_factors(CLI::App* cmd, risk::PartialFactors& f) {
    cmd->add_option("--gamma-tr", f.trajectory,
                    "uni: gamma_Tr, trajectory simulation (1.02 back-analysed, 1.10 literature)")
        ->capture_default_str();
    cmd->add_option("--gamma-dp", f.survey,
                    "uni: gamma_Dp, slope survey (1.02 high quality, 1.10 low)")
        ->capture_default_str();
    cmd->add_option("--gamma-vol", f.volume,
                    "uni: gamma_VolF1, block volume survey (1.02 precise, 1.10 not)")
        ->capture_default_str();
    cmd->add_option("--gamma-unit-weight", f.unit_weight, "uni: gamma_gamma, rock unit weight")
        ->capture_default_str();
}

}  // namespace

void register_formula(CLI::App& app) {
    auto args = std::make_shared<FormulaArgs>();
    CLI::App* cmd = app.add_subcommand(
        "formula",
        "Impact design formulas: jra (Japan Road Association 2000), seed (seed 000's alpha beta "
        "proposal), labiouse (Labiouse et al. 1996 cushion), astra (ASTRA 2008 gallery), uni "
        "(UNI 11211-4 design values from a sample)");
    cmd->add_option("name", args->inputs.name, "Formula: jra, seed, labiouse, astra or uni")
        ->required()
        ->check(CLI::IsMember({"jra", "seed", "labiouse", "astra", "uni"}));
    cmd->add_option("--mass", args->inputs.mass, "Rock mass (kg); for uni the design block's")
        ->required();
    CLI::Option* velocity =
        cmd->add_option("--velocity", args->inputs.velocity, "Impact velocity (m/s)");
    cmd->add_option("--height", args->inputs.height, "Equivalent fall height H = v^2 / 2g (m)")
        ->excludes(velocity);
    CLI::Option* shape = cmd->add_option("--shape", args->inputs.shape,
                                         "seed preset: sphere (default), massive or planar");
    cmd->add_option("--alpha", args->inputs.alpha, "Load scatter factor (replaces the preset's)")
        ->excludes(shape);
    cmd->add_option("--beta", args->inputs.beta, "Shape factor (replaces the preset's)")
        ->excludes(shape);
    cmd->add_option("--lambda", args->inputs.lambda,
                    "Lame constant of the hit material (Pa); seed default 5e8");
    cmd->add_option("--radius", args->inputs.radius, "labiouse, astra: rock radius (m)");
    cmd->add_option("--density", args->inputs.density,
                    "labiouse, astra: rock density (kg/m3), for the radius of its volume's sphere");
    cmd->add_option("--modulus", args->inputs.modulus,
                    "labiouse, astra: plate-load modulus M_E of the cushion (Pa)");
    cmd->add_option("--thickness", args->inputs.thickness, "astra: cushion thickness (m)");
    cmd->add_option("--friction-angle", args->inputs.friction_angle,
                    "astra: friction angle of the cushion material (deg)");
    cmd->add_option("--sample", args->sample,
                    "uni: CSV with columns velocity_m_s and bounce_height_m (one row per rock)");
    cmd->add_option("--percentile", args->inputs.percentile,
                    "uni: characteristic percentile of speed and height (%)")
        ->capture_default_str();
    add_partial_factors(cmd, args->inputs.factors);
    cmd->add_flag("--json", args->json, "Print one JSON document instead of the summary");
    cmd->callback([args, cmd] {
        reject_foreign_options(*cmd, args->inputs.name);
        const report::FormulaReport report =
            args->inputs.name == "uni"
                ? report::evaluate_design_values(args->inputs, read_sample(args->sample))
                : report::evaluate_formula(args->inputs);
        if (args->json) {
            std::cout << report.json.dump(2) << '\n';
            return;
        }
        report::print_formula_report(std::cout, report);
    });
}

}  // namespace rockfall::app
