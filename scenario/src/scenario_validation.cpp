// Range checks and cross-field rules, applied to the filled Scenario struct so that scenarios
// built in code are held to the same rules as files.

#include "scenario/scenario_file.hpp"
#include "scenario_cluster.hpp"
#include "scenario_lining.hpp"
#include "scenario_rock_shape.hpp"
#include "scenario_schema.hpp"
#include "scenario_terrain.hpp"

#include "risk/number_text.hpp"
#include "shapes/rocks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <variant>

namespace rockfall::scenario {
namespace detail {

bool Range::contains(double value) const {
    if (!std::isfinite(value)) return false;
    const bool above = min_open ? value > min : value >= min;
    const bool below = max_open ? value < max : value <= max;
    return above && below;
}

std::string Range::describe() const {
    const bool has_min = min > -infinity;
    const bool has_max = max < infinity;
    if (has_min && has_max) {
        return std::string("in ") + (min_open ? "(" : "[") + format_number(min) + ", " +
               format_number(max) + (max_open ? ")" : "]");
    }
    if (has_min) return (min_open ? "> " : ">= ") + format_number(min);
    if (has_max) return (max_open ? "< " : "<= ") + format_number(max);
    return "finite";
}

void SourceMap::add(std::string path, Location where) {
    entries_.insert_or_assign(std::move(path), std::move(where));
}

Location SourceMap::find(std::string_view path) const {
    while (true) {
        if (const auto found = entries_.find(path); found != entries_.end()) return found->second;
        if (path.empty()) return {};
        const std::size_t cut = path.find_last_of(".[");
        path = path.substr(0, cut == std::string_view::npos ? 0 : cut);
    }
}

std::string format_number(double value) {
    std::string text = risk::number_text(value);
    // number_text (std::to_chars) pads exponents to two digits ("1e-05"); people write "1e-5".
    const std::size_t e = text.find('e');
    if (e != std::string::npos) {
        const std::size_t digits = e + 2;
        while (digits + 1 < text.size() && text[digits] == '0') text.erase(digits, 1);
    }
    return text;
}

std::string format_vector(const engine::Vec3& value) {
    return "[" + format_number(value.x()) + ", " + format_number(value.y()) + ", " +
           format_number(value.z()) + "]";
}

std::string toml_string(std::string_view text) {
    std::string out = "\"";
    for (const char c : text) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\t':
                out += "\\t";
                break;
            case '\r':
                out += "\\r";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
                    char escape[8];
                    std::snprintf(escape, sizeof(escape), "\\u%04x", static_cast<unsigned>(c));
                    out += escape;
                } else {
                    out += c;
                }
        }
    }
    return out + "\"";
}

std::string with_unit(const std::string& value, std::string_view unit) {
    return unit.empty() ? value : value + " " + std::string(unit);
}

namespace {

// Facts about a valid profile that the cross-field rules need.
struct Profile {
    // Distance along the surface from the crown to the end of the part a rock may start on:
    // the toe, or the end of the only segment.
    double inclined_length = 0.0;
    // Horizontal length of the last (run-out) segment, m.
    double runout_horizontal = 0.0;
};

constexpr double deg = 3.14159265358979323846 / 180.0;

Profile profile_of(const shapes::SlopeSpec& slope) {
    const std::vector<shapes::SlopeSegment>& segments = slope.segments;
    Profile profile;
    const shapes::SlopeSegment& last = segments.back();
    profile.runout_horizontal = last.length * std::cos(last.angle_deg * deg);
    profile.inclined_length = segments.size() == 1
                                  ? last.length
                                  : std::accumulate(segments.begin(), segments.end() - 1, 0.0,
                                                    [](double sum, const shapes::SlopeSegment& s) {
                                                        return sum + s.length;
                                                    });
    return profile;
}

void check_bars(Checker& c, const shapes::AngleBars& bars, std::size_t segment_count) {
    const bool ok = c.check_fields(bars, "slope.bars", bar_fields);
    if (!bars.enabled) return;
    if (ok && bars.thickness >= bars.leg) {
        c.fail("slope.bars.thickness", format_number(bars.thickness) + " m",
               "must be < the leg (" + format_number(bars.leg) + " m) of an angle profile");
    }
    if (ok && bars.spacing <= bars.leg) {
        c.fail("slope.bars.spacing", format_number(bars.spacing) + " m",
               "must be > the leg (" + format_number(bars.leg) + " m) so that bars do not overlap");
    }
    // Without segments the indices cannot be judged; the empty profile is reported instead.
    for (std::size_t i = 0; i < bars.segments.size() && segment_count > 0; ++i) {
        const int index = bars.segments[i];
        const std::string path = indexed("slope.bars.segments", i);
        if (index < 0 || static_cast<std::size_t>(index) >= segment_count) {
            c.fail(path, std::to_string(index),
                   "must be a segment index in [0, " + std::to_string(segment_count) +
                       ") (0 is the top segment)");
        } else if (std::count(bars.segments.begin(),
                              bars.segments.begin() + static_cast<std::ptrdiff_t>(i), index) > 0) {
            c.fail(path, std::to_string(index), "is listed twice");
        }
    }
}

void check_rock(Checker& c, const engine::Scenario& s, std::size_t index, bool profile_ok) {
    const engine::RockRelease& rock = s.rocks[index];
    const std::string path = indexed("rocks", index);
    const bool geometry_ok = check_rock_spec(c, s, rock.rock, path);
    const bool release_ok = c.check_fields(rock.release, path + ".release", release_fields);
    if (!release_ok || !profile_ok) return;

    const Profile profile = profile_of(s.slope);
    if (rock.release.distance >= profile.inclined_length) {
        c.fail(path + ".release.distance", format_number(rock.release.distance) + " m",
               "must be in [0, " + format_number(profile.inclined_length) +
                   ") so that the rock starts on the inclined part, above the toe");
    }
    if (geometry_ok) {
        const bool custom = rock.rock.kind == shapes::RockKind::custom;
        // The bounding sphere keeps every orientation, random ones included, off the side walls.
        const double radius = rock.rock.geometry().bounding_radius;
        const double half_room = 0.5 * s.slope.width - radius;
        if (half_room < 0.0) {
            c.fail(path + ".size", format_number(rock.rock.size) + " m",
                   "a " +
                       (custom ? "rock '" + rock.rock.shape->name + "'"
                               : std::string(shapes::to_string(rock.rock.kind))) +
                       " this size (bounding radius " + format_number(radius) +
                       " m) is wider than the slope (" + format_number(s.slope.width) + " m)");
        } else if (std::abs(rock.release.lateral) > half_room) {
            c.fail(path + ".release.lateral", format_number(rock.release.lateral) + " m",
                   "must be in [" + format_number(-half_room) + ", " + format_number(half_room) +
                       "] (half the slope width minus the rock's bounding radius " +
                       format_number(radius) + " m)");
        }
    }
}

// Names of named rocks ([[rocks]] and marked cluster rocks) are unique.
void check_rock_names(Checker& c, const engine::Scenario& s) {
    std::vector<std::pair<std::string, std::string>> named;  // name, path
    for (std::size_t i = 0; i < s.rocks.size(); ++i) {
        named.emplace_back(s.rocks[i].name, indexed("rocks", i) + ".name");
    }
    if (s.cluster) {
        for (std::size_t i = 0; i < s.cluster->marked.size(); ++i) {
            named.emplace_back(s.cluster->marked[i].name, indexed("cluster.marked", i) + ".name");
        }
    }
    for (std::size_t i = 0; i < named.size(); ++i) {
        if (named[i].first.empty()) continue;
        for (std::size_t j = 0; j < i; ++j) {
            if (named[j].first == named[i].first) {
                c.fail(named[i].second, "\"" + named[i].first + "\"",
                       "is already the name of " +
                           named[j].second.substr(0, named[j].second.size() - 5) +
                           ": rock names must be unique");
                break;
            }
        }
    }
}

// The pressure cells need the wall, and their grid must fit on its face.
void check_wall_cells(Checker& c, const engine::Scenario& s) {
    if (!s.wall_cells) return;
    const engine::PressureCells& cells = *s.wall_cells;
    if (!c.check_fields(cells, "wall_cells", wall_cells_fields)) return;
    if (!s.slope.wall.enabled) {
        c.fail("wall_cells", "[wall_cells]", "needs the reaction wall (slope.wall.enabled = true)");
        return;
    }
    if (cells.width > s.slope.width) {
        c.fail("wall_cells.width", format_number(cells.width) + " m",
               "must be in (0, " + format_number(s.slope.width) + "] (the slope's width)");
    }
    if (cells.height > s.slope.wall.height) {
        c.fail("wall_cells.height", format_number(cells.height) + " m",
               "must be in (0, " + format_number(s.slope.wall.height) + "] (the wall's height)");
    }
}

}  // namespace

bool check_slope(Checker& c, const shapes::SlopeSpec& slope) {
    bool profile_ok = c.check_fields(slope, "slope", slope_fields);
    if (slope.segments.empty()) {
        c.fail("slope.segments", "[]", "must have at least one segment");
        profile_ok = false;
    }
    for (std::size_t i = 0; i < slope.segments.size(); ++i) {
        profile_ok &=
            c.check_fields(slope.segments[i], indexed("slope.segments", i), segment_fields);
    }
    c.check_fields(slope.side_walls, "slope.side_walls", side_wall_fields);
    check_bars(c, slope.bars, slope.segments.size());
    const bool wall_ok = c.check_fields(slope.wall, "slope.wall", wall_fields);
    if (profile_ok && wall_ok && slope.wall.enabled) {
        const double runout = profile_of(slope).runout_horizontal;
        const double room = runout - slope.wall.thickness;
        if (slope.wall.distance_from_toe > room) {
            c.fail(
                "slope.wall.distance_from_toe", format_number(slope.wall.distance_from_toe) + " m",
                "must be in (0, " + format_number(room) + "] so that the wall (" +
                    format_number(slope.wall.thickness) + " m thick) stands on the last segment (" +
                    format_number(runout) + " m long horizontally)");
        }
    }
    return profile_ok;
}

std::vector<ScenarioProblem> find_problems(const engine::Scenario& s, const SourceMap* sources) {
    std::vector<ScenarioProblem> problems;
    Checker c(sources, problems);
    if (s.name.empty()) c.fail("name", "\"\"", "must not be empty");
    c.check_fields(s, "", scenario_fields);
    const bool profile_ok = check_slope(c, s.slope);
    check_terrain(c, s, profile_ok);
    check_lining(c, s.slope, profile_ok);
    c.check_fields(s.materials.slope, "materials.slope", material_fields);
    c.check_fields(s.materials.bars, "materials.bars", material_fields);
    c.check_fields(s.materials.side_walls, "materials.side_walls", material_fields);
    c.check_fields(s.materials.wall, "materials.wall", material_fields);
    c.check_fields(s.wall_contact, "wall_contact", wall_contact_fields);
    if (s.wall_contact.hull_model == engine::WallContact::HullModel::rounded &&
        s.wall_contact.model != engine::WallContact::Model::hertz) {
        c.fail("wall_contact.hull_model", "\"rounded\"",
               "needs wall_contact.model = \"hertz\" (the rounded corner is a Hertz contact; "
               "its edges and faces have their own linear laws)");
    }
    check_wall_cells(c, s);
    if (s.rocks.empty() && !s.cluster) {
        c.fail("rocks", "[]", "must have at least one rock (or a [cluster])");
    }
    check_cluster(c, s, profile_ok);
    for (std::size_t i = 0; i < s.rocks.size(); ++i) check_rock(c, s, i, profile_ok);
    check_rock_names(c, s);
    for (std::size_t i = 0; i < s.stations.size(); ++i) {
        const std::string path = indexed("stations", i);
        if (c.check(path, s.stations[i], station_unit, station_range) && profile_ok) {
            const double end = profile_of(s.slope).runout_horizontal;
            if (s.stations[i] > end) {
                c.fail(path, format_number(s.stations[i]) + " m",
                       "must be in [0, " + format_number(end) +
                           "] (a station past the end of the run-out is never crossed)");
            }
        }
    }
    c.check_fields(s.numerics, "numerics", numerics_fields);
    return problems;
}

bool check_rock_spec(Checker& c, const engine::Scenario& s, const engine::RockSpec& rock,
                     const std::string& path) {
    const bool size_ok = c.check_fields(rock, path, rock_fields);
    const bool material_ok = c.check_fields(rock.material, path + ".material", material_fields);
    // A custom shape is what makes a rock custom (scenario files set both or neither).
    const bool custom = rock.kind == shapes::RockKind::custom;
    bool shape_ok = true;
    if (custom != (rock.shape != nullptr)) {
        c.fail(path + ".kind", "\"" + std::string(shapes::to_string(rock.kind)) + "\"",
               custom ? "a custom rock needs a shape (mesh, catalogue with entry, or vertices)"
                      : "a rock with a custom shape must be of kind custom");
        shape_ok = false;
    }
    // The compliant wall contact takes its damping from the mean restitution (ln e,
    // docs/scenarios.md).
    const double mean_restitution =
        0.5 * (rock.material.restitution + s.materials.wall.restitution);
    if (material_ok && s.slope.wall.enabled && mean_restitution <= 0.0) {
        c.fail(path + ".material.restitution", format_number(rock.material.restitution),
               "must be > 0 when materials.wall.restitution is 0 (the wall contact's damping "
               "needs a mean restitution > 0)");
    }
    return size_ok && shape_ok;
}

}  // namespace detail

void validate_scenario(const engine::Scenario& scenario) {
    std::vector<ScenarioProblem> problems = detail::find_problems(scenario, nullptr);
    if (!problems.empty()) throw ScenarioError(std::move(problems));
}

}  // namespace rockfall::scenario
