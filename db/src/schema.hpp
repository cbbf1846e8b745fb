#pragma once
// The results database schema, version 1 (documented in schema_v1.md and the README).

#include <array>
#include <string_view>

namespace rockfall::db::schema {

/// CREATE TABLE and CREATE VIEW statements of the current schema version.
extern const std::string_view definition;

/// Tables and views every database of this version has; open() checks they exist.
inline constexpr std::array<std::string_view, 10> objects = {
    "run",          "zones",        "samples",        "outcomes",       "stations",
    "wall_impacts", "trajectories", "sample_results", "impact_results", "sample_impacts"};

}  // namespace rockfall::db::schema
