// A soil flow in a results database: written whole in one transaction, read back for queries.

#include "db/soil_run.hpp"

#include "create_file.hpp"
#include "file_checks.hpp"
#include "sqlite.hpp"

#include <array>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>

namespace rockfall::db {
namespace {

namespace fs = std::filesystem;
using Kind = DatabaseError::Kind;

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

constexpr std::array outcomes = {"completed", "left_domain", "non_finite"};

// Binds an extensive quantity into its pair of columns (plain, per metre of width): the plain
// column in 3D, the per-metre column in 2D, NULL in the other.
void bind_extensive(sql::Binder& binder, double value, bool per_metre) {
    if (per_metre) {
        binder.null().real(value);
    } else {
        binder.real(value).null();
    }
}

// Reads the pair of columns bound by bind_extensive, starting at `first`.
double read_extensive(const sql::Statement& row, int first, bool per_metre) {
    return row.real(per_metre ? first + 1 : first);
}

void insert_summary(sqlite3* db, const fs::path& path, const SoilRunRecord& r, bool per_metre) {
    sql::Statement insert(
        db, path,
        "INSERT INTO soil_run (id, dimension, outcome, message, particles, steps, cell_size_m, "
        "mass_kg, mass_kg_per_m, simulated_time_s, runtime_s, wall_distance_from_toe_m, "
        "sample_interval_s, filter_window_s, peak_force_x_N, peak_force_x_N_per_m, peak_time_s, "
        "peak_force_x_filtered_N, peak_force_x_filtered_N_per_m, peak_force_x_step_N, "
        "peak_force_x_step_N_per_m, impulse_x_N_s, impulse_x_N_s_per_m, runout_x_m, "
        "runout_past_toe_m) "
        "VALUES (1, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    sql::Binder binder(insert);
    binder.integer(r.dimension).text(r.outcome).text(r.message).integer(r.particles);
    binder.integer(r.steps).real(r.cell_size);
    bind_extensive(binder, r.mass, per_metre);
    binder.real(r.simulated_time).real(r.runtime).real(r.wall_distance_from_toe);
    binder.real(r.sample_interval).real(r.filter_window);
    bind_extensive(binder, r.peak_force, per_metre);
    binder.real(r.peak_time);
    bind_extensive(binder, r.peak_force_filtered, per_metre);
    bind_extensive(binder, r.peak_force_step, per_metre);
    bind_extensive(binder, r.impulse, per_metre);
    binder.real(r.runout_x).real(r.runout_past_toe).run();
}

// Forces in the soil tables' column order: the plain columns x, y, z of every force, then the
// per-metre columns x, z of every force; the plain ones filled in 3D, the per-metre ones in 2D
// (y is not part of a plane-strain section), NULL in the other.
void bind_forces(sql::Binder& binder, std::initializer_list<SceneVector> forces, bool per_metre) {
    for (const SceneVector& f : forces) {
        if (per_metre) {
            binder.null().null().null();
        } else {
            binder.real(f[0]).real(f[1]).real(f[2]);
        }
    }
    for (const SceneVector& f : forces) {
        if (per_metre) {
            binder.real(f[0]).real(f[2]);
        } else {
            binder.null().null();
        }
    }
}

void insert_histories(sqlite3* db, const fs::path& path, const SoilRunRecord& r, bool per_metre) {
    sql::Statement load(db, path,
                        "INSERT INTO soil_load (time_s, force_x_N, force_y_N, force_z_N, "
                        "force_x_filtered_N, force_y_filtered_N, force_z_filtered_N, "
                        "force_x_N_per_m, force_z_N_per_m, force_x_filtered_N_per_m, "
                        "force_z_filtered_N_per_m) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                        true);
    for (const SoilLoadSample& s : r.load) {
        sql::Binder binder(load);
        binder.real(s.time);
        bind_forces(binder, {s.force, s.force_filtered}, per_metre);
        binder.run();
    }
    sql::Statement step(db, path,
                        "INSERT INTO soil_load_steps (step, time_s, dt_s, force_x_N, force_y_N, "
                        "force_z_N, force_x_N_per_m, force_z_N_per_m) "
                        "VALUES (?, ?, ?, ?, ?, ?, ?, ?)",
                        true);
    std::int64_t index = 0;
    for (const SoilStepLoad& s : r.step_load) {
        sql::Binder binder(step);
        binder.integer(++index).real(s.time).real(s.dt);
        bind_forces(binder, {s.force}, per_metre);
        binder.run();
    }
    sql::Statement motion(db, path,
                          "INSERT INTO soil_motion (time_s, centre_x_m, centre_y_m, centre_z_m, "
                          "front_x_m, kinetic_energy_J, kinetic_energy_J_per_m) "
                          "VALUES (?, ?, ?, ?, ?, ?, ?)",
                          true);
    for (const SoilMotionSample& s : r.motion) {
        sql::Binder binder(motion);
        binder.real(s.time).real(s.centre_of_mass[0]);
        binder.real(per_metre ? nan : s.centre_of_mass[1]).real(s.centre_of_mass[2]);
        binder.real(s.front_x);
        bind_extensive(binder, s.kinetic_energy, per_metre);
        binder.run();
    }
    sql::Statement deposit(db, path, "INSERT INTO soil_deposit (x_m, height_m) VALUES (?, ?)",
                           true);
    for (const SoilDepositBin& bin : r.deposit) {
        sql::Binder(deposit).real(bin.x).real(bin.height).run();
    }
}

// A force read back: x, y, z from the plain columns at `plain` in 3D, x and z from the
// per-metre columns at `per_m` in 2D (y NaN).
SceneVector read_force(const sql::Statement& row, int plain, int per_m, bool per_metre) {
    if (per_metre) return {row.real(per_m), nan, row.real(per_m + 1)};
    return {row.real(plain), row.real(plain + 1), row.real(plain + 2)};
}

[[noreturn]] void damaged(const fs::path& path, const std::string& what) {
    throw DatabaseError(
        path.string() + ": " + what + "; the file is damaged or was changed by hand",
        Kind::bad_file);
}

void read_summary(const ResultsDb& db, SoilRunRecord& r) {
    sql::Statement row(
        db.handle(), db.path(),
        "SELECT dimension, outcome, message, particles, steps, cell_size_m, mass_kg, "
        "mass_kg_per_m, simulated_time_s, runtime_s, wall_distance_from_toe_m, sample_interval_s, "
        "filter_window_s, peak_force_x_N, peak_force_x_N_per_m, peak_time_s, "
        "peak_force_x_filtered_N, peak_force_x_filtered_N_per_m, peak_force_x_step_N, "
        "peak_force_x_step_N_per_m, impulse_x_N_s, impulse_x_N_s_per_m, runout_x_m, "
        "runout_past_toe_m FROM soil_run WHERE id = 1");
    if (!row.step()) damaged(db.path(), "the soil flow's row in soil_run is missing");
    r.dimension = static_cast<int>(row.integer(0));
    const bool per_metre = r.dimension == 2;
    r.outcome = row.text(1);
    r.message = row.text(2);
    r.particles = row.integer(3);
    r.steps = row.integer(4);
    r.cell_size = row.real(5);
    r.mass = read_extensive(row, 6, per_metre);
    r.simulated_time = row.real(8);
    r.runtime = row.real(9);
    r.wall_distance_from_toe = row.real(10);
    r.sample_interval = row.real(11);
    r.filter_window = row.real(12);
    r.peak_force = read_extensive(row, 13, per_metre);
    r.peak_time = row.real(15);
    r.peak_force_filtered = read_extensive(row, 16, per_metre);
    r.peak_force_step = read_extensive(row, 18, per_metre);
    r.impulse = read_extensive(row, 20, per_metre);
    r.runout_x = row.real(22);
    r.runout_past_toe = row.real(23);
}

void read_histories(const ResultsDb& db, SoilRunRecord& r) {
    const bool per_metre = r.dimension == 2;
    sql::Statement load(db.handle(), db.path(),
                        "SELECT time_s, force_x_N, force_y_N, force_z_N, force_x_filtered_N, "
                        "force_y_filtered_N, force_z_filtered_N, force_x_N_per_m, "
                        "force_z_N_per_m, force_x_filtered_N_per_m, force_z_filtered_N_per_m "
                        "FROM soil_load ORDER BY time_s");
    while (load.step()) {
        r.load.push_back(
            {load.real(0), read_force(load, 1, 7, per_metre), read_force(load, 4, 9, per_metre)});
    }
    sql::Statement step(db.handle(), db.path(),
                        "SELECT time_s, dt_s, force_x_N, force_y_N, force_z_N, force_x_N_per_m, "
                        "force_z_N_per_m FROM soil_load_steps ORDER BY step");
    while (step.step()) {
        r.step_load.push_back({step.real(0), step.real(1), read_force(step, 2, 5, per_metre)});
    }
    sql::Statement motion(db.handle(), db.path(),
                          "SELECT time_s, centre_x_m, centre_y_m, centre_z_m, front_x_m, "
                          "kinetic_energy_J, kinetic_energy_J_per_m FROM soil_motion "
                          "ORDER BY time_s");
    while (motion.step()) {
        r.motion.push_back({motion.real(0),
                            {motion.real(1), motion.real(2), motion.real(3)},
                            motion.real(4),
                            read_extensive(motion, 5, per_metre)});
    }
    sql::Statement deposit(db.handle(), db.path(),
                           "SELECT x_m, height_m FROM soil_deposit ORDER BY x_m");
    while (deposit.step()) r.deposit.push_back({deposit.real(0), deposit.real(1)});
}

}  // namespace

void check_new_database(const fs::path& path) { require_creatable(path); }

void write_soil_run(const fs::path& path, const SoilRunRecord& record) {
    // Bad values are the caller's bug, not the user's: the schema's CHECKs would reject them
    // with a less helpful message.
    if (record.dimension != 2 && record.dimension != 3) {
        throw std::invalid_argument("soil run dimension " + std::to_string(record.dimension) +
                                    ": must be 2 or 3");
    }
    const bool per_metre = record.dimension == 2;
    create_database_file(path, record.run, RunKind::soil_flow, [&](sqlite3* db) {
        insert_summary(db, path, record, per_metre);
        insert_histories(db, path, record, per_metre);
    });
}

SoilRunRecord read_soil_run(const ResultsDb& db) {
    if (db.kind() != RunKind::soil_flow) {
        throw DatabaseError(db.path().string() + " holds " + held_by(db.kind()) +
                                ", not a soil flow: give a database written by `rockfall soil "
                                "--db`",
                            Kind::bad_file);
    }
    SoilRunRecord record;
    record.run = db.run();
    read_summary(db, record);
    if (record.dimension != 2 && record.dimension != 3) {
        damaged(db.path(), "soil_run.dimension = " + std::to_string(record.dimension));
    }
    bool known = false;
    for (const char* name : outcomes) known = known || record.outcome == name;
    if (!known) damaged(db.path(), "soil_run.outcome = '" + record.outcome + "'");
    read_histories(db, record);
    return record;
}

}  // namespace rockfall::db
