#pragma once
// The results database schema, version 1 (documented in docs/database.md).

#include <array>
#include <string_view>

namespace rockfall::db::schema {

/// CREATE TABLE and CREATE VIEW statements of the current schema version.
extern const std::string_view definition;

/// CREATE TABLE statements of the soil-flow tables (soil_schema.cpp), in every file of this
/// version; filled when run.kind = 'soil_flow'.
extern const std::string_view soil_definition;

/// Tables and views every database of this version has; open() checks they exist.
inline constexpr std::array<std::string_view, 15> objects = {
    "run",          "zones",        "samples",         "outcomes",       "stations",
    "wall_impacts", "trajectories", "sample_results",  "impact_results", "sample_impacts",
    "soil_run",     "soil_load",    "soil_load_steps", "soil_motion",    "soil_deposit"};

}  // namespace rockfall::db::schema
