#pragma once
/// What `rockfall calibrate heap` prints and writes: the angle of repose per shape, the
/// identification curve angle against friction, JSON, the per-heap CSV, the SVG figure (the
/// paper's Fig. 8) and the scenario fragment. The command itself: register_heap.

#include "report/svg_plot.hpp"

#include "risk/heap_test.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rockfall::app {

/// One shape's heap test and, when asked, its identification.
struct HeapShapeRun {
    /// What the rocks are ("cube", "catalogue entry 'cube'", ...).
    std::string label;
    /// The test as run (rocks at the configured friction, funnel, surface, heaps, seed).
    risk::HeapTestSpec spec;
    /// Wadell sphericity of the rock's hull (1 for a sphere).
    double sphericity = 1.0;
    /// The heaps at the configured friction.
    risk::HeapTestResult result;
    /// The rock friction that matches the target, when --target-angle was given.
    std::optional<risk::FrictionIdentification> identification;
};

/// Everything the command reports.
struct HeapReport {
    std::vector<HeapShapeRun> shapes;
    int threads = 1;
    /// Wall-clock time of all the heaps, s.
    double runtime = 0.0;
};

/// The readable summary: per shape the rocks, funnel, surface and materials, the angle of
/// repose over planes and heaps, and the identification's curve and result.
void print_heap_text(std::ostream& out, const HeapReport& report);

/// The same as one JSON document with unit-suffixed keys.
nlohmann::json heap_json(const HeapReport& report);

/// One row per heap and plane (every shape, every curve point), with units in the names.
void write_heap_csv(std::ostream& out, const HeapReport& report);

/// Mean angle of repose against rock friction per identified shape, with the 95 % band of the
/// mean over heaps, the target and the identified points (the paper's Fig. 8).
report::Plot heap_figure(const HeapReport& report);

/// A scenario fragment (TOML) with the identified [cluster.material] of one shape, for
/// `extends`; comments say what it was identified from.
std::string heap_fragment(const HeapShapeRun& run);

/// Adds `heap` to `rockfall calibrate`.
void register_heap(CLI::App& calibrate);

}  // namespace rockfall::app
