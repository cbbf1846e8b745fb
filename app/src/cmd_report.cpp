// `rockfall report DB --html FILE`: one self-contained HTML report of a results database.

#include "commands.hpp"
#include "output_file.hpp"
#include "report/html_report.hpp"

#include "db/results_db.hpp"

#include <memory>
#include <sstream>
#include <string>

namespace rockfall::app {
namespace {

struct ReportArgs {
    std::string database;
    std::string html;
    std::string interval = "wilson";
    std::string velocity = "normal";
    double percentile = 95.0;
    report::HtmlReportOptions options;
};

void run(ReportArgs& args) {
    report::HtmlReportOptions& o = args.options;
    o.database = args.database;
    o.generator = std::string("rockfall ") + ROCKFALL_VERSION + " (" + ROCKFALL_BUILD + ")";
    o.method = db::parse_interval_method(args.interval);
    o.velocity = report::parse_hit_velocity(args.velocity);
    o.design_percentile = args.percentile / 100.0;
    report::validate(o);
    // Refuse a path that may not be written before the database is read.
    output_target(args.html);
    const db::ResultsDb database = db::ResultsDb::open_any(args.database, false);
    // The whole report in memory first: a failure while reading writes no file at all.
    std::ostringstream text;
    report::write_html_report(text, database, o);
    OutputFile file(args.html);
    file.stream() << text.str();
    file.commit();
}

}  // namespace

void register_report(CLI::App& app) {
    auto args = std::make_shared<ReportArgs>();
    report::HtmlReportOptions& o = args->options;
    CLI::App* cmd = app.add_subcommand(
        "report",
        "One self-contained HTML report of a results database (sweep or soil flow): "
        "provenance, convergence, reach, stations with UNI 11211-4 design values, wall loads, "
        "envelope, worst samples; printable to PDF");
    cmd->add_option("database", args->database,
                    "Results database (.db) of `rockfall sweep` or `rockfall soil --db`")
        ->required();
    cmd->add_option("--html", args->html, "HTML file to write (replaced whole)")->required();
    cmd->add_option("--confidence", o.confidence, "Confidence of every interval, in (0, 1)")
        ->capture_default_str();
    cmd->add_option("--interval", args->interval,
                    "Interval of the proportions (convergence, exceedance)")
        ->check(CLI::IsMember({"wilson", "clopper-pearson"}))
        ->capture_default_str();
    cmd->add_option("--distance", o.distance,
                    "Distance past the toe (m) of the convergence of P(reach >= x); default: "
                    "the 90th percentile of the reach, to two digits");
    cmd->add_option("--points", o.curve_points, "Thresholds of each exceedance curve")
        ->check(CLI::Range(2, 10000))
        ->capture_default_str();
    cmd->add_option("--worst", o.worst, "Rows of each worst-samples table")->capture_default_str();
    cmd->add_option("--formula", o.formula.name,
                    "Envelope: seed (seed 000's preset per shape) or jra (handbook, needs "
                    "--lambda)")
        ->capture_default_str()
        ->check(CLI::IsMember({"seed", "jra"}));
    cmd->add_option("--lambda", o.formula.lambda, "Envelope: Lame constant of the wall (Pa)");
    cmd->add_option("--alpha", o.formula.alpha, "Envelope: load scatter factor for every shape");
    cmd->add_option("--beta", o.formula.beta, "Envelope: shape factor for every shape");
    cmd->add_option("--velocity", args->velocity,
                    "Envelope: hit velocity the formula gets, normal (to the wall) or total")
        ->capture_default_str()
        ->check(CLI::IsMember({"normal", "total"}));
    cmd->add_option("--min-velocity", o.min_velocity,
                    "Envelope: leave out impacts slower than this (m/s)")
        ->capture_default_str();
    cmd->add_option("--percentile", args->percentile,
                    "UNI 11211-4: characteristic percentile of speed and height (%)")
        ->capture_default_str();
    cmd->add_option("--design-mass", o.design_mass,
                    "UNI 11211-4: design block mass (kg); default: the largest rock that "
                    "crossed each station");
    risk::PartialFactors& f = o.factors;
    cmd->add_option("--gamma-tr", f.trajectory,
                    "UNI 11211-4: gamma_Tr, trajectory simulation (1.02 back-analysed, 1.10 "
                    "literature)")
        ->capture_default_str();
    cmd->add_option("--gamma-dp", f.survey,
                    "UNI 11211-4: gamma_Dp, slope survey (1.02 high quality, 1.10 low)")
        ->capture_default_str();
    cmd->add_option("--gamma-vol", f.volume,
                    "UNI 11211-4: gamma_VolF1, block volume survey (1.02 precise, 1.10 not)")
        ->capture_default_str();
    cmd->add_option("--gamma-unit-weight", f.unit_weight, "UNI 11211-4: gamma_gamma, unit weight")
        ->capture_default_str();
    cmd->callback([args] { run(*args); });
}

}  // namespace rockfall::app
