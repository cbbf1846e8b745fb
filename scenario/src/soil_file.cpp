// Soil scenario files: the rock scenario loader's TOML reader, extends handling and range
// checker applied to mpm::SoilScenario, with its own key lists.

#include "scenario/soil_file.hpp"

#include "scenario_reader.hpp"
#include "scenario_schema.hpp"

#include <toml++/toml.h>

#include <array>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace rockfall::scenario {
namespace {

namespace fs = std::filesystem;
using detail::Fields;
using detail::Range;

constexpr Range open_interval(double min, double max) { return {min, max, true, true}; }

// Key lists of the soil tables; ranges are the ones documented on mpm's structs
// (mpm/include/mpm/soil.hpp, material.hpp). Rules between keys are in check_soil.
inline const Fields<mpm::SoilScenario, 1> soil_fields{{
    {"density", &mpm::SoilScenario::density, "kg/m3", detail::positive()},
}};

inline const Fields<mpm::DruckerPrager, 6> soil_material_fields{{
    {"youngs_modulus", &mpm::DruckerPrager::youngs_modulus, "Pa", detail::positive()},
    {"poisson_ratio", &mpm::DruckerPrager::poisson_ratio, "", detail::half_open(0.0, 0.5)},
    {"friction_angle_deg", &mpm::DruckerPrager::friction_angle_deg, "deg",
     detail::closed(0.0, 70.0)},
    {"dilatancy_angle_deg", &mpm::DruckerPrager::dilatancy_angle_deg, "deg",
     detail::closed(0.0, 70.0)},
    {"cohesion", &mpm::DruckerPrager::cohesion, "Pa", detail::non_negative()},
    {"tensile_strength", &mpm::DruckerPrager::tensile_strength, "Pa", detail::non_negative()},
}};

inline const Fields<mpm::SoilRelease, 9> soil_release_fields{{
    {"length", &mpm::SoilRelease::length, "m", detail::positive()},
    {"width", &mpm::SoilRelease::width, "m", detail::positive()},
    {"thickness", &mpm::SoilRelease::thickness, "m", detail::positive()},
    {"bed_angle_deg", &mpm::SoilRelease::bed_angle_deg, "deg", open_interval(0.0, 90.0)},
    {"initial_bed_angle_deg", &mpm::SoilRelease::initial_bed_angle_deg, "deg",
     detail::half_open(0.0, 90.0)},
    {"tilt_duration", &mpm::SoilRelease::tilt_duration, "s", detail::non_negative()},
    {"hinge_offset_x", &mpm::SoilRelease::hinge_offset_x, "m", detail::any_finite()},
    {"hinge_offset_z", &mpm::SoilRelease::hinge_offset_z, "m", detail::any_finite()},
    {"side_board_height", &mpm::SoilRelease::side_board_height, "m", detail::non_negative()},
}};

inline const Fields<mpm::SoilBoundaries, 6> soil_boundary_fields{{
    {"basal_friction_angle_deg", &mpm::SoilBoundaries::basal_friction_angle_deg, "deg",
     detail::closed(0.0, 89.0)},
    {"bed_friction_angle_deg", &mpm::SoilBoundaries::bed_friction_angle_deg, "deg",
     detail::closed(0.0, 89.0)},
    {"wall_fixed", &mpm::SoilBoundaries::wall_fixed, "", {}},
    {"wall_facing_mass", &mpm::SoilBoundaries::wall_facing_mass, "kg/m2", detail::positive()},
    {"wall_stiffness", &mpm::SoilBoundaries::wall_stiffness, "Pa/m", detail::positive()},
    {"wall_damping_ratio", &mpm::SoilBoundaries::wall_damping_ratio, "", detail::closed(0.0, 10.0)},
}};

inline constexpr std::array<detail::EnumName<mpm::WallSupport>, 2> wall_support_names{{
    {"rigid", mpm::WallSupport::rigid},
    {"spring", mpm::WallSupport::spring},
}};

inline const Fields<mpm::SoilNumerics, 10> soil_numerics_fields{{
    {"dimension", &mpm::SoilNumerics::dimension, "", detail::closed(2, 3)},
    {"cell_size", &mpm::SoilNumerics::cell_size, "m", detail::positive()},
    {"particles_per_cell", &mpm::SoilNumerics::particles_per_cell, "", detail::closed(1, 8)},
    {"cfl", &mpm::SoilNumerics::cfl, "", Range{0.0, 1.0, true, false}},
    {"align_grid", &mpm::SoilNumerics::align_grid, "", {}},
    {"boundary_reach", &mpm::SoilNumerics::boundary_reach, "", detail::closed(0.0, 0.5)},
    {"volumetric_averaging", &mpm::SoilNumerics::volumetric_averaging, "", {}},
    {"flip", &mpm::SoilNumerics::flip, "", detail::closed(0.0, 1.0)},
    {"min_density_ratio", &mpm::SoilNumerics::min_density_ratio, "", Range{0.0, 1.0, false, true}},
    {"threads", &mpm::SoilNumerics::threads, "", detail::non_negative()},
}};

inline const Fields<mpm::SoilOutput, 4> soil_output_fields{{
    {"duration", &mpm::SoilOutput::duration, "s", detail::positive()},
    {"sample_interval", &mpm::SoilOutput::sample_interval, "s", detail::positive()},
    {"filter_window", &mpm::SoilOutput::filter_window, "s", detail::non_negative()},
    {"frame_interval", &mpm::SoilOutput::frame_interval, "s", detail::positive()},
}};

inline constexpr std::array<detail::EnumName<mpm::ConeMatch>, 3> cone_match_names{{
    {"plane_strain", mpm::ConeMatch::plane_strain},
    {"compression", mpm::ConeMatch::compression},
    {"extension", mpm::ConeMatch::extension},
}};

void read_soil_material(detail::TableReader& r, mpm::DruckerPrager& material) {
    detail::read_fields(r, material, soil_material_fields);
    std::array<std::string_view, cone_match_names.size()> names;
    for (std::size_t i = 0; i < names.size(); ++i) names[i] = cone_match_names[i].name;
    if (const auto index = detail::read_choice(r, "match", names)) {
        material.match = cone_match_names[*index].value;
    }
}

mpm::SoilScenario read_soil(const toml::table& root, std::string& name, detail::Context& context) {
    using detail::TableReader;
    mpm::SoilScenario scenario;
    TableReader r(root, "", context);
    // Resolved before reading; asked for so that it counts as known.
    r.get("extends");
    detail::read(r, "name", name);
    detail::read_fields(r, scenario, soil_fields);
    detail::with_table(r, "slope", [&](TableReader& s) { detail::read_slope(s, scenario.slope); });
    detail::with_table(r, "material",
                       [&](TableReader& s) { read_soil_material(s, scenario.material); });
    detail::with_table(r, "release", [&](TableReader& s) {
        detail::read_fields(s, scenario.release, soil_release_fields);
    });
    detail::with_table(r, "boundaries", [&](TableReader& s) {
        detail::read_fields(s, scenario.boundaries, soil_boundary_fields);
        detail::read_enum(s, "wall_support", wall_support_names, scenario.boundaries.wall_support);
    });
    detail::with_table(r, "numerics", [&](TableReader& s) {
        detail::read_fields(s, scenario.numerics, soil_numerics_fields);
    });
    detail::with_table(r, "output", [&](TableReader& s) {
        detail::read_fields(s, scenario.output, soil_output_fields);
    });
    r.finish();
    return scenario;
}

// Ranges, then the rules between keys; mpm::validate runs last as a backstop, so that a rule
// the solver adds later is still reported with its key's location.
void check_soil(const mpm::SoilScenario& s, const detail::SourceMap& sources,
                std::vector<ScenarioProblem>& problems) {
    using detail::format_number;
    detail::Checker c(&sources, problems);
    c.check_fields(s, "", soil_fields);
    detail::check_slope(c, s.slope);
    const bool material_ok = c.check_fields(s.material, "material", soil_material_fields);
    if (material_ok && s.material.dilatancy_angle_deg > s.material.friction_angle_deg) {
        c.fail(
            "material.dilatancy_angle_deg", format_number(s.material.dilatancy_angle_deg) + " deg",
            "must be in [0, friction_angle_deg = " + format_number(s.material.friction_angle_deg) +
                " deg]");
    }
    if (material_ok && s.material.friction_angle_deg == 0.0 && s.material.cohesion == 0.0) {
        c.fail("material.cohesion", "0 Pa",
               "must be > 0 when friction_angle_deg = 0 (the soil has no strength otherwise)");
    }
    const bool release_ok = c.check_fields(s.release, "release", soil_release_fields);
    if (release_ok && s.release.initial_bed_angle_deg > s.release.bed_angle_deg) {
        c.fail(
            "release.initial_bed_angle_deg",
            format_number(s.release.initial_bed_angle_deg) + " deg",
            "must be in [0, bed_angle_deg = " + format_number(s.release.bed_angle_deg) + " deg]");
    }
    const bool boundaries_ok = c.check_fields(s.boundaries, "boundaries", soil_boundary_fields);
    if (boundaries_ok && s.boundaries.wall_support == mpm::WallSupport::spring &&
        !s.slope.wall.enabled) {
        c.fail("boundaries.wall_support", "\"spring\"",
               "must be \"rigid\" without a wall (slope.wall.enabled = false)");
    }
    c.check_fields(s.numerics, "numerics", soil_numerics_fields);
    const bool output_ok = c.check_fields(s.output, "output", soil_output_fields);
    if (output_ok && s.output.sample_interval > s.output.duration) {
        c.fail("output.sample_interval", format_number(s.output.sample_interval) + " s",
               "must be in (0, duration = " + format_number(s.output.duration) + " s]");
    }
    if (!problems.empty()) return;
    try {
        mpm::validate(s);
    } catch (const std::invalid_argument& error) {
        // One `field = value unit: must be range` per line.
        std::istringstream lines(error.what());
        for (std::string line; std::getline(lines, line);) {
            const std::size_t equals = line.find(" = ");
            if (equals == std::string::npos) {
                c.fail("", line, "rejected by the soil solver");
                continue;
            }
            const std::string key = line.substr(0, equals);
            const std::string rest = line.substr(equals + 3);
            const std::size_t colon = rest.find(": ");
            if (colon == std::string::npos) {
                c.fail(key, rest, "rejected by the soil solver");
            } else {
                c.fail(key, rest.substr(0, colon), rest.substr(colon + 2));
            }
        }
    }
}

SoilFile parse(std::string_view text, const std::string& source, const fs::path& base_dir,
               std::vector<fs::path> chain) {
    toml::table root = detail::parse_toml(text, source);
    const bool extended = root.contains("extends");
    root = detail::resolve_extends(std::move(root), source, base_dir, chain);

    std::vector<ScenarioProblem> problems;
    detail::SourceMap sources;
    sources.add("", {source, 0});
    detail::Context context{source, sources, problems};
    SoilFile loaded;
    loaded.scenario = read_soil(root, loaded.name, context);
    if (loaded.name.empty()) loaded.name = fs::path(source).stem().string();
    check_soil(loaded.scenario, sources, problems);
    if (!problems.empty()) throw ScenarioError(std::move(problems));
    if (extended) {
        // The merged tables, so that the text stands alone (results databases keep it).
        std::ostringstream merged;
        merged << toml::toml_formatter(root);
        loaded.text = merged.str();
    } else {
        loaded.text = std::string(text);
    }
    return loaded;
}

}  // namespace

SoilFile load_soil_scenario(const fs::path& file) {
    const std::string text = detail::read_text(file, "", 0);
    SoilFile loaded = parse(text, file.string(), file.parent_path(), {fs::weakly_canonical(file)});
    loaded.path = file;
    return loaded;
}

SoilFile parse_soil_scenario(std::string_view text, const std::string& source,
                             const fs::path& base_dir) {
    return parse(text, source, base_dir, {});
}

}  // namespace rockfall::scenario
