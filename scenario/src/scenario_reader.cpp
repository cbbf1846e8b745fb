#include "scenario_reader.hpp"

#include "scenario_cluster.hpp"
#include "scenario_lining.hpp"
#include "scenario_rock_shape.hpp"
#include "scenario_terrain.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>
#include <variant>

namespace rockfall::scenario::detail {

Location node_location(const toml::node& node, const std::string& fallback) {
    const toml::source_region& source = node.source();
    return {source.path ? *source.path : fallback, static_cast<int>(source.begin.line)};
}

std::string describe(const toml::node& node) {
    if (node.is_table()) return "{...}";
    if (const auto* text = node.as_string()) return toml_string(text->get());
    std::ostringstream out;
    node.visit([&out](const auto& concrete) { out << concrete; });
    std::string text = out.str();
    std::replace(text.begin(), text.end(), '\n', ' ');
    constexpr std::size_t max_length = 60;
    if (text.size() > max_length) text = text.substr(0, max_length - 3) + "...";
    return text;
}

// "must be a number (kg/m3) in [500, 10000]": the expected type, unit and range.
std::string expectation(std::string_view what, std::string_view unit, const Range& range) {
    std::string text = "must be " + std::string(what);
    if (!unit.empty()) text += " (" + std::string(unit) + ")";
    if (range.min > -infinity || range.max < infinity) text += " " + range.describe();
    return text;
}

namespace {

// Levenshtein distance, to suggest the key a misspelt one was meant to be.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
            diagonal = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
        }
    }
    return row[b.size()];
}

}  // namespace

TableReader::TableReader(const toml::table& table, std::string path, Context& context)
    : table_(table), path_(std::move(path)), context_(context) {
    context_.sources.add(path_, node_location(table_, context_.file));
}

const toml::node* TableReader::get(std::string_view key) {
    known_.emplace_back(key);
    const toml::node* node = table_.get(key);
    if (node != nullptr) context_.sources.add(path(key), node_location(*node, context_.file));
    return node;
}

void TableReader::finish() {
    for (const auto& [key, node] : table_) {
        const std::string_view name = key.str();
        if (std::find(known_.begin(), known_.end(), name) != known_.end()) continue;
        context_.report(node, path(name), describe(node) + ": " + unknown_key_text(name));
    }
}

std::string TableReader::unknown_key_text(std::string_view name) const {
    std::string text = "unknown key";
    const std::string* best = nullptr;
    std::size_t best_distance = std::max<std::size_t>(2, name.size() / 3) + 1;
    for (const std::string& candidate : known_) {
        const std::size_t distance = edit_distance(name, candidate);
        if (distance < best_distance) {
            best = &candidate;
            best_distance = distance;
        }
    }
    if (best != nullptr) text += " (did you mean '" + *best + "'?)";
    text += "; allowed here:";
    for (std::size_t i = 0; i < known_.size(); ++i) text += (i == 0 ? " " : ", ") + known_[i];
    return text;
}

std::optional<double> number_of(const toml::node& node) {
    if (const auto* value = node.as_floating_point()) return value->get();
    if (const auto* value = node.as_integer()) return static_cast<double>(value->get());
    return std::nullopt;
}

// Leaf readers: a missing key keeps `out`; a wrong type is reported and keeps `out`.
void read(TableReader& reader, std::string_view key, double& out, std::string_view unit,
          const Range& range) {
    const toml::node* node = reader.get(key);
    if (node == nullptr) return;
    if (const std::optional<double> value = number_of(*node)) {
        out = *value;
    } else {
        reader.context().report(*node, reader.path(key),
                                describe(*node) + ": " + expectation("a number", unit, range));
    }
}

void read(TableReader& reader, std::string_view key, int& out, std::string_view unit,
          const Range& range) {
    const toml::node* node = reader.get(key);
    if (node == nullptr) return;
    const auto* value = node->as_integer();
    if (value == nullptr) {
        reader.context().report(*node, reader.path(key),
                                describe(*node) + ": " + expectation("an integer", unit, range));
        return;
    }
    const std::int64_t number = value->get();
    if (number < std::numeric_limits<int>::min() || number > std::numeric_limits<int>::max()) {
        reader.context().report(*node, reader.path(key),
                                with_unit(describe(*node), unit) + ": must be " + range.describe());
        return;
    }
    out = static_cast<int>(number);
}

void read(TableReader& reader, std::string_view key, bool& out, std::string_view /*unit*/,
          const Range& /*range*/) {
    const toml::node* node = reader.get(key);
    if (node == nullptr) return;
    if (const auto* value = node->as_boolean()) {
        out = value->get();
    } else {
        reader.context().report(*node, reader.path(key),
                                describe(*node) + ": must be true or false");
    }
}

void read(TableReader& reader, std::string_view key, engine::Vec3& out, std::string_view unit,
          const Range& range) {
    const toml::node* node = reader.get(key);
    if (node == nullptr) return;
    const auto* array = node->as_array();
    if (array != nullptr && array->size() == 3) {
        engine::Vec3 value;
        bool numbers = true;
        for (std::size_t i = 0; i < 3 && numbers; ++i) {
            const std::optional<double> component = number_of(*array->get(i));
            numbers = component.has_value();
            if (numbers) value[static_cast<Eigen::Index>(i)] = *component;
        }
        if (numbers) {
            out = value;
            return;
        }
    }
    reader.context().report(
        *node, reader.path(key),
        describe(*node) + ": " + expectation("an array of 3 numbers [x, y, z]", unit, range));
}

void read(TableReader& reader, std::string_view key, std::string& out) {
    const toml::node* node = reader.get(key);
    if (node == nullptr) return;
    if (const auto* value = node->as_string()) {
        out = value->get();
    } else {
        reader.context().report(*node, reader.path(key), describe(*node) + ": must be a string");
    }
}

namespace {

void read_material(TableReader& parent, std::string_view key, engine::Material& material) {
    with_table(parent, key, [&](TableReader& r) { read_fields(r, material, material_fields); });
}

void read_wall_contact(TableReader& r, engine::WallContact& contact) {
    read_enum(r, "model", wall_model_names, contact.model);
    read_enum(r, "hull_model", wall_hull_model_names, contact.hull_model);
    read_fields(r, contact, wall_contact_fields);
}

void read_rock(TableReader& r, engine::RockRelease& rock, RockShapeCache& shape_cache) {
    read(r, "name", rock.name);
    read_rock_spec(r, rock.rock, shape_cache);
    with_table(r, "release", [&](TableReader& s) { read_fields(s, rock.release, release_fields); });
}

}  // namespace

void read_rock_spec(TableReader& r, engine::RockSpec& rock, RockShapeCache& shape_cache) {
    std::array<std::string_view, all_rock_kinds.size()> names;
    for (std::size_t i = 0; i < names.size(); ++i) names[i] = shapes::to_string(all_rock_kinds[i]);
    if (const auto index = read_choice(r, "kind", names)) rock.kind = all_rock_kinds[*index];
    read_fields(r, rock, rock_fields);
    read_rock_shape(r, rock, shape_cache);
    read_material(r, "material", rock.material);
}

void read_slope(TableReader& r, shapes::SlopeSpec& slope) {
    read_fields(r, slope, slope_fields);
    with_table_array(r, "segments", slope.segments, [](TableReader& s, shapes::SlopeSegment& e) {
        read_fields(s, e, segment_fields);
    });
    with_table(r, "side_walls",
               [&](TableReader& s) { read_fields(s, slope.side_walls, side_wall_fields); });
    with_table(r, "bars", [&](TableReader& s) {
        read_fields(s, slope.bars, bar_fields);
        read_segment_list(s, "segments", slope.bars.segments);
    });
    with_table(r, "wall", [&](TableReader& s) { read_fields(s, slope.wall, wall_fields); });
}

engine::Scenario read_scenario(const toml::table& root, const std::string& file, SourceMap& sources,
                               std::vector<ScenarioProblem>& problems) {
    Context context{file, sources, problems};
    engine::Scenario scenario;
    TableReader r(root, "", context);
    // Resolved before reading (scenario_file.cpp); asked for so that it counts as known.
    r.get("extends");
    // Read after the scenario, which gives its defaults (sweep_reader.cpp).
    r.get("sweep");
    read(r, "name", scenario.name);
    read_fields(r, scenario, scenario_fields);
    with_table(r, "slope", [&](TableReader& s) {
        read_slope(s, scenario.slope);
        // Not in read_slope: the soil solver has no terrain meshes or linings.
        read_terrain(s, scenario.slope);
        read_lining(s, scenario.slope);
    });
    with_table(r, "materials", [&](TableReader& s) {
        read_material(s, "slope", scenario.materials.slope);
        read_material(s, "bars", scenario.materials.bars);
        read_material(s, "side_walls", scenario.materials.side_walls);
        read_material(s, "wall", scenario.materials.wall);
    });
    with_table(r, "wall_contact",
               [&](TableReader& s) { read_wall_contact(s, scenario.wall_contact); });
    if (r.contains("wall_cells")) {
        with_table(r, "wall_cells", [&](TableReader& s) {
            read_fields(s, scenario.wall_cells.emplace(), wall_cells_fields);
        });
    }
    RockShapeCache shape_cache;
    with_table_array(r, "rocks", scenario.rocks, [&](TableReader& s, engine::RockRelease& rock) {
        read_rock(s, rock, shape_cache);
    });
    read_cluster(r, scenario, r.contains("rocks"), shape_cache);
    read_list(r, "stations", scenario.stations, "distances (m)",
              [&](const toml::node& item, const std::string& path) -> std::optional<double> {
                  if (std::optional<double> value = number_of(item)) return value;
                  context.report(
                      item, path,
                      describe(item) + ": " + expectation("a number", station_unit, station_range));
                  return std::nullopt;
              });
    with_table(r, "numerics", [&](TableReader& s) {
        read_fields(s, scenario.numerics, numerics_fields);
        read_enum(s, "wall_stepping", wall_stepping_names, scenario.numerics.wall_stepping);
        read_enum(s, "sheet_contact", sheet_contact_names, scenario.numerics.sheet_contact);
    });
    r.finish();
    return scenario;
}

}  // namespace rockfall::scenario::detail
