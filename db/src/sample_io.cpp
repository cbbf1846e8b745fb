#include "sample_io.hpp"

#include "shapes/rocks.hpp"

#include <array>
#include <cmath>
#include <string>

namespace rockfall::db {
namespace {

constexpr std::array rock_kinds = {shapes::RockKind::sphere, shapes::RockKind::massive,
                                   shapes::RockKind::planar, shapes::RockKind::custom};
constexpr std::array stop_reasons = {engine::StopReason::at_rest, engine::StopReason::left_domain,
                                     engine::StopReason::time_limit,
                                     engine::StopReason::numerical_failure};

// The stored name back to its enum; a name this build does not know means the file was
// written by another program or damaged.
template <class Enum, std::size_t N>
Enum parse_stored(const std::array<Enum, N>& values, const std::string& name,
                  const std::filesystem::path& path, const char* column, std::int64_t sample) {
    for (const Enum value : values) {
        if (to_string(value) == name) return value;
    }
    throw DatabaseError(path.string() + ": " + column + " = '" + name + "' of sample " +
                            std::to_string(sample) +
                            " is not a value this build knows; the file was written by a "
                            "newer rockfall or changed by hand",
                        DatabaseError::Kind::bad_file);
}

// samples.shape: the kind's name for the families; for kind custom, "custom" for the base
// rock's own shape, else the named shape or "generated" (names risk reserves).
constexpr std::string_view base_shape = "custom";
constexpr std::string_view generated_shape = "generated";

std::string shape_text(shapes::RockKind kind, const std::string& shape) {
    if (kind != shapes::RockKind::custom) return std::string(shapes::to_string(kind));
    return shape.empty() ? std::string(base_shape) : shape;
}

// samples.shape or rocks.shape back to SampleInputs::shape.
std::string shape_of(shapes::RockKind kind, const std::string& stored) {
    if (kind != shapes::RockKind::custom) return {};
    return stored == base_shape ? std::string() : stored;
}

engine::Vec3 vec3(const sql::Statement& row, int first) {
    return {row.real(first), row.real(first + 1), row.real(first + 2)};
}

}  // namespace

ResultsDb::Statements::Statements(sqlite3* db, const std::filesystem::path& path)
    : sample(db, path,
             "INSERT INTO samples (sample, seed, zone, kind, size_m, density_kg_m3, mass_kg, "
             "friction, restitution, rolling_resistance, release_distance_m, release_lateral_m, "
             "speed_m_s, spin_rad_s, orientation_x_deg, orientation_y_deg, orientation_z_deg, "
             "shape, sphericity, target_sphericity, shape_seed, rocks) "
             "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
             true),
      rock(db, path,
           "INSERT INTO rocks (sample, rock, origin, kind, shape, size_m, density_kg_m3, mass_kg, "
           "friction, restitution, rolling_resistance) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
           true),
      outcome(db, path,
              "INSERT INTO outcomes (sample, rock, stop_reason, stop_time_s, reach_m, final_x_m, "
              "final_y_m, final_z_m, final_vx_m_s, final_vy_m_s, final_vz_m_s, final_speed_m_s, "
              "max_speed_m_s, max_kinetic_energy_J, max_bounce_height_m, velocity_change, "
              "wall_hits) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
              true),
      station(db, path,
              "INSERT INTO stations (sample, rock, station, distance_from_toe_m, reached, time_s, "
              "speed_m_s, parallel_speed_m_s, angular_speed_rad_s, bounce_height_m, "
              "rolling_coefficient, translational_energy_J, rotational_energy_J) "
              "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
              true),
      impact(
          db, path,
          "INSERT INTO wall_impacts (sample, rock, hit, start_time_s, end_time_s, x_m, y_m, z_m, "
          "impact_speed_m_s, normal_speed_m_s, normal_impulse_N_s, tangential_impulse_N_s, "
          "tangential_impulse_x_N_s, tangential_impulse_y_N_s, tangential_impulse_z_N_s, "
          "vx_before_m_s, vy_before_m_s, vz_before_m_s, vx_after_m_s, vy_after_m_s, "
          "vz_after_m_s, wx_before_rad_s, wy_before_rad_s, wz_before_rad_s, wx_after_rad_s, "
          "wy_after_rad_s, wz_after_rad_s, energy_before_J, energy_after_J, peak_force_N, "
          "peak_time_s) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
          "?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
          true),
      trajectory(db, path,
                 "INSERT INTO trajectories (sample, rock, time_s, x_m, y_m, z_m, vx_m_s, vy_m_s, "
                 "vz_m_s, wx_rad_s, wy_rad_s, wz_rad_s, orientation_w, orientation_x, "
                 "orientation_y, orientation_z, translational_energy_J, rotational_energy_J, "
                 "kinetic_energy_J) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
                 "?)",
                 true) {}

void ResultsDb::Statements::write(const SampleRecord& record) {
    const risk::SampleInputs& in = record.inputs;
    const std::int64_t index = in.index;
    sql::Binder binder(sample);
    binder.integer(index)
        .integer(sql::to_stored(in.seed))
        .integer(static_cast<std::int64_t>(in.zone))
        .text(shapes::to_string(in.kind))
        .real(in.size)
        .real(in.density)
        .real(in.mass)
        .real(in.material.friction)
        .real(in.material.restitution)
        .real(in.material.rolling_resistance)
        .real(in.release_distance)
        .real(in.release_lateral)
        .real(in.speed)
        .real(in.spin)
        .real(in.orientation_deg.x())
        .real(in.orientation_deg.y())
        .real(in.orientation_deg.z())
        .text(shape_text(in.kind, in.shape))
        .real(in.sphericity);
    // A generated rock's target and generator seed rebuild its hull (risk::sample_shape).
    if (in.shape == generated_shape) {
        binder.real(in.target_sphericity).integer(sql::to_stored(in.shape_seed));
    } else {
        binder.null().null();
    }
    binder.integer(static_cast<std::int64_t>(record.rocks.size())).run();
    for (std::size_t rock = 0; rock < record.rocks.size(); ++rock) {
        write_rock(index, static_cast<std::int64_t>(rock), record.rocks[rock]);
    }
}

void ResultsDb::Statements::write_rock(std::int64_t index, std::int64_t rock_index,
                                       const risk::RockResult& result) {
    const risk::RockInputs& in = result.inputs;
    sql::Binder(rock)
        .integer(index)
        .integer(rock_index)
        .text(in.cluster ? "cluster" : "rocks")
        .text(shapes::to_string(in.kind))
        .text(shape_text(in.kind, in.shape))
        .real(in.size)
        .real(in.density)
        .real(in.mass)
        .real(in.material.friction)
        .real(in.material.restitution)
        .real(in.material.rolling_resistance)
        .run();
    const engine::RockOutcome& out = result.outcome;

    const engine::RockState& final_state = out.final_state;
    sql::Binder(outcome)
        .integer(index)
        .integer(rock_index)
        .text(engine::to_string(out.stop))
        .real(out.stop_time)
        .real(out.reach)
        .real(final_state.position.x())
        .real(final_state.position.y())
        .real(final_state.position.z())
        .real(final_state.velocity.x())
        .real(final_state.velocity.y())
        .real(final_state.velocity.z())
        .real(final_state.velocity.norm())
        .real(out.max_speed)
        .real(out.max_kinetic_energy)
        .real(out.max_bounce_height)
        .real(out.velocity_change)
        .integer(static_cast<std::int64_t>(out.wall_hits.size()))
        .run();

    for (std::size_t i = 0; i < out.stations.size(); ++i) {
        const engine::StationCrossing& s = out.stations[i];
        // A station not reached has no crossing values (outcome.hpp); NULL keeps them out of
        // SQL aggregates such as AVG(speed_m_s).
        sql::Binder(station)
            .integer(index)
            .integer(rock_index)
            .integer(static_cast<std::int64_t>(i + 1))
            .real(s.distance_from_toe)
            .integer(s.reached ? 1 : 0)
            .real_if(s.reached, s.time)
            .real_if(s.reached, s.speed)
            .real_if(s.reached, s.parallel_speed)
            .real_if(s.reached, s.angular_speed)
            .real_if(s.reached, s.bounce_height)
            .real_if(s.reached, s.rolling_coefficient)
            .real_if(s.reached, s.translational_energy)
            .real_if(s.reached, s.rotational_energy)
            .run();
    }

    for (std::size_t i = 0; i < out.wall_hits.size(); ++i) {
        const engine::WallHit& h = out.wall_hits[i];
        sql::Binder(impact)
            .integer(index)
            .integer(rock_index)
            .integer(static_cast<std::int64_t>(i + 1))
            .real(h.start_time)
            .real(h.end_time)
            .real(h.point.x())
            .real(h.point.y())
            .real(h.point.z())
            .real(h.velocity_before.norm())
            .real(h.normal_speed)
            .real(h.normal_impulse)
            .real(h.tangential_impulse.norm())
            .real(h.tangential_impulse.x())
            .real(h.tangential_impulse.y())
            .real(h.tangential_impulse.z())
            .real(h.velocity_before.x())
            .real(h.velocity_before.y())
            .real(h.velocity_before.z())
            .real(h.velocity_after.x())
            .real(h.velocity_after.y())
            .real(h.velocity_after.z())
            .real(h.angular_velocity_before.x())
            .real(h.angular_velocity_before.y())
            .real(h.angular_velocity_before.z())
            .real(h.angular_velocity_after.x())
            .real(h.angular_velocity_after.y())
            .real(h.angular_velocity_after.z())
            .real(h.energy_before)
            .real(h.energy_after)
            .real(h.peak_normal_force)
            .real(h.peak_time)
            .run();
    }

    for (const engine::RockState& s : result.trajectory) {
        sql::Binder(trajectory)
            .integer(index)
            .integer(rock_index)
            .real(s.time)
            .real(s.position.x())
            .real(s.position.y())
            .real(s.position.z())
            .real(s.velocity.x())
            .real(s.velocity.y())
            .real(s.velocity.z())
            .real(s.angular_velocity.x())
            .real(s.angular_velocity.y())
            .real(s.angular_velocity.z())
            .real(s.orientation.w())
            .real(s.orientation.x())
            .real(s.orientation.y())
            .real(s.orientation.z())
            .real(s.translational_energy)
            .real(s.rotational_energy)
            .real(s.translational_energy + s.rotational_energy)
            .run();
    }
}

std::optional<SampleRecord> read_sample(sqlite3* db, const std::filesystem::path& path,
                                        std::int64_t index) {
    sql::Statement inputs(db, path,
                          "SELECT seed, zone, kind, size_m, density_kg_m3, mass_kg, friction, "
                          "restitution, rolling_resistance, release_distance_m, "
                          "release_lateral_m, speed_m_s, spin_rad_s, orientation_x_deg, "
                          "orientation_y_deg, orientation_z_deg, shape, sphericity, "
                          "target_sphericity, shape_seed FROM samples WHERE sample = ?");
    inputs.bind_int(1, index);
    if (!inputs.step()) return std::nullopt;
    SampleRecord record;
    risk::SampleInputs& in = record.inputs;
    in.index = index;
    in.seed = sql::from_stored(inputs.integer(0));
    in.zone = static_cast<std::size_t>(inputs.integer(1));
    in.kind = parse_stored(rock_kinds, inputs.text(2), path, "samples.kind", index);
    in.size = inputs.real(3);
    in.density = inputs.real(4);
    in.mass = inputs.real(5);
    in.material = {inputs.real(6), inputs.real(7), inputs.real(8)};
    in.release_distance = inputs.real(9);
    in.release_lateral = inputs.real(10);
    in.speed = inputs.real(11);
    in.spin = inputs.real(12);
    in.orientation_deg = vec3(inputs, 13);
    in.shape = shape_of(in.kind, inputs.text(16));
    in.sphericity = inputs.real(17);
    if (in.shape == generated_shape) {
        in.target_sphericity = inputs.real(18);
        in.shape_seed = sql::from_stored(inputs.integer(19));
    }

    sql::Statement rocks(db, path,
                         "SELECT origin, kind, shape, size_m, density_kg_m3, mass_kg, friction, "
                         "restitution, rolling_resistance FROM rocks WHERE sample = ? "
                         "ORDER BY rock");
    rocks.bind_int(1, index);
    while (rocks.step()) {
        risk::RockInputs& rock = record.rocks.emplace_back().inputs;
        rock.cluster = rocks.text(0) == "cluster";
        rock.kind = parse_stored(rock_kinds, rocks.text(1), path, "rocks.kind", index);
        rock.shape = shape_of(rock.kind, rocks.text(2));
        rock.size = rocks.real(3);
        rock.density = rocks.real(4);
        rock.mass = rocks.real(5);
        rock.material = {rocks.real(6), rocks.real(7), rocks.real(8)};
    }
    if (record.rocks.empty()) return std::nullopt;
    for (std::size_t rock = 0; rock < record.rocks.size(); ++rock) {
        if (!read_rock(db, path, index, static_cast<std::int64_t>(rock), record.rocks[rock])) {
            return std::nullopt;
        }
    }
    return record;
}

engine::StationCrossing station_from(const sql::Statement& row, int first) {
    engine::StationCrossing s;
    s.distance_from_toe = row.real(first);
    s.reached = row.integer(first + 1) != 0;
    if (!s.reached) return s;
    s.time = row.real(first + 2);
    s.speed = row.real(first + 3);
    s.parallel_speed = row.real(first + 4);
    s.angular_speed = row.real(first + 5);
    s.bounce_height = row.real(first + 6);
    s.rolling_coefficient = row.real(first + 7);
    s.translational_energy = row.real(first + 8);
    s.rotational_energy = row.real(first + 9);
    return s;
}

bool read_rock(sqlite3* db, const std::filesystem::path& path, std::int64_t index,
               std::int64_t rock, risk::RockResult& result) {
    sql::Statement outcome(db, path,
                           "SELECT stop_reason, stop_time_s, reach_m, final_x_m, final_y_m, "
                           "final_z_m, final_vx_m_s, final_vy_m_s, final_vz_m_s, max_speed_m_s, "
                           "max_kinetic_energy_J, max_bounce_height_m, velocity_change "
                           "FROM outcomes WHERE sample = ? AND rock = ?");
    outcome.bind_int(1, index);
    outcome.bind_int(2, rock);
    if (!outcome.step()) return false;
    engine::RockOutcome& out = result.outcome;
    out.size = result.inputs.size;
    out.stop = parse_stored(stop_reasons, outcome.text(0), path, "outcomes.stop_reason", index);
    out.stop_time = outcome.real(1);
    out.reach = outcome.real(2);
    out.final_state.time = out.stop_time;
    out.final_state.position = vec3(outcome, 3);
    out.final_state.velocity = vec3(outcome, 6);
    out.max_speed = outcome.real(9);
    out.max_kinetic_energy = outcome.real(10);
    out.max_bounce_height = outcome.real(11);
    out.velocity_change = outcome.real(12);

    sql::Statement stations(db, path,
                            std::string("SELECT ") + station_columns +
                                " FROM stations WHERE sample = ? AND rock = ? ORDER BY station");
    stations.bind_int(1, index);
    stations.bind_int(2, rock);
    while (stations.step()) out.stations.push_back(station_from(stations, 0));

    sql::Statement impacts(
        db, path,
        "SELECT start_time_s, end_time_s, x_m, y_m, z_m, normal_speed_m_s, normal_impulse_N_s, "
        "tangential_impulse_x_N_s, tangential_impulse_y_N_s, tangential_impulse_z_N_s, "
        "vx_before_m_s, vy_before_m_s, vz_before_m_s, vx_after_m_s, vy_after_m_s, vz_after_m_s, "
        "wx_before_rad_s, wy_before_rad_s, wz_before_rad_s, wx_after_rad_s, wy_after_rad_s, "
        "wz_after_rad_s, energy_before_J, energy_after_J, peak_force_N, peak_time_s "
        "FROM wall_impacts WHERE sample = ? AND rock = ? ORDER BY hit");
    impacts.bind_int(1, index);
    impacts.bind_int(2, rock);
    while (impacts.step()) {
        engine::WallHit& h = out.wall_hits.emplace_back();
        h.start_time = impacts.real(0);
        h.end_time = impacts.real(1);
        h.point = vec3(impacts, 2);
        h.normal_speed = impacts.real(5);
        h.normal_impulse = impacts.real(6);
        h.tangential_impulse = vec3(impacts, 7);
        h.velocity_before = vec3(impacts, 10);
        h.velocity_after = vec3(impacts, 13);
        h.angular_velocity_before = vec3(impacts, 16);
        h.angular_velocity_after = vec3(impacts, 19);
        h.energy_before = impacts.real(22);
        h.energy_after = impacts.real(23);
        h.peak_normal_force = impacts.real(24);
        h.peak_time = impacts.real(25);
    }

    sql::Statement trajectory(db, path,
                              "SELECT time_s, x_m, y_m, z_m, vx_m_s, vy_m_s, vz_m_s, wx_rad_s, "
                              "wy_rad_s, wz_rad_s, orientation_w, orientation_x, orientation_y, "
                              "orientation_z, translational_energy_J, rotational_energy_J "
                              "FROM trajectories WHERE sample = ? AND rock = ? ORDER BY time_s");
    trajectory.bind_int(1, index);
    trajectory.bind_int(2, rock);
    while (trajectory.step()) {
        engine::RockState& s = result.trajectory.emplace_back();
        s.time = trajectory.real(0);
        s.position = vec3(trajectory, 1);
        s.velocity = vec3(trajectory, 4);
        s.angular_velocity = vec3(trajectory, 7);
        s.orientation = Eigen::Quaterniond(trajectory.real(10), trajectory.real(11),
                                           trajectory.real(12), trajectory.real(13));
        s.translational_energy = trajectory.real(14);
        s.rotational_energy = trajectory.real(15);
    }
    return true;
}

}  // namespace rockfall::db
