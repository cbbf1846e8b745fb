#pragma once
/// Soil scenario files (scenario C, `rockfall soil`): TOML, SI units, every value defaulted
/// (mpm::SoilScenario's defaults, the seed's Table 1) and validated at load time.
///
/// Layout: top-level `name`, `extends`, `density`; tables `[slope]` (as in rock scenario
/// files: `[[slope.segments]]`, `[slope.side_walls]`, `[slope.bars]`, `[slope.wall]`),
/// `[material]`, `[release]`, `[boundaries]`, `[numerics]` and `[output]`, whose keys are the
/// field names of mpm::SoilScenario's members. `extends` works as in rock scenario files.
/// Problems are reported as app::ScenarioError, every one at once with file:line, key, value,
/// unit and allowed range.

#include "scenario/scenario_file.hpp"

#include "mpm/soil.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace rockfall::scenario {

/// A loaded soil scenario and where it came from.
struct SoilFile {
    /// The scenario's name (`name` key; the file name when absent).
    std::string name;
    /// The validated scenario.
    mpm::SoilScenario scenario;
    /// The file's text as written; for a file with `extends`, the resolved tables (the base
    /// merged with the file) as TOML, so that the text stands alone.
    std::string text;
    /// Path it was read from.
    std::filesystem::path path;
};

/// Reads, parses and validates a soil scenario file; throws ScenarioError listing all problems
/// (a missing or unreadable file and TOML syntax errors are single problems).
SoilFile load_soil_scenario(const std::filesystem::path& file);

/// Parses and validates soil scenario text; `source` names it in messages and is the name
/// when the text has none; `base_dir` resolves `extends` paths. Throws ScenarioError.
SoilFile parse_soil_scenario(std::string_view text, const std::string& source,
                             const std::filesystem::path& base_dir = ".");

}  // namespace rockfall::scenario
