#pragma once
/// What `rockfall calibrate drop` prints and writes: the coefficient table per shape, the
/// identification curve, JSON, the per-drop CSV, the SVG figure and the scenario fragment.

#include "report/svg_plot.hpp"

#include "risk/drop_test.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rockfall::app {

/// One shape's drop test and, when asked, its identification.
struct DropShapeRun {
    /// What the rock is ("sphere 0.2 m", "catalogue entry 'cube'", a [[rocks]] name).
    std::string label;
    /// The test as run (rock, surface at the configured restitution, height, count, seed).
    risk::DropTestSpec spec;
    /// Wadell sphericity of the rock's hull (1 for a sphere).
    double sphericity = 1.0;
    /// The drops at the configured surface restitution.
    risk::DropTestResult result;
    /// The surface restitution that matches the target, when --target-cor was given.
    std::optional<risk::RestitutionIdentification> identification;
};

/// Everything the command reports.
struct DropReport {
    std::vector<DropShapeRun> shapes;
    /// Which coefficient the identification matched.
    risk::CorDefinition definition = risk::CorDefinition::height;
    int threads = 1;
    /// Wall-clock time of all the drops, s.
    double runtime = 0.0;
};

/// "height" or "speed".
std::string to_string(risk::CorDefinition definition);

/// The readable summary: per shape the rock, surface and contact, the coefficient table with
/// percentiles and Student t intervals, and the identification's curve and result.
void print_drop_text(std::ostream& out, const DropReport& report);

/// The same as one JSON document with unit-suffixed keys.
nlohmann::json drop_json(const DropReport& report);

/// One row per drop (every shape), with units in the column names.
void write_drop_csv(std::ostream& out, const DropReport& report);

/// Mean COR against surface restitution per identified shape, with the 95 % band of the mean
/// (up to three shapes),
/// the target and the identified points (the paper's Fig. 11).
report::Plot drop_figure(const DropReport& report);

/// A scenario fragment (TOML) with the identified [materials.slope] of one shape, for
/// `extends`; comments say what it was identified from.
std::string drop_fragment(const DropShapeRun& run, risk::CorDefinition definition);

}  // namespace rockfall::app
