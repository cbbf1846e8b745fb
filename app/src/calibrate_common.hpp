#pragma once
/// What the `rockfall calibrate` experiments share: the rocks a command line names, option
/// checks, and the pieces of their outputs (distribution rows, JSON, figures, exact numbers).

#include "progress.hpp"
#include "report/svg_plot.hpp"
#include "scenario/shape_source.hpp"

#include "db/calibration_run.hpp"
#include "engine/scenario.hpp"
#include "risk/parameter_search.hpp"
#include "risk/sample_summary.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rockfall::app {

/// A rock to test and what to call it.
struct CalibrationRock {
    std::string label;
    engine::RockSpec spec;
};

/// Throws std::invalid_argument "OPTION = VALUE UNIT: must be in [LOWER, UPPER]" (an open lower
/// bound with `open_lower`) unless the value is finite and in the range.
void require_in(const char* option, double value, const char* unit, double lower, double upper,
                bool open_lower = false);

/// The rocks of a command line: every [[rocks]] entry of `scenario_file` (when given), or the
/// rock (every entry of a catalogue without --entry) the shape options describe, as `rockfall
/// shape` reads them, at `density` (kg/m3). `command` names the command in the message when no
/// rock is given. Each rock passes the scenario rules.
/// `scenario_text`, when given, receives the scenario file's resolved text (empty without one).
std::vector<CalibrationRock> calibration_rocks(const scenario::ShapeRequest& request,
                                               const std::optional<std::string>& scenario_file,
                                               double density, const std::string& command,
                                               std::string* scenario_text = nullptr);

/// Where a calibration command writes its files (each optional) and how it prints.
struct CalibrationFiles {
    std::optional<std::string> csv;
    std::optional<std::string> svg;
    std::optional<std::string> fragment;
    /// A new results database (db/calibration_run.hpp).
    std::optional<std::string> db;
    bool json = false;
    bool quiet = false;
};

/// The progress bar of a calibration over several shapes: each shape's test of `runs` runs, then,
/// when the command identifies a parameter, an identification planned at `search_steps` tests of
/// `runs` runs (curve points plus the search's largest number of refinements; 0: none). It
/// usually stops earlier, so the bar ends at the runs done.
class CalibrationProgress {
  public:
    CalibrationProgress(const CalibrationFiles& files, std::int64_t runs, int search_steps,
                        std::size_t shapes, std::string unit);
    /// The callback the tests and identifications report to.
    risk::BatchProgress callback();
    /// After a shape's test of `runs` runs.
    void tested();
    /// After a shape's identification.
    void identified();
    /// Ends the bar.
    void finish();

  private:
    Progress progress_;
    const std::int64_t runs_;
    const bool identifies_;
    std::int64_t offset_ = 0;
    std::int64_t last_ = 0;
};

/// Help texts of a command's --svg, --csv and --fragment.
struct CalibrationFileHelp {
    std::string svg;
    std::string csv;
    std::string fragment;
};

/// Adds --svg, --csv, --fragment, --db, --json and --quiet to `cmd`.
void add_calibration_file_options(CLI::App& cmd, CalibrationFiles& files,
                                  const CalibrationFileHelp& help);

/// Every option of `cmd` (but --help and --help-all) by its long name without dashes: the values
/// given, or the default as --help shows it (null without one); a flag as true or false. What a
/// calibration database stores as the run's settings.
nlohmann::json option_settings(const CLI::App& cmd);

/// Checks every given path by the output-file rule (the database by db::check_new_database)
/// before the experiment runs.
void check_calibration_files(const CalibrationFiles& files);

/// Writes the given files: the CSV by `csv`, the figure `figure()`, the fragment `fragment()`,
/// the database of `record()`.
void write_calibration_files(const CalibrationFiles& files,
                             const std::function<void(std::ostream&)>& csv,
                             const std::function<report::Plot()>& figure,
                             const std::function<std::string()>& fragment,
                             const std::function<db::CalibrationRecord()>& record);

/// "WHAT written to PATH" for every file written (`csv_what` names the CSV's rows).
void print_calibration_files(std::ostream& out, const CalibrationFiles& files,
                             const std::string& csv_what);

/// Adds FILE, --kind, --entry and --scale (a rock as `rockfall shape` reads it) to `cmd`;
/// `file_help` says what a catalogue means to the command.
void add_shape_options(CLI::App& cmd, scenario::ShapeRequest& request,
                       const std::string& file_help);

/// "friction F, restitution E, rolling resistance R".
std::string material_text(const engine::Material& m);

/// {"friction", "restitution", "rolling_resistance"}.
nlohmann::json material_json(const engine::Material& m);

/// {"count", "mean", "standard_deviation", "p5", "p50", "p95", "mean_ci95"}.
nlohmann::json summary_json(const risk::SampleSummary& d);

/// One table row: `name` in 44 columns, then mean, sd, p5, p50, p95 in `number` (printf) and
/// the interval of the mean in brackets.
void print_summary_row(std::ostream& out, const std::string& name, const risk::SampleSummary& d,
                       const char* number);

/// The shortest text that reads back as the same double.
std::string exact(double value);

/// A shape's curve for a calibration figure: its points (sorted by x), the identified one.
struct FigureCurve {
    std::string label;
    std::vector<risk::SearchPoint> points;
    risk::SearchPoint identified;
};

/// Mean output against parameter per curve, with the 95 % band of the mean (dashed, for up to
/// three curves), the identified points (squares) and the target (a dashed line over
/// [x_min, x_max]).
void add_calibration_curves(report::Plot& plot, const std::vector<FigureCurve>& curves,
                            double target, const std::string& target_label);

}  // namespace rockfall::app
