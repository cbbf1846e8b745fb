#include "scenario/scenario_file.hpp"

#include "scenario_reader.hpp"
#include "scenario_schema.hpp"
#include "sweep_reader.hpp"

#include <climits>
#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>

namespace rockfall::scenario {

namespace fs = std::filesystem;

std::string to_string(const ScenarioProblem& problem) {
    std::string text =
        problem.key.empty() ? problem.message : problem.key + " = " + problem.message;
    if (!problem.file.empty()) {
        text += " (" + problem.file;
        if (problem.line > 0) text += ":" + std::to_string(problem.line);
        if (problem.line > 0 && problem.column > 0) text += ":" + std::to_string(problem.column);
        text += ")";
    }
    return text;
}

namespace {

std::string join_lines(const std::vector<ScenarioProblem>& problems) {
    std::string text;
    for (const ScenarioProblem& problem : problems) {
        if (!text.empty()) text += "\n";
        text += to_string(problem);
    }
    return text;
}

const std::vector<ScenarioProblem>& sort_in_file_order(std::vector<ScenarioProblem>& problems) {
    // Problems without a line (missing keys of tables the file never wrote) go last.
    const auto order = [](const ScenarioProblem& p) {
        return std::pair(p.file, p.line > 0 ? p.line : INT_MAX);
    };
    std::stable_sort(
        problems.begin(), problems.end(),
        [&](const ScenarioProblem& a, const ScenarioProblem& b) { return order(a) < order(b); });
    return problems;
}

[[noreturn]] void fail(std::string file, int line, std::string message) {
    throw ScenarioError({{std::move(file), line, "", std::move(message)}});
}

// Overrides `base` with `over`: tables merge recursively, any other value replaces the base's.
// Inline tables are values: TOML defines them as complete, and merging two distributions
// ({ uniform = ... } over { normal = ... }) would make one naming both.
// Nodes are moved, which keeps their source file and line for messages.
void merge(toml::table& base, toml::table&& over) {
    for (auto&& [key, node] : over) {
        auto* over_table = node.as_table();
        auto* base_table = base.get_as<toml::table>(key.str());
        if (over_table != nullptr && base_table != nullptr && !over_table->is_inline()) {
            merge(*base_table, std::move(*over_table));
        } else {
            base.insert_or_assign(key, std::move(node));
        }
    }
}

}  // namespace

namespace detail {

std::string read_text(const fs::path& file, const std::string& referenced_from, int line) {
    std::error_code error;
    const fs::file_status status = fs::status(file, error);
    std::string reason;
    if (!fs::exists(status)) {
        reason = "no such file";
    } else if (fs::is_directory(status)) {
        reason = "is a directory";
    }
    std::ifstream in(file, std::ios::binary);
    if (reason.empty() && !in) reason = std::strerror(errno);
    std::ostringstream text;
    if (reason.empty()) {
        text << in.rdbuf();
        if (in.bad()) reason = "read error";
    }
    if (!reason.empty()) {
        if (referenced_from.empty()) {
            fail(file.string(), 0, "cannot read the scenario file: " + reason);
        }
        fail(referenced_from, line,
             "cannot read the base scenario '" + file.string() + "' named by extends: " + reason);
    }
    return std::move(text).str();
}

toml::table parse_toml(std::string_view text, const std::string& source) {
    try {
        return toml::parse(text, source);
    } catch (const toml::parse_error& error) {
        const toml::source_position begin = error.source().begin;
        throw ScenarioError({{source, static_cast<int>(begin.line), "",
                              "TOML syntax error: " + std::string(error.description()),
                              static_cast<int>(begin.column)}});
    }
}

namespace {

// resolve_extends below, `depth` bases down from the file being loaded.
toml::table resolve_extends_at(toml::table table, const std::string& source,
                               const fs::path& base_dir, std::vector<fs::path>& chain, int depth) {
    const toml::node* extends = table.get("extends");
    if (extends == nullptr) return table;
    const Location where = node_location(*extends, source);
    const auto* name = extends->as_string();
    if (name == nullptr || name->get().empty()) {
        throw ScenarioError(
            {{where.file, where.line, "extends",
              describe(*extends) +
                  ": must be the path of a base scenario file (a non-empty string)"}});
    }
    const fs::path base_path = (base_dir / name->get()).lexically_normal();
    const fs::path identity = fs::weakly_canonical(base_path);
    if (std::find(chain.begin(), chain.end(), identity) != chain.end()) {
        std::string cycle;
        for (const fs::path& file : chain) cycle += file.filename().string() + " -> ";
        fail(where.file, where.line,
             "extends forms a cycle: " + cycle + identity.filename().string());
    }
    // Checked before the base is read: a chain of any length costs at most this many reads.
    if (depth >= max_extends_depth) {
        fail(where.file, where.line,
             "extends = \"" + name->get() + "\": the chain of base scenarios goes " +
                 std::to_string(depth + 1) + " files deep here; the most is " +
                 std::to_string(max_extends_depth));
    }
    const std::string base_source = base_path.string();
    toml::table base = parse_toml(read_text(base_path, where.file, where.line), base_source);
    chain.push_back(identity);
    base =
        resolve_extends_at(std::move(base), base_source, base_path.parent_path(), chain, depth + 1);
    chain.pop_back();
    table.erase("extends");
    merge(base, std::move(table));
    return base;
}

}  // namespace

toml::table resolve_extends(toml::table table, const std::string& source, const fs::path& base_dir,
                            std::vector<fs::path>& chain) {
    return resolve_extends_at(std::move(table), source, base_dir, chain, 0);
}

}  // namespace detail

namespace {

struct Parsed {
    engine::Scenario scenario;
    risk::SweepSpec sweep;
    bool has_sweep = false;
    bool extended = false;
};

Parsed parse(std::string_view text, const std::string& source, const fs::path& base_dir,
             std::vector<fs::path> chain) {
    toml::table root = detail::parse_toml(text, source);
    Parsed parsed;
    parsed.extended = root.contains("extends");
    root = detail::resolve_extends(std::move(root), source, base_dir, chain);

    std::vector<ScenarioProblem> problems;
    detail::SourceMap sources;
    sources.add("", {source, 0});
    parsed.scenario = detail::read_scenario(root, source, sources, problems);
    std::vector<ScenarioProblem> invalid = detail::find_problems(parsed.scenario, &sources);
    problems.insert(problems.end(), invalid.begin(), invalid.end());

    // The sweep's defaults and checks need a valid base; its keys are read in any case, so that
    // their problems come with the base's.
    const bool base_valid = problems.empty();
    if (base_valid && (!parsed.scenario.rocks.empty() || parsed.scenario.cluster)) {
        parsed.sweep = risk::sweep_defaults(parsed.scenario);
    }
    if (const toml::node* sweep = root.get("sweep")) {
        parsed.has_sweep = true;
        detail::Context context{source, sources, problems};
        detail::read_sweep(*sweep, parsed.sweep, context, parsed.scenario.cluster.has_value());
        if (base_valid) {
            std::vector<ScenarioProblem> sweep_problems =
                detail::find_sweep_problems(parsed.sweep, parsed.scenario, &sources);
            problems.insert(problems.end(), sweep_problems.begin(), sweep_problems.end());
        }
    }
    if (!problems.empty()) throw ScenarioError(std::move(problems));
    return parsed;
}

ScenarioFile file_from(std::string text, const std::string& source, const fs::path& base_dir,
                       std::vector<fs::path> chain) {
    ScenarioFile loaded;
    loaded.path = source;
    loaded.text = std::move(text);
    const Parsed parsed = parse(loaded.text, source, base_dir, std::move(chain));
    loaded.scenario = parsed.scenario;
    loaded.sweep = parsed.sweep;
    loaded.has_sweep = parsed.has_sweep;
    // The text must stand alone (results databases keep it): resolve what refers to other
    // files, base scenarios, mesh files (rocks and terrain) and the sweep's catalogue, by
    // writing every key out (meshes and named shapes as vertices).
    const bool refers_to_files =
        loaded.scenario.slope.terrain != nullptr ||
        std::any_of(loaded.scenario.rocks.begin(), loaded.scenario.rocks.end(),
                    [](const engine::RockRelease& rock) { return rock.rock.shape != nullptr; }) ||
        !parsed.sweep.entries.empty();
    if (parsed.extended || refers_to_files) {
        loaded.text = "# " + source +
                      " with its base scenarios and meshes resolved: every key "
                      "written out.\n" +
                      format_scenario(loaded.scenario);
        if (parsed.has_sweep) {
            loaded.text +=
                "\n" + (loaded.scenario.cluster ? detail::format_cluster_sweep(parsed.sweep)
                                                : detail::format_sweep(parsed.sweep));
        }
    }
    return loaded;
}

}  // namespace

ScenarioError::ScenarioError(std::vector<ScenarioProblem> problems)
    : std::runtime_error(join_lines(sort_in_file_order(problems))),
      problems_(std::move(problems)) {}

ScenarioFile load_scenario(const fs::path& file) {
    ScenarioFile loaded = file_from(detail::read_text(file, "", 0), file.string(),
                                    file.parent_path(), {fs::weakly_canonical(file)});
    loaded.path = file;
    return loaded;
}

ScenarioFile parse_scenario_file(std::string_view text, const std::string& source,
                                 const fs::path& base_dir) {
    return file_from(std::string(text), source, base_dir, {});
}

engine::Scenario parse_scenario(std::string_view text, const std::string& source,
                                const fs::path& base_dir) {
    return parse(text, source, base_dir, {}).scenario;
}

}  // namespace rockfall::scenario
