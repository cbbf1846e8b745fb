#pragma once
// TOML document -> Scenario. Only types and key names are checked here; ranges and
// cross-field rules are checked on the filled struct (scenario_validation.cpp), so the same
// checks apply to scenarios built in code. The table reader and the leaf readers are shared with
// the soil scenario loader (soil_file.cpp).

#include "scenario/scenario_file.hpp"
#include "scenario_schema.hpp"

#include "engine/scenario.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rockfall::scenario::detail {

// Fills a Scenario from `root` (extends already resolved and removed). A missing key keeps the
// struct default. Wrong types and unknown keys are appended to `problems`; the location of
// every key read is recorded in `sources`. `file` names nodes that carry no source path.
engine::Scenario read_scenario(const toml::table& root, const std::string& file, SourceMap& sources,
                               std::vector<ScenarioProblem>& problems);

// A node as it would be written in TOML, on one line and shortened; tables show as {...}.
std::string describe(const toml::node& node);

// Where a node was written: its source path (or `fallback`) and line.
Location node_location(const toml::node& node, const std::string& fallback);

// Reads the text of a scenario file; a missing or unreadable file throws ScenarioError, placed
// at `referenced_from`:`line` (the extends key naming it) when that is not empty.
std::string read_text(const std::filesystem::path& file, const std::string& referenced_from,
                      int line);

// Parses TOML text; a syntax error throws ScenarioError with the line and column.
toml::table parse_toml(std::string_view text, const std::string& source);

// Resolves `extends` in `table`, written in `source`: the base (relative to `base_dir`) is read
// and overridden key by key. `chain` holds the canonical paths of the files being resolved,
// outermost first, to detect cycles; at most max_extends_depth bases are followed.
toml::table resolve_extends(toml::table table, const std::string& source,
                            const std::filesystem::path& base_dir,
                            std::vector<std::filesystem::path>& chain);

// What a reading pass shares: the file name for nodes without a source, where keys were
// written, and the problems found so far.
struct Context {
    const std::string& file;
    SourceMap& sources;
    std::vector<ScenarioProblem>& problems;

    void report(const toml::node& node, std::string path, std::string message) {
        Location where = node_location(node, file);
        problems.push_back(
            {std::move(where.file), where.line, std::move(path), std::move(message)});
    }
};

// "must be a number (kg/m3) in [500, 10000]": the expected type, unit and range.
std::string expectation(std::string_view what, std::string_view unit, const Range& range);

// One TOML table being read: remembers which keys the reader asked for, so that every other
// key can be reported as unknown, and records where each key was written.
class TableReader {
  public:
    TableReader(const toml::table& table, std::string path, Context& context);

    // The node at `key`, or null when absent; `key` becomes one of the table's known keys.
    const toml::node* get(std::string_view key);

    // Whether the table has `key`, without making it known.
    bool contains(std::string_view key) const { return table_.contains(key); }

    std::string path(std::string_view key) const {
        return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
    }

    Context& context() { return context_; }

    // Reports every key of the table that get() was never asked for.
    void finish();

  private:
    std::string unknown_key_text(std::string_view name) const;

    const toml::table& table_;
    std::string path_;
    Context& context_;
    std::vector<std::string> known_;
};

// The value of an integer or floating-point node; empty for any other node.
std::optional<double> number_of(const toml::node& node);

// Leaf readers: a missing key keeps `out`; a wrong type is reported and keeps `out`.
void read(TableReader& reader, std::string_view key, double& out, std::string_view unit,
          const Range& range);
void read(TableReader& reader, std::string_view key, int& out, std::string_view unit,
          const Range& range);
void read(TableReader& reader, std::string_view key, bool& out, std::string_view unit,
          const Range& range);
void read(TableReader& reader, std::string_view key, engine::Vec3& out, std::string_view unit,
          const Range& range);
void read(TableReader& reader, std::string_view key, std::string& out);

template <class S, std::size_t N>
void read_fields(TableReader& reader, S& object, const Fields<S, N>& fields) {
    for (const Field<S>& field : fields) {
        std::visit(
            [&](auto member) { read(reader, field.key, object.*member, field.unit, field.range); },
            field.member);
    }
}

// A string key that must be one of `names`; returns the index of the name given.
template <std::size_t N>
std::optional<std::size_t> read_choice(TableReader& reader, std::string_view key,
                                       const std::array<std::string_view, N>& names) {
    const toml::node* node = reader.get(key);
    if (node == nullptr) return std::nullopt;
    if (const auto* value = node->as_string()) {
        const auto found = std::find(names.begin(), names.end(), value->get());
        if (found != names.end()) return static_cast<std::size_t>(found - names.begin());
    }
    std::string allowed;
    for (std::size_t i = 0; i < N; ++i)
        allowed += (i == 0 ? "\"" : ", \"") + std::string(names[i]) + "\"";
    reader.context().report(*node, reader.path(key),
                            describe(*node) + ": must be one of " + allowed);
    return std::nullopt;
}

// A string key naming one of `choices` (entries with .name and .value, as EnumName); `value`
// keeps its default when the key is absent.
template <typename Choice, std::size_t N, typename E>
void read_enum(TableReader& r, std::string_view key, const std::array<Choice, N>& choices,
               E& value) {
    std::array<std::string_view, N> names;
    for (std::size_t i = 0; i < N; ++i) names[i] = choices[i].name;
    if (const auto index = read_choice(r, key, names)) value = choices[*index].value;
}

// An array whose elements are all accepted by `element` (which reports the ones it rejects);
// replaces `out` only when every element is accepted.
template <class T, class Element>
void read_list(TableReader& reader, std::string_view key, std::vector<T>& out,
               std::string_view what, Element element) {
    const toml::node* node = reader.get(key);
    if (node == nullptr) return;
    const auto* array = node->as_array();
    if (array == nullptr) {
        reader.context().report(*node, reader.path(key),
                                describe(*node) + ": must be an array of " + std::string(what));
        return;
    }
    std::vector<T> values;
    bool all = true;
    for (std::size_t i = 0; i < array->size(); ++i) {
        const toml::node& item = *array->get(i);
        const std::string path = reader.path(key) + "[" + std::to_string(i) + "]";
        reader.context().sources.add(path, node_location(item, reader.context().file));
        if (std::optional<T> value = element(item, path)) {
            values.push_back(std::move(*value));
        } else {
            all = false;
        }
    }
    if (all) out = std::move(values);
}

// Runs `body` on the sub-table at `key`, if present; reports a non-table value.
template <class Body>
void with_table(TableReader& parent, std::string_view key, Body body) {
    const toml::node* node = parent.get(key);
    if (node == nullptr) return;
    if (const auto* table = node->as_table()) {
        TableReader reader(*table, parent.path(key), parent.context());
        body(reader);
        reader.finish();
    } else {
        parent.context().report(*node, parent.path(key),
                                describe(*node) + ": must be a table ([" + parent.path(key) + "])");
    }
}

// Reads an array of tables ([[key]] sections) into `out`, one default-initialised element per
// table, each filled by `body(reader, element)`.
template <class T, class Body>
void with_table_array(TableReader& parent, std::string_view key, std::vector<T>& out, Body body) {
    Context& context = parent.context();
    read_list(parent, key, out, "tables ([[" + parent.path(key) + "]])",
              [&](const toml::node& item, const std::string& path) -> std::optional<T> {
                  const auto* table = item.as_table();
                  if (table == nullptr) {
                      context.report(item, path, describe(item) + ": must be a table");
                      return std::nullopt;
                  }
                  T element{};
                  TableReader reader(*table, path, context);
                  body(reader, element);
                  reader.finish();
                  return element;
              });
}

// The keys of a [slope] table (segments, side walls, bars, wall).
void read_slope(TableReader& r, shapes::SlopeSpec& slope);

}  // namespace rockfall::scenario::detail
