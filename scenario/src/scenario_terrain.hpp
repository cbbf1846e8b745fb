#pragma once
// Terrain meshes in scenario files: the [slope.terrain] table (docs/scenarios.md, "Terrain from
// files"). Its keys are `mesh` (a mesh file, relative to the scenario file that names it) or
// `vertices` and `triangles` (inline, as the writer stores them), and `scale`, `offset`, `name`.

#include "scenario_reader.hpp"
#include "scenario_schema.hpp"

#include "engine/scenario.hpp"
#include "shapes/slope.hpp"

namespace rockfall::scenario::detail {

// Reads [slope.terrain] from the [slope] table being read, if present; the terrain's problems
// (bad keys, unreadable or bad meshes) are reported at their keys.
void read_terrain(TableReader& slope_reader, shapes::SlopeSpec& slope);

// Cross-field rules of a scenario's terrain (none without one): the mesh covers the slope's
// footprint and has ground under every release point. `profile_ok`: the profile is valid.
void check_terrain(Checker& c, const engine::Scenario& scenario, bool profile_ok);

}  // namespace rockfall::scenario::detail
