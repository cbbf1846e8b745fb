// A calibration experiment in a results database: written whole in one transaction, read back
// for queries and tests.

#include "db/calibration_run.hpp"

#include "create_file.hpp"
#include "file_checks.hpp"
#include "sqlite.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rockfall::db {
namespace {

namespace fs = std::filesystem;
using Kind = DatabaseError::Kind;

constexpr std::array heap_statuses = {engine::HeapStatus::at_rest, engine::HeapStatus::time_limit,
                                      engine::HeapStatus::overflow,
                                      engine::HeapStatus::numerical_failure};

bool is_calibration(RunKind kind) {
    return kind == RunKind::drop_test || kind == RunKind::heap_test;
}

[[noreturn]] void damaged(const fs::path& path, const std::string& what) {
    throw DatabaseError(
        path.string() + ": " + what + "; the file is damaged or was changed by hand",
        Kind::bad_file);
}

// A summary's columns in the tables' order: count, mean, sd, (p5, p50, p95 when `percentiles`),
// the interval of the mean.
void bind_summary(sql::Binder& binder, const risk::SampleSummary& s, bool percentiles) {
    binder.integer(s.count).real(s.mean).real(s.standard_deviation);
    if (percentiles) binder.real(s.p5).real(s.p50).real(s.p95);
    binder.real(s.mean_interval.lower).real(s.mean_interval.upper);
}

risk::SampleSummary read_summary(const sql::Statement& row, int first, bool percentiles) {
    risk::SampleSummary s;
    s.count = row.integer(first);
    s.mean = row.real(first + 1);
    s.standard_deviation = row.real(first + 2);
    int at = first + 3;
    if (percentiles) {
        s.p5 = row.real(at);
        s.p50 = row.real(at + 1);
        s.p95 = row.real(at + 2);
        at += 3;
    }
    s.mean_interval = {row.real(at), row.real(at + 1)};
    return s;
}

void insert_shape(sqlite3* db, const fs::path& path, std::int64_t index,
                  const CalibrationShape& shape) {
    sql::Statement insert(
        db, path,
        "INSERT INTO calibration_shapes (shape, label, kind, size_m, "
        "density_kg_m3, sphericity, rock_friction, rock_restitution, "
        "rock_rolling_resistance, surface_friction, surface_restitution, "
        "surface_rolling_resistance) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    sql::Binder binder(insert);
    binder.integer(index).text(shape.label).text(shape.kind).real(shape.size);
    binder.real(shape.density).real(shape.sphericity);
    for (const engine::Material* m : {&shape.rock, &shape.surface}) {
        binder.real(m->friction).real(m->restitution).real(m->rolling_resistance);
    }
    binder.run();
}

void insert_identified(sqlite3* db, const fs::path& path, std::int64_t index,
                       const CalibrationIdentified& id) {
    sql::Statement insert(db, path,
                          "INSERT INTO calibration_identified (shape, parameter, measure, target, "
                          "value, contact_value, achieved_count, achieved_mean, achieved_sd, "
                          "achieved_mean_lower, achieved_mean_upper, consistent_lower, "
                          "consistent_upper) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    sql::Binder binder(insert);
    binder.integer(index).text(id.parameter).text(id.measure).real(id.target).real(id.value);
    binder.real(id.contact_value);
    bind_summary(binder, id.achieved, false);
    binder.real(id.consistent.lower).real(id.consistent.upper).run();
    sql::Statement point(db, path,
                         "INSERT INTO calibration_curve (shape, parameter_value, refinement, "
                         "contact_value, count, mean, sd, p5, p50, p95, mean_lower, mean_upper) "
                         "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                         true);
    for (const CalibrationCurvePoint& p : id.curve) {
        sql::Binder row(point);
        row.integer(index).real(p.parameter).integer(p.refinement ? 1 : 0).real(p.contact_value);
        bind_summary(row, p.measure, true);
        row.run();
    }
}

void insert_drops(sqlite3* db, const fs::path& path, std::int64_t index,
                  const std::vector<risk::DropMeasurement>& drops) {
    sql::Statement insert(
        db, path,
        "INSERT INTO drop_tests (shape, drop_index, seed, rebounded, mass_kg, drop_height_m, "
        "rebound_height_m, approach_speed_m_s, rebound_speed_m_s, normal_impulse_N_s, "
        "first_impulse_N_s, compression_impulse_N_s, restitution_impulse_N_s, energy_before_J, "
        "energy_after_J, cor_height, cor_speed, cor_kinetic, cor_energy) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
        true);
    for (const risk::DropMeasurement& m : drops) {
        sql::Binder binder(insert);
        binder.integer(index).integer(m.index).integer(static_cast<std::int64_t>(m.seed));
        binder.integer(m.rebounded ? 1 : 0).real(m.mass).real(m.drop_height);
        binder.real(m.rebound_height).real(m.approach_speed).real(m.rebound_speed);
        binder.real(m.normal_impulse).real(m.first_impulse).real(m.compression_impulse);
        binder.real(m.restitution_impulse).real(m.energy_before).real(m.energy_after);
        binder.real(m.cor_height).real(m.cor_speed).real(m.cor_kinetic).real(m.cor_energy);
        binder.run();
    }
}

void insert_heaps(sqlite3* db, const fs::path& path, std::int64_t index,
                  const std::vector<CalibrationHeap>& heaps) {
    sql::Statement heap(db, path,
                        "INSERT INTO heap_tests (shape, rock_friction, heap, seed, status, rocks, "
                        "rolled_off, fill_height_m, fill_time_s, lift_time_s, settle_time_s, "
                        "heap_height_m, foot_radius_m, angle_deg, angle_sd_deg, valid_planes) "
                        "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                        true);
    sql::Statement plane(db, path,
                         "INSERT INTO heap_planes (shape, rock_friction, heap, plane, "
                         "azimuth_deg, valid, angle_deg, fitted_points, heap_height_m, "
                         "foot_radius_m) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                         true);
    for (const CalibrationHeap& h : heaps) {
        const risk::HeapMeasurement& m = h.heap;
        sql::Binder binder(heap);
        binder.integer(index).real(h.rock_friction).integer(m.index);
        binder.integer(static_cast<std::int64_t>(m.seed)).text(engine::to_string(m.status));
        binder.integer(m.rocks).integer(m.rolled_off).real(m.fill_height).real(m.fill_time);
        binder.real(m.lift_time).real(m.settle_time).real(m.heap_height).real(m.foot_radius);
        binder.real(m.angle_deg).real(m.angle_sd_deg).integer(m.valid_planes).run();
        for (std::size_t k = 0; k < m.planes.size(); ++k) {
            const risk::HeapProfile& p = m.planes[k];
            sql::Binder row(plane);
            row.integer(index).real(h.rock_friction).integer(m.index);
            row.integer(static_cast<std::int64_t>(k)).real(p.azimuth_deg).integer(p.valid ? 1 : 0);
            row.real(p.angle_deg).integer(p.fitted_points).real(p.heap_height);
            row.real(p.foot_radius).run();
        }
    }
}

std::vector<CalibrationShape> read_shapes(const ResultsDb& db) {
    std::vector<CalibrationShape> shapes;
    sql::Statement row(db.handle(), db.path(),
                       "SELECT shape, label, kind, size_m, density_kg_m3, sphericity, "
                       "rock_friction, rock_restitution, rock_rolling_resistance, "
                       "surface_friction, surface_restitution, surface_rolling_resistance "
                       "FROM calibration_shapes ORDER BY shape");
    while (row.step()) {
        if (row.integer(0) != static_cast<std::int64_t>(shapes.size())) {
            damaged(db.path(), "calibration_shapes.shape " + std::to_string(row.integer(0)) +
                                   " where " + std::to_string(shapes.size()) + " was expected");
        }
        CalibrationShape& s = shapes.emplace_back();
        s.label = row.text(1);
        s.kind = row.text(2);
        s.size = row.real(3);
        s.density = row.real(4);
        s.sphericity = row.real(5);
        s.rock = {row.real(6), row.real(7), row.real(8)};
        s.surface = {row.real(9), row.real(10), row.real(11)};
    }
    return shapes;
}

// The shape a row of a per-shape table names, checked against those read.
CalibrationShape& shape_of(std::vector<CalibrationShape>& shapes, const ResultsDb& db,
                           std::int64_t shape, const char* table) {
    if (shape < 0 || shape >= static_cast<std::int64_t>(shapes.size())) {
        damaged(db.path(), std::string(table) + " names shape " + std::to_string(shape) +
                               " but calibration_shapes has " + std::to_string(shapes.size()));
    }
    return shapes[static_cast<std::size_t>(shape)];
}

void read_identified(const ResultsDb& db, std::vector<CalibrationShape>& shapes) {
    sql::Statement row(db.handle(), db.path(),
                       "SELECT shape, parameter, measure, target, value, contact_value, "
                       "achieved_count, achieved_mean, achieved_sd, achieved_mean_lower, "
                       "achieved_mean_upper, consistent_lower, consistent_upper "
                       "FROM calibration_identified ORDER BY shape");
    while (row.step()) {
        CalibrationIdentified& id =
            shape_of(shapes, db, row.integer(0), "calibration_identified").identified.emplace();
        id.parameter = row.text(1);
        id.measure = row.text(2);
        id.target = row.real(3);
        id.value = row.real(4);
        id.contact_value = row.real(5);
        id.achieved = read_summary(row, 6, false);
        id.consistent = {row.real(11), row.real(12)};
    }
    sql::Statement point(db.handle(), db.path(),
                         "SELECT shape, parameter_value, refinement, contact_value, count, mean, "
                         "sd, p5, p50, p95, mean_lower, mean_upper FROM calibration_curve "
                         "ORDER BY shape, parameter_value");
    while (point.step()) {
        CalibrationShape& shape = shape_of(shapes, db, point.integer(0), "calibration_curve");
        if (!shape.identified) {
            damaged(db.path(), "calibration_curve has points of shape " +
                                   std::to_string(point.integer(0)) +
                                   ", which has no row in calibration_identified");
        }
        shape.identified->curve.push_back(
            {point.real(1), point.real(3), point.integer(2) != 0, read_summary(point, 4, true)});
    }
}

void read_drops(const ResultsDb& db, std::vector<CalibrationShape>& shapes) {
    sql::Statement row(db.handle(), db.path(),
                       "SELECT shape, drop_index, seed, rebounded, mass_kg, drop_height_m, "
                       "rebound_height_m, approach_speed_m_s, rebound_speed_m_s, "
                       "normal_impulse_N_s, first_impulse_N_s, compression_impulse_N_s, "
                       "restitution_impulse_N_s, energy_before_J, energy_after_J, cor_height, "
                       "cor_speed, cor_kinetic, cor_energy FROM drop_tests "
                       "ORDER BY shape, drop_index");
    while (row.step()) {
        risk::DropMeasurement& m =
            shape_of(shapes, db, row.integer(0), "drop_tests").drops.emplace_back();
        m.index = row.integer(1);
        m.seed = static_cast<std::uint64_t>(row.integer(2));
        m.rebounded = row.integer(3) != 0;
        double* fields[] = {&m.mass,           &m.drop_height,         &m.rebound_height,
                            &m.approach_speed, &m.rebound_speed,       &m.normal_impulse,
                            &m.first_impulse,  &m.compression_impulse, &m.restitution_impulse,
                            &m.energy_before,  &m.energy_after,        &m.cor_height,
                            &m.cor_speed,      &m.cor_kinetic,         &m.cor_energy};
        int column = 4;
        for (double* field : fields) *field = row.real(column++);
    }
}

engine::HeapStatus heap_status(const ResultsDb& db, const std::string& name) {
    for (const engine::HeapStatus status : heap_statuses) {
        if (name == engine::to_string(status)) return status;
    }
    damaged(db.path(), "heap_tests.status = '" + name + "'");
}

void read_heaps(const ResultsDb& db, std::vector<CalibrationShape>& shapes) {
    sql::Statement row(db.handle(), db.path(),
                       "SELECT shape, rock_friction, heap, seed, status, rocks, rolled_off, "
                       "fill_height_m, fill_time_s, lift_time_s, settle_time_s, heap_height_m, "
                       "foot_radius_m, angle_deg, angle_sd_deg, valid_planes FROM heap_tests "
                       "ORDER BY shape, rock_friction, heap");
    sql::Statement planes(db.handle(), db.path(),
                          "SELECT azimuth_deg, valid, angle_deg, fitted_points, heap_height_m, "
                          "foot_radius_m FROM heap_planes WHERE shape = ? AND rock_friction = ? "
                          "AND heap = ? ORDER BY plane");
    while (row.step()) {
        CalibrationHeap& h =
            shape_of(shapes, db, row.integer(0), "heap_tests").heaps.emplace_back();
        h.rock_friction = row.real(1);
        risk::HeapMeasurement& m = h.heap;
        m.index = row.integer(2);
        m.seed = static_cast<std::uint64_t>(row.integer(3));
        m.status = heap_status(db, row.text(4));
        m.rocks = static_cast<int>(row.integer(5));
        m.rolled_off = static_cast<int>(row.integer(6));
        m.fill_height = row.real(7);
        m.fill_time = row.real(8);
        m.lift_time = row.real(9);
        m.settle_time = row.real(10);
        m.heap_height = row.real(11);
        m.foot_radius = row.real(12);
        m.angle_deg = row.real(13);
        m.angle_sd_deg = row.real(14);
        m.valid_planes = static_cast<int>(row.integer(15));
        planes.reset();
        planes.bind_int(1, row.integer(0));
        planes.bind_real(2, h.rock_friction);
        planes.bind_int(3, m.index);
        while (planes.step()) {
            risk::HeapProfile& p = m.planes.emplace_back();
            p.azimuth_deg = planes.real(0);
            p.valid = planes.integer(1) != 0;
            p.angle_deg = planes.real(2);
            p.fitted_points = static_cast<int>(planes.integer(3));
            p.heap_height = planes.real(4);
            p.foot_radius = planes.real(5);
        }
    }
}

}  // namespace

void write_calibration(const fs::path& path, const CalibrationRecord& record) {
    if (!is_calibration(record.kind)) {
        throw std::invalid_argument("write_calibration: run kind '" +
                                    std::string(to_string(record.kind)) +
                                    "' is not a calibration experiment");
    }
    create_database_file(path, record.run, record.kind, [&](sqlite3* db) {
        for (std::size_t k = 0; k < record.shapes.size(); ++k) {
            const auto index = static_cast<std::int64_t>(k);
            const CalibrationShape& shape = record.shapes[k];
            insert_shape(db, path, index, shape);
            if (shape.identified) insert_identified(db, path, index, *shape.identified);
            insert_drops(db, path, index, shape.drops);
            insert_heaps(db, path, index, shape.heaps);
        }
    });
}

CalibrationRecord read_calibration(const ResultsDb& db) {
    const RunKind kind = db.kind();
    if (!is_calibration(kind)) {
        throw DatabaseError(db.path().string() + " holds " + held_by(kind) +
                                ", not a calibration experiment: give a database written by "
                                "`rockfall calibrate drop --db` or `calibrate heap --db`",
                            Kind::bad_file);
    }
    CalibrationRecord record;
    record.run = db.run();
    record.kind = kind;
    record.shapes = read_shapes(db);
    read_identified(db, record.shapes);
    read_drops(db, record.shapes);
    read_heaps(db, record.shapes);
    return record;
}

}  // namespace rockfall::db
