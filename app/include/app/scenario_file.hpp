#pragma once
/// Scenario files: TOML, SI units, every value defaulted and validated at load time.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "engine/scenario.hpp"

namespace rockfall::app {

/// One problem found in a scenario file.
struct ScenarioProblem {
    /// File the problem is in.
    std::string file;
    /// 1-based line, or 0 when the key is missing.
    int line = 0;
    /// Dotted key path, e.g. "rocks[2].density".
    std::string key;
    /// What is wrong, with the value, its unit and the allowed range.
    std::string message;
};

/// Every problem found in a scenario file; what() lists them one per line as
/// `key = value unit: must be ... (file:line)`.
class ScenarioError : public std::runtime_error {
public:
    explicit ScenarioError(std::vector<ScenarioProblem> problems);
    const std::vector<ScenarioProblem>& problems() const { return problems_; }

private:
    std::vector<ScenarioProblem> problems_;
};

/// A loaded scenario and the text it came from (kept for results databases).
struct ScenarioFile {
    engine::Scenario scenario;
    /// The file's text (after resolving `extends`).
    std::string text;
    /// Path it was read from.
    std::filesystem::path path;
};

/// Reads, parses and validates a scenario file; throws ScenarioError listing all problems.
ScenarioFile load_scenario(const std::filesystem::path& file);

/// Parses and validates scenario text; `source` names it in messages; `base_dir` resolves
/// `extends` paths.
engine::Scenario parse_scenario(std::string_view text, const std::string& source,
                                const std::filesystem::path& base_dir = ".");

}  // namespace rockfall::app
