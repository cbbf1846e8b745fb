// `rockfall query DB <what>`: questions on a results database written by `rockfall sweep`.

#include "commands.hpp"
#include "output_file.hpp"
#include "report/calibration_summary.hpp"
#include "report/curve_figure.hpp"
#include "report/fit_figure.hpp"
#include "report/query_report.hpp"
#include "report/soil_report.hpp"
#include "report/station_figures.hpp"

#include "db/queries.hpp"
#include "db/results_db.hpp"
#include "db/soil_run.hpp"
#include "db/station_values.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::app {
namespace {

struct QueryArgs {
    std::string database;
    bool json = false;
    bool csv = false;
    double confidence = 0.95;
    // percentiles, exceed, curve: the breakdown.
    std::string group = "none";
    std::vector<double> size_classes;
    std::string per = "rock";
    // percentiles.
    std::string of = "reach";
    std::vector<double> levels = {50.0, 90.0, 95.0, 99.0};
    // exceed.
    std::optional<double> distance;
    std::optional<double> value;
    std::string interval = "wilson";
    // curve.
    int points = 200;
    std::string svg;
    // worst.
    std::int64_t count = 10;
    std::string worst_by = "reach";
    // stations.
    std::string figure = "vchange-cr";
    std::string compare;
};

report::QueryFormat format_of(const QueryArgs& args) {
    if (args.json) return report::QueryFormat::json;
    return args.csv ? report::QueryFormat::csv : report::QueryFormat::text;
}

db::Grouping grouping_of(const QueryArgs& args) {
    db::Grouping grouping{db::parse_group_by(args.group), args.size_classes,
                          db::parse_per(args.per)};
    if (!args.size_classes.empty() && grouping.by != db::GroupBy::size) {
        throw std::invalid_argument("--size-classes applies to --by size only");
    }
    db::validate_size_edges(grouping.size_edges);
    return grouping;
}

db::ResultsDb open_database(const QueryArgs& args) {
    return db::ResultsDb::open(args.database, false);
}

void run_summary(const QueryArgs& args) {
    // Soil and calibration databases have summaries of their own; every other query is about
    // rock sweeps.
    const db::ResultsDb database = db::ResultsDb::open_any(args.database, false);
    if (database.kind() == db::RunKind::soil_flow) {
        report::write_soil_summary(std::cout, format_of(args), args.database,
                                   db::read_soil_run(database));
        return;
    }
    if (database.kind() == db::RunKind::drop_test || database.kind() == db::RunKind::heap_test) {
        report::write_calibration_summary(std::cout, format_of(args), args.database,
                                          db::read_calibration(database));
        return;
    }
    report::write_summary(std::cout, format_of(args), args.database,
                          db::summarize(database, args.confidence));
}

void run_history(const QueryArgs& args) {
    const db::ResultsDb database = db::ResultsDb::open_any(args.database, false);
    const db::SoilRunRecord record = db::read_soil_run(database);
    if (!args.svg.empty()) {
        write_svg(args.svg, report::soil_load_figure(record, record.run.scenario_name, nullptr));
    }
    report::write_soil_history(std::cout, format_of(args), args.database, record);
    if (!args.svg.empty() && format_of(args) == report::QueryFormat::text) {
        std::cout << "figure written to " << args.svg << '\n';
    }
}

void run_percentiles(const QueryArgs& args) {
    const db::Quantity quantity = db::parse_quantity(args.of);
    const db::Grouping grouping = grouping_of(args);
    std::vector<double> ps;
    for (const double level : args.levels) ps.push_back(level / 100.0);
    const db::ResultsDb database = open_database(args);
    report::write_percentiles(std::cout, format_of(args), args.database,
                              db::percentiles(database, quantity, ps, grouping, args.confidence),
                              grouping.by, grouping.per);
}

void run_exceed(const QueryArgs& args) {
    // --distance D is the common question; --of Q --value V asks the same of another quantity.
    if (args.distance.has_value() == args.value.has_value()) {
        throw std::invalid_argument(
            "exceed needs --distance D (m past the toe) or --of QUANTITY --value V");
    }
    const db::Quantity quantity = args.distance ? db::Quantity::reach : db::parse_quantity(args.of);
    const double threshold = args.distance ? *args.distance : *args.value;
    const db::Grouping grouping = grouping_of(args);
    const db::IntervalMethod method = db::parse_interval_method(args.interval);
    const db::ResultsDb database = open_database(args);
    report::write_exceedance(
        std::cout, format_of(args), args.database,
        db::exceedance(database, quantity, threshold, grouping, method, args.confidence),
        grouping.by, grouping.per);
}

void run_curve(const QueryArgs& args) {
    const db::Quantity quantity = db::parse_quantity(args.of);
    const db::Grouping grouping = grouping_of(args);
    const db::IntervalMethod method = db::parse_interval_method(args.interval);
    const db::ResultsDb database = open_database(args);
    const db::ExceedanceCurve curve =
        db::exceedance_curve(database, quantity, args.points, grouping, method, args.confidence);
    if (!args.svg.empty()) {
        // The figure first: a failed write must not follow a printed table.
        const std::string stem = std::filesystem::path(args.database).stem().string();
        write_svg(args.svg, report::curve_figure(curve, "Exceedance of " +
                                                            std::string(db::to_string(quantity)) +
                                                            ": " + stem));
    }
    report::write_curve(std::cout, format_of(args), args.database, curve, grouping.by,
                        grouping.per);
    if (!args.svg.empty() && format_of(args) == report::QueryFormat::text) {
        std::cout << "figure written to " << args.svg << '\n';
    }
}

void run_worst(const QueryArgs& args) {
    const db::Quantity by = db::parse_quantity(args.worst_by);
    if (args.count < 1) {
        throw std::invalid_argument("--n = " + std::to_string(args.count) + ": must be >= 1");
    }
    const db::ResultsDb database = open_database(args);
    const db::Per per = db::parse_per(args.per);
    report::write_worst(std::cout, format_of(args), args.database, by,
                        db::worst_samples(database, by, args.count, per), per);
}

report::StationSet station_set(const std::string& path) {
    const db::ResultsDb database = db::ResultsDb::open(path, false);
    return {std::filesystem::path(path).stem().string(), path, database.run().scenario_name,
            db::read_rock_stations(database)};
}

void run_stations(const QueryArgs& args) {
    std::vector<report::StationSet> sets = {station_set(args.database)};
    if (!args.compare.empty()) sets.push_back(station_set(args.compare));
    // Files of one name in two folders are told apart by their paths.
    if (sets.size() > 1 && sets[0].label == sets[1].label) {
        for (report::StationSet& set : sets) set.label = set.database;
    }
    for (const report::StationSet& set : sets) {
        report::station_distances(set);  // no station rows: refused before any output
    }
    if (!args.svg.empty()) {
        const bool spin = args.figure == "omega-v";
        std::vector<report::MotionTrend> trends;
        for (const report::StationSet& set : sets) {
            trends.push_back(spin ? report::spin_speed_trend(set)
                                  : report::velocity_change_trend(set));
        }
        write_svg(
            args.svg,
            spin ? report::spin_speed_figure(trends, "Angular speed against speed at the toe")
                 : report::velocity_change_figure(trends, "V' against Cr at 4 m past the toe"));
    }
    report::write_stations(std::cout, format_of(args), sets);
    if (!args.svg.empty() && format_of(args) == report::QueryFormat::text) {
        std::cout << "figure written to " << args.svg << '\n';
    }
}

std::vector<std::string> quantity_names() {
    std::vector<std::string> names;
    for (const db::Quantity q : db::all_quantities) names.emplace_back(db::to_string(q));
    return names;
}

// "reach (m), max_speed (m/s), ...": the quantities with their units, for help texts.
std::string quantity_units() {
    std::string text;
    for (const db::Quantity q : db::all_quantities) {
        text += (text.empty() ? "" : ", ") + std::string(db::to_string(q)) + " (" +
                std::string(db::unit_of(q)) + ")";
    }
    return text;
}

// Options every query has: output format and confidence.
void add_common(CLI::App* cmd, QueryArgs& args) {
    CLI::Option* json = cmd->add_flag("--json", args.json, "Print one JSON document");
    cmd->add_flag("--csv", args.csv, "Print CSV (units in the column names)")->excludes(json);
    cmd->add_option("--confidence", args.confidence, "Confidence of the intervals, in (0, 1)")
        ->capture_default_str();
}

void add_per(CLI::App* cmd, QueryArgs& args) {
    cmd->add_option("--per", args.per,
                    "What one observation is: each rock of each sample (rock), or each sample "
                    "as a whole (sample: its largest value over its rocks; impulse: the total)")
        ->check(CLI::IsMember({"rock", "sample"}))
        ->capture_default_str();
}

void add_grouping(CLI::App* cmd, QueryArgs& args) {
    cmd->add_option("--by", args.group,
                    "Break down by shape kind, shape (family, named shape or generated), size "
                    "class or release zone")
        ->check(CLI::IsMember({"kind", "shape", "size", "zone"}));
    cmd->add_option("--size-classes", args.size_classes,
                    "Size class edges (m), ascending, e.g. 0.2,0.3,0.4; default: quartiles")
        ->delimiter(',');
    add_per(cmd, args);
}

}  // namespace

void register_query(CLI::App& app) {
    auto args = std::make_shared<QueryArgs>();
    CLI::App* query =
        app.add_subcommand("query",
                           "Questions on a results database written by `rockfall sweep` or "
                           "`rockfall soil --db`");
    query->add_option("database", args->database, "Results database (.db)")->required();
    query->require_subcommand(1);

    CLI::App* summary = query->add_subcommand(
        "summary", "The run, stop reasons, reach, wall and station shares, wall loads");
    add_common(summary, *args);
    summary->callback([args] { run_summary(*args); });

    CLI::App* history = query->add_subcommand(
        "history",
        "A soil flow's wall load, centre of mass and front over time (`rockfall soil --db`)");
    CLI::Option* history_json = history->add_flag("--json", args->json, "Print one JSON document");
    history->add_flag("--csv", args->csv, "Print CSV (units in the column names)")
        ->excludes(history_json);
    history->add_option("--svg", args->svg, "Also draw the wall-load history to this SVG file");
    history->callback([args] { run_history(*args); });

    CLI::App* pct = query->add_subcommand(
        "percentiles", "Percentiles with distribution-free confidence intervals");
    pct->add_option("--of", args->of, "Quantity: " + quantity_units())
        ->check(CLI::IsMember(quantity_names()))
        ->capture_default_str();
    pct->add_option("--p", args->levels, "Percentiles in (0, 100), e.g. 50,90,95,99")
        ->delimiter(',');
    add_grouping(pct, *args);
    add_common(pct, *args);
    pct->callback([args] { run_percentiles(*args); });

    CLI::App* exceed = query->add_subcommand(
        "exceed", "Probability that a rock's reach (or another quantity) is >= a value");
    CLI::Option* distance =
        exceed->add_option("--distance", args->distance, "Horizontal distance past the toe (m)");
    exceed
        ->add_option("--of", args->of,
                     "Quantity other than reach (with --value): " + quantity_units())
        ->check(CLI::IsMember(quantity_names()))
        ->excludes(distance);
    exceed->add_option("--value", args->value, "Threshold of --of, in its unit")
        ->excludes(distance);
    exceed->add_option("--interval", args->interval, "Interval for the probability")
        ->check(CLI::IsMember({"wilson", "clopper-pearson"}))
        ->capture_default_str();
    add_grouping(exceed, *args);
    add_common(exceed, *args);
    exceed->callback([args] { run_exceed(*args); });

    CLI::App* curve = query->add_subcommand(
        "curve", "Exceedance curve: probability that a quantity is >= x over its range");
    curve->add_option("--of", args->of, "Quantity: " + quantity_units())
        ->check(CLI::IsMember(quantity_names()))
        ->capture_default_str();
    curve->add_option("--points", args->points, "Thresholds, evenly spaced over the stored range")
        ->check(CLI::Range(2, 10000))
        ->capture_default_str();
    curve->add_option("--interval", args->interval, "Interval for the probability")
        ->check(CLI::IsMember({"wilson", "clopper-pearson"}))
        ->capture_default_str();
    curve->add_option("--svg", args->svg, "Also draw the curves with their bands to this SVG file");
    add_grouping(curve, *args);
    add_common(curve, *args);
    curve->callback([args] { run_curve(*args); });

    CLI::App* worst = query->add_subcommand(
        "worst", "The worst rocks (or samples) with their index and seed, for replay");
    worst->add_option("--n", args->count, "How many rocks (samples)")->capture_default_str();
    worst->add_option("--by", args->worst_by, "Quantity to rank by: " + quantity_units())
        ->check(CLI::IsMember(quantity_names()))
        ->capture_default_str();
    add_common(worst, *args);
    add_per(worst, *args);
    worst->callback([args] { run_worst(*args); });

    CLI::App* stations = query->add_subcommand(
        "stations",
        "Rocks at each station by shape; seed 000's V' against Cr (Fig. 5) and angular speed "
        "against speed (Fig. 6)");
    CLI::Option* svg = stations->add_option(
        "--svg", args->svg, "Also draw the --figure to this SVG file, one marker series per shape");
    stations
        ->add_option("--figure", args->figure,
                     "vchange-cr: V' from the toe to 4 m against Cr at 4 m (seed 000 Fig. 5); "
                     "omega-v: angular speed against speed at the toe with least-squares lines "
                     "(Fig. 6)")
        ->check(CLI::IsMember({"vchange-cr", "omega-v"}))
        ->needs(svg)
        ->capture_default_str();
    stations
        ->add_option("--compare", args->compare,
                     "A second database (e.g. the same sweep with bars off), shown beside the "
                     "first; each is labelled by its file name without extension")
        ->check(CLI::ExistingFile);
    add_common(stations, *args);
    stations->callback([args] { run_stations(*args); });
}

}  // namespace rockfall::app
