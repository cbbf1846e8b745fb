#include "calibrate_common.hpp"

#include "output_file.hpp"
#include "report/text_format.hpp"
#include "scenario/scenario_file.hpp"

#include "db/soil_run.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace rockfall::app {
namespace {

using report::fmt;

const char* const kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                               "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};
// More curves than this get no confidence band in the figure (it would hide the curves).
constexpr std::size_t kBandedCurves = 3;

std::string rock_label(const engine::RockRelease& release) {
    if (!release.name.empty()) return release.name;
    if (release.rock.shape) return "custom '" + release.rock.shape->name + "'";
    return std::string(shapes::to_string(release.rock.kind));
}

engine::RockSpec spec_of(const scenario::ShapeResult& shape, double density) {
    engine::RockSpec spec;
    spec.size = shape.rock.nominal_size;
    spec.density = density;
    if (shape.rock.kind == shapes::RockKind::custom) {
        spec.kind = shapes::RockKind::custom;
        spec.shape = std::make_shared<const shapes::CustomShape>(
            shapes::CustomShape{shape.label, shape.rock.hull});
    } else {
        spec.kind = shape.rock.kind;
    }
    return spec;
}

// The scenario rules for each rock (size, density, material, a custom kind with a hull).
void validate_rocks(const std::vector<CalibrationRock>& rocks) {
    for (const CalibrationRock& rock : rocks) {
        engine::Scenario check;
        check.rocks.front().rock = rock.spec;
        try {
            scenario::validate_scenario(check);
        } catch (const scenario::ScenarioError& e) {
            throw std::invalid_argument(rock.label + ": " + e.what());
        }
    }
}

}  // namespace

void require_in(const char* option, double value, const char* unit, double lower, double upper,
                bool open_lower) {
    const bool above = open_lower ? value > lower : value >= lower;
    if (std::isfinite(value) && above && value <= upper) return;
    std::ostringstream message;
    message << option << " = " << value << (*unit ? " " : "") << unit << ": must be in "
            << (open_lower ? '(' : '[') << lower << ", " << upper << ']';
    throw std::invalid_argument(message.str());
}

std::vector<CalibrationRock> calibration_rocks(const scenario::ShapeRequest& request,
                                               const std::optional<std::string>& scenario_file,
                                               double density, const std::string& command,
                                               std::string* scenario_text) {
    std::vector<CalibrationRock> rocks;
    if (scenario_file) {
        if (request.file || request.kind || request.entry || request.size) {
            throw std::invalid_argument(
                "give the rock either as --scenario FILE (its [[rocks]]) or as FILE / --kind "
                "with --entry and --size, not both");
        }
        const scenario::ScenarioFile file = scenario::load_scenario(*scenario_file);
        if (scenario_text) *scenario_text = file.text;
        const engine::Scenario& scenario = file.scenario;
        for (const engine::RockRelease& release : scenario.rocks) {
            rocks.push_back({rock_label(release), release.rock});
        }
        validate_rocks(rocks);
        return rocks;
    }
    if (!request.file && !request.kind) {
        throw std::invalid_argument(command +
                                    " needs a rock: --kind K, a mesh FILE, a catalogue FILE "
                                    "[--entry NAME]" +
                                    (command == "calibrate drop" ? " or --scenario FILE" : ""));
    }
    std::vector<scenario::ShapeResult> shapes;
    if (request.file && scenario::is_catalogue(*request.file) && !request.entry && !request.kind) {
        shapes = scenario::catalogue_shapes(request);
    } else {
        shapes.push_back(scenario::make_shape(request));
    }
    for (const scenario::ShapeResult& shape : shapes) {
        rocks.push_back({shape.label, spec_of(shape, density)});
    }
    validate_rocks(rocks);
    return rocks;
}

void add_calibration_file_options(CLI::App& cmd, CalibrationFiles& files,
                                  const CalibrationFileHelp& help) {
    cmd.add_option("--svg", files.svg, help.svg);
    cmd.add_option("--csv", files.csv, help.csv);
    cmd.add_option("--fragment", files.fragment, help.fragment);
    cmd.add_option("--db", files.db,
                   "Write every result (shapes, measurements, curve, identification) into a new "
                   "results database (docs/database.md)");
    cmd.add_flag("--json", files.json, "Print one JSON document instead of the summary");
    cmd.add_flag("--quiet", files.quiet, "No progress display");
}

nlohmann::json option_settings(const CLI::App& cmd) {
    nlohmann::json settings = nlohmann::json::object();
    for (const CLI::Option* option : cmd.get_options()) {
        const std::string name = option->get_single_name();
        if (name == "help" || name == "help-all") continue;
        nlohmann::json& value = settings[name];
        if (option->get_expected_max() == 0) {
            value = option->count() > 0;
        } else if (option->count() > 0) {
            const std::vector<std::string>& given = option->results();
            value = given.size() == 1 ? nlohmann::json(given.front()) : nlohmann::json(given);
        } else if (!option->get_default_str().empty()) {
            value = option->get_default_str();
        }
    }
    return settings;
}

void check_calibration_files(const CalibrationFiles& files) {
    for (const std::optional<std::string>& path : {files.csv, files.svg, files.fragment}) {
        if (path) output_target(*path);
    }
    if (files.db) db::check_new_database(*files.db);
}

void write_calibration_files(const CalibrationFiles& files,
                             const std::function<void(std::ostream&)>& csv,
                             const std::function<report::Plot()>& figure,
                             const std::function<std::string()>& fragment,
                             const std::function<db::CalibrationRecord()>& record) {
    if (files.csv) {
        OutputFile file(*files.csv);
        csv(file.stream());
        file.commit();
    }
    if (files.svg) write_svg(*files.svg, figure());
    if (files.fragment) {
        OutputFile file(*files.fragment);
        file.stream() << fragment();
        file.commit();
    }
    if (files.db) db::write_calibration(*files.db, record());
}

void print_calibration_files(std::ostream& out, const CalibrationFiles& files,
                             const std::string& csv_what) {
    if (files.csv) out << csv_what << " written to " << *files.csv << '\n';
    if (files.svg) out << "figure written to " << *files.svg << '\n';
    if (files.fragment) out << "scenario fragment written to " << *files.fragment << '\n';
    if (files.db) out << "results database written to " << *files.db << '\n';
}

void add_shape_options(CLI::App& cmd, scenario::ShapeRequest& request,
                       const std::string& file_help) {
    std::string kinds;
    for (const std::string& name : scenario::shape_kind_names())
        kinds += (kinds.empty() ? "" : ", ") + name;
    cmd.add_option("FILE", request.file, file_help);
    cmd.add_option("--kind", request.kind, "Shape: " + kinds)
        ->check(CLI::IsMember(scenario::shape_kind_names()));
    cmd.add_option("--entry", request.entry, "Catalogue entry");
    cmd.add_option("--scale", request.scale, "Mesh units to m (mm: 0.001)");
}

std::string material_text(const engine::Material& m) {
    return "friction " + report::short_number(m.friction) + ", restitution " +
           report::short_number(m.restitution) + ", rolling resistance " +
           report::short_number(m.rolling_resistance);
}

nlohmann::json material_json(const engine::Material& m) {
    return {{"friction", m.friction},
            {"restitution", m.restitution},
            {"rolling_resistance", m.rolling_resistance}};
}

nlohmann::json summary_json(const risk::SampleSummary& d) {
    return {{"count", d.count},
            {"mean", d.mean},
            {"standard_deviation", d.standard_deviation},
            {"p5", d.p5},
            {"p50", d.p50},
            {"p95", d.p95},
            {"mean_ci95", {d.mean_interval.lower, d.mean_interval.upper}}};
}

void print_summary_row(std::ostream& out, const std::string& name, const risk::SampleSummary& d,
                       const char* number) {
    char line[256];
    std::snprintf(line, sizeof line, "  %-44s", name.c_str());
    out << line;
    for (double v : {d.mean, d.standard_deviation, d.p5, d.p50, d.p95})
        out << ' ' << fmt(number, v);
    out << "  [" << fmt(number, d.mean_interval.lower) << ", " << fmt(number, d.mean_interval.upper)
        << "]\n";
}

std::string exact(double value) {
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    return std::string(buffer, end);
}

void add_calibration_curves(report::Plot& plot, const std::vector<FigureCurve>& curves,
                            double target, const std::string& target_label) {
    std::size_t colour = 0;
    for (const FigureCurve& curve : curves) {
        const std::string color = kColors[colour++ % std::size(kColors)];
        report::Series mean;
        mean.label = curve.label;
        mean.color = color;
        report::Series lower;
        lower.color = color;
        report::Series upper = lower;
        mean.marker = report::Marker::circle;
        lower.dash = upper.dash = "4 3";
        if (colour == 1) lower.label = "95 % CI of the mean";
        lower.line_width = upper.line_width = 1.0;
        for (const risk::SearchPoint& p : curve.points) {
            mean.x.push_back(p.parameter);
            mean.y.push_back(p.value.mean);
            lower.x.push_back(p.parameter);
            lower.y.push_back(p.value.mean_interval.lower);
            upper.x.push_back(p.parameter);
            upper.y.push_back(p.value.mean_interval.upper);
        }
        report::Series found;
        found.color = color;
        found.x = {curve.identified.parameter};
        found.y = {curve.identified.value.mean};
        found.line = false;
        found.marker = report::Marker::square;
        found.marker_size = 7.0;
        if (curves.size() <= kBandedCurves) {
            plot.series.push_back(lower);
            plot.series.push_back(upper);
        }
        plot.series.push_back(mean);
        plot.series.push_back(found);
    }
    if (!curves.empty()) {
        report::Series line;
        line.label = target_label;
        line.color = "#555555";
        line.x = {plot.x_min.value_or(0.0), plot.x_max.value_or(1.0)};
        line.y = {target, target};
        line.dash = "8 4";
        plot.series.push_back(line);
    }
}

CalibrationProgress::CalibrationProgress(const CalibrationFiles& files, std::int64_t runs,
                                         int search_steps, std::size_t shapes, std::string unit)
    : progress_(std::cerr, progress_mode_for_stderr(files.quiet || files.json),
                runs * (1 + search_steps) * static_cast<std::int64_t>(shapes), std::move(unit)),
      runs_(runs),
      identifies_(search_steps > 0) {}

risk::BatchProgress CalibrationProgress::callback() {
    return [this](std::int64_t done, std::int64_t) {
        last_ = done;
        progress_.update(offset_ + done);
    };
}

void CalibrationProgress::tested() {
    offset_ += runs_;
    last_ = 0;
}

void CalibrationProgress::identified() {
    offset_ += last_;
    last_ = 0;
}

void CalibrationProgress::finish() {
    progress_.finish(offset_,
                     identifies_ ? "(identification needed fewer steps than planned)" : "");
}

}  // namespace rockfall::app
