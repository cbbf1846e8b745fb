#pragma once
/// Scenario files: TOML, SI units, every value defaulted and validated at load time.
///
/// Layout (docs/scenarios.md, "Scenario files", lists every key with unit, default and range):
/// top-level `name`, `extends`, `gravity`, `stations`; tables `[slope]` (with `[[slope.segments]]`,
/// `[slope.side_walls]`, `[slope.bars]`, `[slope.wall]`), `[materials.slope|bars|side_walls|
/// wall]`, `[wall_contact]`, `[[rocks]]` (with `[rocks.material]`, `[rocks.release]`),
/// `[numerics]`, and `[sweep]` (what a sweep varies, risk::SweepSpec). Keys are the field names of
/// engine::Scenario and shapes::SlopeSpec; a missing key keeps the struct's default. Indices in key
/// paths and `slope.bars.segments` are 0-based.
///
/// `extends = "base.toml"` (relative to the file) loads the base first and overrides it key by
/// key: tables merge recursively, every other value (arrays, arrays of tables and inline tables
/// `{ ... }`, which TOML defines as complete in themselves, included) replaces the base's. Bases
/// may extend further bases, at most max_extends_depth levels; cycles are errors.

#include "engine/scenario.hpp"
#include "risk/sampling.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rockfall::scenario {

/// The most base files one `extends` chain may follow (a file, its base, the base's base, ...
/// count 1 per base); a longer chain is an error naming the file whose `extends` goes too deep.
inline constexpr int max_extends_depth = 32;

/// One problem found in a scenario file.
struct ScenarioProblem {
    /// File the problem is in; empty for a scenario built in code.
    std::string file;
    /// 1-based line, or 0 when unknown (e.g. a missing file).
    int line = 0;
    /// Dotted key path, e.g. "rocks[2].density"; empty for file-level problems.
    std::string key;
    /// What is wrong, with the value, its unit and the allowed range, e.g.
    /// "-2500 kg/m3: must be in [500, 10000]".
    std::string message;
    /// 1-based column for syntax errors, otherwise 0.
    int column = 0;
};

/// One line `key = message (file:line)`, or `message (file:line:column)` without a key.
std::string to_string(const ScenarioProblem& problem);

/// Every problem found in a scenario file; what() lists them one per line as
/// `key = value unit: must be ... (file:line)`, in file and line order.
class ScenarioError : public std::runtime_error {
  public:
    /// Sorts the problems by file and line (problems without a line last).
    explicit ScenarioError(std::vector<ScenarioProblem> problems);
    /// The problems, in the order what() lists them.
    const std::vector<ScenarioProblem>& problems() const { return problems_; }

  private:
    std::vector<ScenarioProblem> problems_;
};

/// A loaded scenario and the text it came from (kept for results databases).
struct ScenarioFile {
    /// The validated scenario.
    engine::Scenario scenario;
    /// The file's text as written; for a file with `extends`, the resolved scenario with
    /// every key written out (format_scenario), so that the text stands alone.
    std::string text;
    /// Path it was read from.
    std::filesystem::path path;
    /// What a sweep of this scenario varies: the file's [sweep] table, its omitted keys fixed
    /// at the first rock's values (risk::sweep_defaults); without [sweep], sweep_defaults.
    risk::SweepSpec sweep;
    /// Whether the file has a [sweep] table.
    bool has_sweep = false;
};

/// Reads, parses and validates a scenario file; throws ScenarioError listing all problems
/// (a missing or unreadable file and TOML syntax errors are single problems).
ScenarioFile load_scenario(const std::filesystem::path& file);

/// Parses and validates scenario text as load_scenario reads a file (path = source; the text
/// as given, or resolved when it has `extends`); throws ScenarioError.
ScenarioFile parse_scenario_file(std::string_view text, const std::string& source,
                                 const std::filesystem::path& base_dir = ".");

/// Parses and validates scenario text; `source` names it in messages; `base_dir` resolves
/// `extends` paths. Throws ScenarioError.
engine::Scenario parse_scenario(std::string_view text, const std::string& source,
                                const std::filesystem::path& base_dir = ".");

/// Applies the file's range and cross-field rules to a scenario built in code; throws
/// ScenarioError (problems have key paths but no file).
void validate_scenario(const engine::Scenario& scenario);

/// Applies the [sweep] rules to a spec built in code, against a base scenario that must be
/// valid too: the spec's own rules (risk::find_problems) and the base scenario's ranges and
/// cross-field rules applied to each end of every support (size, density, material, release
/// distance); throws ScenarioError with key paths such as "sweep.rock.size".
void validate_sweep(const risk::SweepSpec& spec, const engine::Scenario& base);

/// The scenario as a complete TOML document, every key written out; parse_scenario reads it
/// back to an identical scenario (numbers are written in their shortest exact form).
std::string format_scenario(const engine::Scenario& scenario);

}  // namespace rockfall::scenario
