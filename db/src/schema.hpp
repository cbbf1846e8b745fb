#pragma once
// The results database schema, version 2 (documented in docs/database.md).

#include <array>
#include <string_view>

namespace rockfall::db::schema {

/// CREATE TABLE statements of the current schema version.
extern const std::string_view definition;

/// CREATE VIEW statements of the current schema version (sample_results, impact_results,
/// sample_impacts), over the tables of `definition`.
extern const std::string_view views;

/// TEMP views that present a version-1 file's tables as version 2's (rock = 0, a rocks view
/// from samples); `views` then follow as TEMP views too.
extern const std::string_view version1_adapter;

/// CREATE TABLE statements of the soil-flow tables (soil_schema.cpp), in every file of this
/// version; filled when run.kind = 'soil_flow'.
extern const std::string_view soil_definition;

/// CREATE TABLE statements of the calibration tables (calibration_schema.cpp), in every file
/// of this version written since they were added; filled when run.kind is 'drop_test' or
/// 'heap_test'.
extern const std::string_view calibration_definition;

/// The calibration tables; open_any() checks they exist in a calibration database (older files
/// of this version lack them and hold no calibration).
inline constexpr std::array<std::string_view, 6> calibration_objects = {
    "calibration_shapes", "calibration_identified", "calibration_curve", "drop_tests", "heap_tests",
    "heap_planes"};

/// Tables and views every database of this version has; open() checks they exist.
/// (A version-1 file has all but rocks.)
inline constexpr std::array<std::string_view, 16> objects = {
    "run",          "zones",        "samples",         "outcomes",       "stations",
    "wall_impacts", "trajectories", "sample_results",  "impact_results", "sample_impacts",
    "soil_run",     "soil_load",    "soil_load_steps", "soil_motion",    "soil_deposit",
    "rocks"};

}  // namespace rockfall::db::schema
