#pragma once
/// The verification and validation report of the tool itself (`rockfall validate --html`):
/// every check as its reference value (analytic or published), the simulated value, the
/// tolerance and the verdict (PASS or MISS), grouped in sections with their figures; as one
/// self-contained HTML file (the page of `rockfall report`: inline CSS with a print style
/// sheet, inline SVG, no script), as JSON and as a text summary. The HTML holds no runtimes
/// and no time of writing: the same build and options give the same bytes.

#include "report/reproduction_report.hpp"
#include "report/svg_plot.hpp"

#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace rockfall::report {

/// One check: a reference value, the simulated one, a tolerance and the verdict.
struct VvCheck {
    /// Key, unique in a report, [a-z0-9_.-] ("free_fall.drop"): the HTML row's id ("check-"
    /// and the key) and the JSON entry's.
    std::string id;
    /// What is compared, e.g. "drop after 1 s, dt 1 ms".
    std::string label;
    /// Unit of reference and simulated value ("m", "m/s2", "" for a ratio).
    std::string unit;
    /// The reference value (analytic or published) and where it comes from ("z0 - g t^2 / 2").
    double reference = std::numeric_limits<double>::quiet_NaN();
    std::string source;
    /// The simulated value; NaN when the run gave none (a MISS).
    double simulated = std::numeric_limits<double>::quiet_NaN();
    /// Largest allowed |simulated - reference|: a fraction of |reference| when relative,
    /// otherwise in the unit.
    double tolerance = 0.0;
    bool relative = true;
    /// More about the simulated value (spread, count), may be empty.
    std::string note;

    /// (simulated - reference) / |reference| when relative, else simulated - reference; NaN
    /// without a simulated value.
    double error() const;
    /// Whether there is a simulated value and |error()| <= tolerance.
    bool pass() const;
};

/// A check from its fields in order (no note).
VvCheck make_check(std::string id, std::string label, std::string unit, double reference,
                   std::string source, double simulated, double tolerance, bool relative = true);

/// A series drawn as a line through (x, y), without markers.
Series line_series(std::string label, std::string color, std::vector<double> x = {},
                   std::vector<double> y = {});

/// A series of `marker`s, its points added later; joined by a line when the marker is none.
Series point_series(std::string label, std::string color, Marker marker);

/// A figure's plot: title, axis labels (with units), the series, 480 px high, both axes from 0
/// when `from_zero` (otherwise following the data).
Plot vv_plot(std::string title, std::string x_label, std::string y_label,
             std::vector<Series> series, bool from_zero = true);

/// A figure of a section: the plot and its caption (the figure number is the report's).
struct VvFigure {
    Plot plot;
    std::string caption;
};

/// A table of checks with its caption.
struct VvTable {
    std::string caption;
    std::vector<VvCheck> checks;
};

/// A table of text cells (a reproduction's trends); header cells name their units.
struct VvTextTable {
    std::string caption;
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
};

/// One section: what was run and why the tolerances are what they are, its checks, figures.
struct VvSection {
    /// Anchor ([a-z-]) and heading.
    std::string id;
    std::string title;
    /// Paragraphs before the tables: the set-up, the reference's source, the tolerance's reason.
    std::vector<std::string> notes;
    std::vector<VvTable> tables;
    std::vector<VvTextTable> text_tables;
    std::vector<VvFigure> figures;
    /// The section's own text tables (seed 001's): print_vv_summary prints them in place of
    /// the check lines when not empty.
    std::string text;
};

/// A section with its anchor, heading and notes; tables and figures are added later.
VvSection vv_section(std::string id, std::string title, std::vector<std::string> notes);

/// The whole report.
struct VvReport {
    /// The program's version and build (ROCKFALL_VERSION, ROCKFALL_BUILD).
    std::string version;
    std::string build;
    /// Whether this is the --quick run.
    bool quick = false;
    /// The options as given, one (name, value) per line of the provenance.
    std::vector<std::pair<std::string, std::string>> settings;
    std::vector<VvSection> sections;
    /// What the report leaves out, and why.
    std::vector<std::pair<std::string, std::string>> left_out;
};

/// Every check of the report, in order.
std::vector<const VvCheck*> all_checks(const VvReport& report);

/// The report as one HTML document (well-formed XML as well).
void write_vv_html(std::ostream& out, const VvReport& report);

/// The checks as JSON: version, build, quick, checks (list of {id, section, label, unit,
/// reference, source, simulated, tolerance, relative, error, verdict}), passed, missed.
nlohmann::json vv_json(const VvReport& report);

/// The checks as a text table per section (or the section's own text) with a closing count
/// of PASS and MISS.
void print_vv_summary(std::ostream& out, const VvReport& report);

/// Seed 001's reproduction as a report section: Table 2's numerical and physical cells and the
/// speeds at 1.4 m as checks (published value, simulated mean with its spread and count,
/// relative tolerance), the trends, and the figure of simulated against published.
VvSection seed001_section(const risk::seed001::Reproduction& reproduction,
                          const ReproductionInfo& info);

}  // namespace rockfall::report
