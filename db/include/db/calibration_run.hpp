#pragma once
/// A calibration experiment in a results database (`rockfall calibrate drop|heap --db`): the
/// same file format as a sweep's (application_id, schema version, the run table) with run.kind =
/// 'drop_test' or 'heap_test' and the calibration tables calibration_shapes,
/// calibration_identified, calibration_curve, drop_tests, heap_tests and heap_planes
/// (docs/database.md); one experiment per file, every shape it tested. SI units; angles in
/// degrees.

#include "db/results_db.hpp"
#include "engine/scenario.hpp"
#include "risk/drop_test.hpp"
#include "risk/heap_test.hpp"
#include "risk/sample_summary.hpp"

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace rockfall::db {

/// One point of an identification curve: the parameter and the measure's distribution there.
struct CalibrationCurvePoint {
    /// Surface restitution (drop test) or rock friction (heap test).
    double parameter = 0.0;
    /// Drop test: the contact restitution at that point (the mean with the rock's); heap test:
    /// NaN.
    double contact_value = std::numeric_limits<double>::quiet_NaN();
    /// Whether the search added it after the even grid.
    bool refinement = false;
    /// Mean kinematic COR (drop) or angle of repose, deg (heap), over the drops or heaps.
    risk::SampleSummary measure;
};

/// A shape's identification: the parameter value that reproduces a measured value.
struct CalibrationIdentified {
    /// "surface_restitution" (drop test) or "rock_friction" (heap test).
    std::string parameter;
    /// "cor_height", "cor_speed" (drop test) or "angle_deg" (heap test).
    std::string measure;
    /// The measured value matched and the parameter identified.
    double target = 0.0;
    double value = 0.0;
    /// Drop test: the contact restitution at `value`; heap test: NaN.
    double contact_value = std::numeric_limits<double>::quiet_NaN();
    /// The measure's distribution at `value`.
    risk::SampleSummary achieved;
    /// Parameter values whose 95 % interval of the mean holds the target.
    risk::Interval consistent;
    /// The curve and the refinement points, in parameter order.
    std::vector<CalibrationCurvePoint> curve;
};

/// One heap with the rock friction it ran at.
struct CalibrationHeap {
    double rock_friction = 0.0;
    risk::HeapMeasurement heap;
};

/// One shape of the experiment.
struct CalibrationShape {
    /// What the rock is ("sphere 0.2 m", "catalogue entry 'cube'", a [[rocks]] name).
    std::string label;
    /// shapes::to_string of the rock's kind (sphere, massive, planar, custom).
    std::string kind;
    /// Drop test: nominal diameter, m; heap test: NaN (sizes come from the grading).
    double size = std::numeric_limits<double>::quiet_NaN();
    /// kg/m3.
    double density = 0.0;
    /// Wadell sphericity of the rock's hull (1 for a sphere).
    double sphericity = 1.0;
    /// The rock's and the surface's materials as configured.
    engine::Material rock;
    engine::Material surface;
    /// Drop test: every drop at the configured surface; heap test: empty.
    std::vector<risk::DropMeasurement> drops;
    /// Heap test: every heap at the configured friction and at each curve point; drop test:
    /// empty.
    std::vector<CalibrationHeap> heaps;
    /// When the command identified a parameter.
    std::optional<CalibrationIdentified> identified;
};

/// One calibration experiment.
struct CalibrationRecord {
    /// Tool, times, settings (JSON), seed; method "drop_test" or "heap_test", samples_planned
    /// the drops or heaps per shape, scenario_text the --scenario file's text (else empty).
    RunRecord run;
    /// RunKind::drop_test or RunKind::heap_test.
    RunKind kind = RunKind::drop_test;
    std::vector<CalibrationShape> shapes;
};

/// Writes a new database at `path` holding `record`, in one transaction in a hidden temporary
/// file published under `path` at the end: the file appears whole or not at all, and an
/// existing file is never replaced. Throws DatabaseError (bad_file) when `path` exists or its
/// directory is missing or read-only, (failure) when writing fails (e.g. disk full), and
/// std::invalid_argument when `record.kind` is not a calibration kind.
void write_calibration(const std::filesystem::path& path, const CalibrationRecord& record);

/// The calibration experiment `db` holds (open it with ResultsDb::open_any). Throws
/// DatabaseError (bad_file) when it holds something else or its tables are damaged. Plane
/// outlines (HeapProfile::radius and height) are not stored and come back empty.
CalibrationRecord read_calibration(const ResultsDb& db);

}  // namespace rockfall::db
