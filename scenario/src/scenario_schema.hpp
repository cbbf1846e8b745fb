#pragma once
// The scenario file's keys: one list of leaf fields per struct, shared by the reader, the
// validator and the writer, so that each key's name, unit and allowed range are stated once.
// Ranges are the ones documented on the structs (engine/scenario.hpp, shapes/slope.hpp).

#include "scenario/scenario_file.hpp"

#include "engine/scenario.hpp"
#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rockfall::scenario::detail {

inline constexpr double infinity = std::numeric_limits<double>::infinity();

// An interval of allowed values, open or closed at each end; unbounded ends are infinite.
// Non-finite values are never allowed.
struct Range {
    double min = -infinity;
    double max = infinity;
    bool min_open = false;
    bool max_open = false;

    bool contains(double value) const;
    // "in [500, 10000]", "in [0, 0.5)", "> 0", ">= 0" or "finite".
    std::string describe() const;
};

constexpr Range closed(double min, double max) { return {min, max, false, false}; }
constexpr Range half_open(double min, double max) { return {min, max, false, true}; }
constexpr Range positive() { return {0.0, infinity, true, false}; }
constexpr Range non_negative() { return {0.0, infinity, false, false}; }
constexpr Range any_finite() { return {}; }

template <class S>
using Member = std::variant<double S::*, int S::*, bool S::*, engine::Vec3 S::*>;

// One leaf key of a table: a number, integer, boolean or 3-vector member of struct S. For a
// vector the range applies to each component; booleans have no range.
template <class S>
struct Field {
    std::string_view key;
    Member<S> member;
    std::string_view unit;
    Range range;
};

template <class S, std::size_t N>
using Fields = std::array<Field<S>, N>;

inline const Fields<engine::Material, 3> material_fields{{
    {"friction", &engine::Material::friction, "", closed(0.0, 2.0)},
    {"restitution", &engine::Material::restitution, "", closed(0.0, 1.0)},
    {"rolling_resistance", &engine::Material::rolling_resistance, "", closed(0.0, 1.0)},
}};

inline const Fields<shapes::SlopeSpec, 2> slope_fields{{
    {"width", &shapes::SlopeSpec::width, "m", positive()},
    {"thickness", &shapes::SlopeSpec::thickness, "m", positive()},
}};

inline const Fields<shapes::SlopeSegment, 2> segment_fields{{
    {"length", &shapes::SlopeSegment::length, "m", positive()},
    {"angle_deg", &shapes::SlopeSegment::angle_deg, "deg", closed(0.0, 80.0)},
}};

inline const Fields<shapes::SideWalls, 3> side_wall_fields{{
    {"enabled", &shapes::SideWalls::enabled, "", {}},
    {"height", &shapes::SideWalls::height, "m", positive()},
    {"thickness", &shapes::SideWalls::thickness, "m", positive()},
}};

inline const Fields<shapes::AngleBars, 4> bar_fields{{
    {"enabled", &shapes::AngleBars::enabled, "", {}},
    {"leg", &shapes::AngleBars::leg, "m", positive()},
    {"thickness", &shapes::AngleBars::thickness, "m", positive()},
    {"spacing", &shapes::AngleBars::spacing, "m", positive()},
}};

inline const Fields<shapes::ReactionWall, 4> wall_fields{{
    {"enabled", &shapes::ReactionWall::enabled, "", {}},
    {"distance_from_toe", &shapes::ReactionWall::distance_from_toe, "m", positive()},
    {"height", &shapes::ReactionWall::height, "m", positive()},
    {"thickness", &shapes::ReactionWall::thickness, "m", positive()},
}};

inline const Fields<engine::WallContact, 7> wall_contact_fields{{
    {"rock_youngs_modulus", &engine::WallContact::rock_youngs_modulus, "Pa", positive()},
    {"rock_poisson_ratio", &engine::WallContact::rock_poisson_ratio, "", half_open(0.0, 0.5)},
    {"wall_youngs_modulus", &engine::WallContact::wall_youngs_modulus, "Pa", positive()},
    {"wall_poisson_ratio", &engine::WallContact::wall_poisson_ratio, "", half_open(0.0, 0.5)},
    {"linear_stiffness", &engine::WallContact::linear_stiffness, "N/m", non_negative()},
    {"steps_per_contact", &engine::WallContact::steps_per_contact, "", closed(20, 1000)},
    {"corner_roundness", &engine::WallContact::corner_roundness, "", {0.0, 1.0, true, false}},
}};

inline const Fields<engine::PressureCells, 6> wall_cells_fields{{
    {"columns", &engine::PressureCells::columns, "", closed(1, 256)},
    {"rows", &engine::PressureCells::rows, "", closed(1, 256)},
    {"width", &engine::PressureCells::width, "m", positive()},
    {"height", &engine::PressureCells::height, "m", positive()},
    {"capacity", &engine::PressureCells::capacity, "Pa", positive()},
    {"sample_interval", &engine::PressureCells::sample_interval, "s", closed(1e-5, 0.1)},
}};

inline const Fields<engine::RockSpec, 2> rock_fields{{
    {"size", &engine::RockSpec::size, "m", closed(0.01, 10.0)},
    {"density", &engine::RockSpec::density, "kg/m3", closed(500.0, 10000.0)},
}};

// The lateral position's range depends on the slope width and the rock; it is checked with
// the other cross-field rules.
inline const Fields<engine::Release, 7> release_fields{{
    {"distance", &engine::Release::distance, "m", non_negative()},
    {"lateral", &engine::Release::lateral, "m", any_finite()},
    {"height", &engine::Release::height, "m", non_negative()},
    {"velocity", &engine::Release::velocity, "m/s", any_finite()},
    {"spin", &engine::Release::spin, "rad/s", any_finite()},
    {"orientation_deg", &engine::Release::orientation_deg, "deg", any_finite()},
    {"random_orientation", &engine::Release::random_orientation, "", {}},
}};

inline const Fields<engine::Numerics, 8> numerics_fields{{
    {"time_step", &engine::Numerics::time_step, "s", closed(1e-5, 1e-2)},
    {"max_time", &engine::Numerics::max_time, "s", positive()},
    {"rest_speed", &engine::Numerics::rest_speed, "m/s", positive()},
    {"rest_duration", &engine::Numerics::rest_duration, "s", positive()},
    {"restitution_threshold", &engine::Numerics::restitution_threshold, "m/s", closed(0.001, 1.0)},
    {"solver_iterations", &engine::Numerics::solver_iterations, "", closed(1, 100)},
    {"contact_slop", &engine::Numerics::contact_slop, "g dt^2", closed(0.0, 100.0)},
    {"bar_refinement", &engine::Numerics::bar_refinement, "", closed(1, 64)},
}};

inline const Fields<engine::Scenario, 1> scenario_fields{{
    {"gravity", &engine::Scenario::gravity, "m/s2", positive()},
}};

// Unit and range of the list-valued keys.
inline constexpr std::string_view station_unit = "m";
inline constexpr Range station_range = non_negative();

template <class E>
struct EnumName {
    std::string_view name;
    E value;
};

// The name of `value` in `names`, "?" when it has none.
template <typename E, std::size_t N>
constexpr std::string_view name_of(const std::array<EnumName<E>, N>& names, E value) {
    for (const EnumName<E>& entry : names) {
        if (entry.value == value) return entry.name;
    }
    return "?";
}

inline constexpr std::array<EnumName<engine::WallContact::Model>, 2> wall_model_names{{
    {"hertz", engine::WallContact::Model::hertz},
    {"linear", engine::WallContact::Model::linear},
}};

inline constexpr std::array<EnumName<engine::WallContact::HullModel>, 2> wall_hull_model_names{{
    {"sphere", engine::WallContact::HullModel::sphere},
    {"rounded", engine::WallContact::HullModel::rounded},
}};

inline constexpr std::array<EnumName<engine::WallStepping>, 2> wall_stepping_names{{
    {"per_rock", engine::WallStepping::per_rock},
    {"world", engine::WallStepping::world},
}};

inline constexpr std::array<EnumName<engine::SheetContact>, 2> sheet_contact_names{{
    {"structured", engine::SheetContact::structured},
    {"mesh", engine::SheetContact::mesh},
}};

inline constexpr std::array<shapes::RockKind, 3> all_rock_kinds{
    shapes::RockKind::sphere, shapes::RockKind::massive, shapes::RockKind::planar};

// Where a key was written: file and 1-based line (0 when unknown).
struct Location {
    std::string file;
    int line = 0;
};

// Key path -> where it was written, filled by the reader and used to place cross-field
// problems, which concern keys that may have been left out (then their table's line is used).
class SourceMap {
  public:
    void add(std::string path, Location where);
    // The location of `path` or of its closest recorded parent ("a.b[2].c" -> "a.b[2]" ...).
    Location find(std::string_view path) const;

  private:
    std::map<std::string, Location, std::less<>> entries_;
};

// Shortest text that reads back to the same double ("0.1", "2600", "1e-05").
std::string format_number(double value);
// "path[index]", the path of an array element in messages.
inline std::string indexed(std::string_view path, std::size_t index) {
    return std::string(path) + "[" + std::to_string(index) + "]";
}
// "[x, y, z]" with format_number.
std::string format_vector(const engine::Vec3& value);
// A TOML basic string: "text" with quotes, backslashes and control characters escaped.
std::string toml_string(std::string_view text);
// "<value> <unit>" or "<value>" when dimensionless.
std::string with_unit(const std::string& value, std::string_view unit);

// Collects range and cross-field problems of a filled struct as ScenarioProblems.
// The profile alone (segments, width, thickness) without bars, side walls or wall, which may
// be invalid while the profile is valid (they are reported elsewhere): what the checks that
// need a built shapes::Slope may build once the profile's fields are valid.
inline shapes::SlopeSpec profile_only(const shapes::SlopeSpec& slope) {
    shapes::SlopeSpec profile;
    profile.segments = slope.segments;
    profile.width = slope.width;
    profile.thickness = slope.thickness;
    profile.side_walls.enabled = false;
    profile.bars.enabled = false;
    profile.bars.segments.clear();
    profile.wall.enabled = false;
    return profile;
}

class Checker {
  public:
    Checker(const SourceMap* sources, std::vector<ScenarioProblem>& problems)
        : sources_(sources), problems_(problems) {}

    // Records `path = value: rule` at the key's location (or its table's when it is absent).
    void fail(const std::string& path, const std::string& value, const std::string& rule) {
        Location where = sources_ != nullptr ? sources_->find(path) : Location{};
        problems_.push_back({std::move(where.file), where.line, path, value + ": " + rule});
    }

    bool check(const std::string& path, double value, std::string_view unit, const Range& range) {
        if (range.contains(value)) return true;
        fail(path, with_unit(format_number(value), unit),
             std::string(std::isfinite(value) ? "must be " : "must be finite and ") +
                 range.describe());
        return false;
    }

    bool check(const std::string& path, int value, std::string_view unit, const Range& range) {
        if (range.contains(value)) return true;
        fail(path, with_unit(std::to_string(value), unit), "must be " + range.describe());
        return false;
    }

    bool check(const std::string& path, const engine::Vec3& value, std::string_view unit,
               const Range& range) {
        if (std::all_of(value.begin(), value.end(), [&](double c) { return range.contains(c); })) {
            return true;
        }
        fail(path, with_unit(format_vector(value), unit),
             "every component must be " + range.describe());
        return false;
    }

    bool check(const std::string& /*path*/, bool /*value*/, std::string_view /*unit*/,
               const Range& /*range*/) {
        return true;
    }

    // Checks every field of `object` against its range; true when all pass.
    template <class S, std::size_t N>
    bool check_fields(const S& object, const std::string& prefix, const Fields<S, N>& fields) {
        bool ok = true;
        for (const Field<S>& field : fields) {
            const std::string path =
                prefix.empty() ? std::string(field.key) : prefix + "." + std::string(field.key);
            std::visit(
                [&](auto member) { ok &= check(path, object.*member, field.unit, field.range); },
                field.member);
        }
        return ok;
    }

  private:
    const SourceMap* sources_;
    std::vector<ScenarioProblem>& problems_;
};

// Range checks and cross-field rules of a slope (shared with the soil scenario); returns true
// when the profile is valid, so that rules depending on it can run.
bool check_slope(Checker& c, const shapes::SlopeSpec& slope);

// Range checks and cross-field rules for a scenario read from a file or built in code;
// `sources` (may be null) places each problem in the file.
std::vector<ScenarioProblem> find_problems(const engine::Scenario& scenario,
                                           const SourceMap* sources);

}  // namespace rockfall::scenario::detail
