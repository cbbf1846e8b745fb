#pragma once
// TOML document -> Scenario. Only types and key names are checked here; ranges and
// cross-field rules are checked on the filled struct (scenario_validation.cpp), so the same
// checks apply to scenarios built in code.

#include "scenario_schema.hpp"

#include "app/scenario_file.hpp"
#include "engine/scenario.hpp"

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace rockfall::app::detail {

// Fills a Scenario from `root` (extends already resolved and removed). A missing key keeps the
// struct default. Wrong types and unknown keys are appended to `problems`; the location of
// every key read is recorded in `sources`. `file` names nodes that carry no source path.
engine::Scenario read_scenario(const toml::table& root, const std::string& file, SourceMap& sources,
                               std::vector<ScenarioProblem>& problems);

// A node as it would be written in TOML, on one line and shortened; tables show as {...}.
std::string describe(const toml::node& node);

// Where a node was written: its source path (or `fallback`) and line.
Location node_location(const toml::node& node, const std::string& fallback);

}  // namespace rockfall::app::detail
