#include "report/soil_report.hpp"

#include "report/text_format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace rockfall::report {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Units of the extensive quantities: a 2D run is a plane-strain section, so its forces,
// impulses, masses and energies are per metre of width.
struct Units {
    const char* force;
    const char* impulse;
    const char* mass;
    bool per_metre;
    // A key or column with a unit suffix: "wall_force_N", or "wall_force_N_per_m" in 2D.
    std::string key(const char* base) const {
        return per_metre ? base + std::string("_per_m") : base;
    }
};

Units units_of(const db::SoilRunRecord& r) {
    if (r.dimension == 2) return {"N/m", "N s/m", "kg/m", true};
    return {"N", "N s", "kg", false};
}

bool has_wall(const db::SoilRunRecord& r) { return !std::isnan(r.wall_distance_from_toe); }

// The highest bin of the deposit's height profile, if any soil rests on the slope.
std::optional<std::size_t> highest_bin(const db::SoilRunRecord& r) {
    if (r.deposit.empty()) return std::nullopt;
    const auto top = std::max_element(r.deposit.begin(), r.deposit.end(),
                                      [](const db::SoilDepositBin& a, const db::SoilDepositBin& b) {
                                          return a.height < b.height;
                                      });
    return static_cast<std::size_t>(top - r.deposit.begin());
}

}  // namespace

risk::LoadHistory sampled_load(const db::SoilRunRecord& record, bool filtered) {
    risk::LoadHistory h;
    h.source = "simulated";
    h.per_metre = record.dimension == 2;
    for (const db::SoilLoadSample& s : record.load) {
        h.time.push_back(s.time);
        h.load.push_back(filtered ? s.force_filtered[0] : s.force[0]);
    }
    return h;
}

std::string filter_text(const db::SoilRunRecord& record) {
    return record.filter_window > 0.0 ? "filtered by a centred moving average over " +
                                            fmt("%g", record.filter_window) + " s"
                                      : "unfiltered";
}

Plot soil_load_figure(const db::SoilRunRecord& record, const std::string& name,
                      const risk::LoadHistory* measured) {
    return load_history_plot(
        "Wall load history: " + name, sampled_load(record, false),
        "simulated, per " + fmt("%g", record.sample_interval) + " s", sampled_load(record, true),
        record.filter_window > 0.0
            ? "simulated, " + fmt("%g", record.filter_window) + " s moving average"
            : "simulated, unfiltered",
        measured);
}

void print_soil_summary(std::ostream& out, const db::SoilRunRecord& r, const std::string& origin) {
    const Units u = units_of(r);
    out << "soil scenario " << r.run.scenario_name << " (" << origin << ")\n";
    out << "  "
        << (u.per_metre ? "2D plane strain: forces, impulses and masses per metre of width" : "3D")
        << ", cell " << fmt("%.3f m", r.cell_size) << ", " << r.particles
        << " particles, soil mass " << fmt("%.1f ", r.mass) << u.mass << '\n';
    out << "status: " << r.outcome;
    if (!r.message.empty()) out << " (" << r.message << ")";
    out << '\n';
    out << "simulated " << fmt("%.3f s", r.simulated_time) << " in " << r.steps
        << " steps; runtime " << fmt("%.2f s", r.runtime) << '\n';
    if (has_wall(r)) {
        out << "wall load (normal to the wall, " << fmt("%.2f m", r.wall_distance_from_toe)
            << " past the toe), " << u.force << ":\n";
        out << "  peak " << fmt("%.1f ", r.peak_force) << u.force << " at "
            << fmt("%.3f s", r.peak_time) << " (largest mean over any "
            << fmt("%g s", r.sample_interval) << " window)\n";
        out << "  peak filtered " << fmt("%.1f ", r.peak_force_filtered) << u.force
            << (r.filter_window > 0.0
                    ? " (largest mean over any " + fmt("%g s", r.filter_window) + " window)\n"
                    : " (no filter: the peak)\n");
        out << "  peak raw " << fmt("%.1f ", r.peak_force_step) << u.force << " (single step)\n";
        out << "  total impulse " << fmt("%.1f ", r.impulse) << u.impulse << '\n';
    } else {
        out << "wall: none in this scenario\n";
    }
    out << "deposit:\n";
    if (std::isfinite(r.runout_x)) {
        out << "  runout " << fmt("%.2f m", r.runout_past_toe) << " past the toe (x "
            << fmt("%.2f m", r.runout_x) << ")\n";
    } else {
        out << "  runout: none (the run ended " << r.outcome << ", before the soil came to rest)\n";
    }
    if (!r.motion.empty()) {
        const db::SoilMotionSample& last = r.motion.back();
        out << "  final front x " << fmt("%.2f m", last.front_x) << ", centre of mass x "
            << fmt("%.2f m", last.centre_of_mass[0]) << ", z "
            << fmt("%.2f m", last.centre_of_mass[2]) << '\n';
    }
    if (const auto top = highest_bin(r)) {
        out << "  max height " << fmt("%.2f m", r.deposit[*top].height) << " above the slope at x "
            << fmt("%.2f m", r.deposit[*top].x) << " (profile of " << r.deposit.size()
            << " bins from x " << fmt("%.2f m", r.deposit.front().x) << " to "
            << fmt("%.2f m", r.deposit.back().x) << ")\n";
    }
}

nlohmann::json soil_json(const db::SoilRunRecord& r) {
    const Units u = units_of(r);
    nlohmann::json profile = nlohmann::json::array();
    for (const db::SoilDepositBin& bin : r.deposit) profile.push_back({bin.x, bin.height});
    nlohmann::json deposit = {
        {"runout_x_m", r.runout_x},
        {"runout_past_toe_m", r.runout_past_toe},
        {"height_profile", {{"columns", {"x_m", "height_m"}}, {"rows", std::move(profile)}}}};
    if (const auto top = highest_bin(r)) {
        deposit["max_height_m"] = r.deposit[*top].height;
        deposit["max_height_x_m"] = r.deposit[*top].x;
    }
    const Table history = soil_history(r);
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : history.rows) {
        nlohmann::json values = nlohmann::json::array();
        for (const Cell& cell : row)
            values.push_back(nlohmann::json(json_number(std::get<double>(cell))));
        rows.push_back(std::move(values));
    }
    nlohmann::json result = {
        {"scenario", r.run.scenario_name},
        {"dimension", r.dimension},
        {"per_metre_of_width", u.per_metre},
        {"status", r.outcome},
        {"message", r.message},
        {"particles", r.particles},
        {u.key("mass_kg"), r.mass},
        {"steps", r.steps},
        {"simulated_time_s", r.simulated_time},
        {"runtime_s", r.runtime},
        {"wall_enabled", has_wall(r)},
        {"wall_distance_from_toe_m", json_number(r.wall_distance_from_toe)},
        {"sample_interval_s", r.sample_interval},
        {"filter_window_s", r.filter_window},
        {u.key("peak_wall_force_N"), r.peak_force},
        {"peak_wall_force_time_s", r.peak_time},
        {u.key("peak_wall_force_filtered_N"), r.peak_force_filtered},
        {u.key("peak_wall_force_step_N"), r.peak_force_step},
        {u.key("wall_impulse_N_s"), r.impulse},
        {"deposit", std::move(deposit)},
        {"history", {{"columns", history.columns}, {"rows", std::move(rows)}}}};
    if (!r.motion.empty()) {
        const db::SoilMotionSample& last = r.motion.back();
        result["final_front_x_m"] = last.front_x;
        result["final_centre_of_mass_m"] = {json_number(last.centre_of_mass[0]),
                                            json_number(last.centre_of_mass[1]),
                                            json_number(last.centre_of_mass[2])};
    }
    return result;
}

Table soil_summary_items(const db::SoilRunRecord& r) {
    const Units u = units_of(r);
    Table table{{"item", "value"}, {}};
    const auto add = [&table](const std::string& name, Cell value) {
        table.rows.push_back({name, std::move(value)});
    };
    add("scenario_name", r.run.scenario_name);
    add("scenario_hash", r.run.scenario_hash);
    add("dimension", static_cast<std::int64_t>(r.dimension));
    add("status", r.outcome);
    add("particles", r.particles);
    add(u.key("mass_kg"), r.mass);
    add("steps", r.steps);
    add("simulated_time_s", r.simulated_time);
    add("runtime_s", r.runtime);
    add("wall_distance_from_toe_m", r.wall_distance_from_toe);
    add(u.key("peak_wall_force_N"), r.peak_force);
    add("peak_wall_force_time_s", r.peak_time);
    add(u.key("peak_wall_force_filtered_N"), r.peak_force_filtered);
    add(u.key("peak_wall_force_step_N"), r.peak_force_step);
    add(u.key("wall_impulse_N_s"), r.impulse);
    add("runout_x_m", r.runout_x);
    add("runout_past_toe_m", r.runout_past_toe);
    if (const auto top = highest_bin(r)) {
        add("max_height_m", r.deposit[*top].height);
        add("max_height_x_m", r.deposit[*top].x);
    }
    add("started_at", r.run.started_at);
    add("finished_at", r.run.finished_at);
    add("tool_version", r.run.tool_version);
    return table;
}

Table soil_history(const db::SoilRunRecord& r) {
    const Units u = units_of(r);
    Table table{
        {"time_s", u.key("wall_force_N"), u.key("wall_force_filtered_N"), "centre_of_mass_x_m",
         "centre_of_mass_z_m", "front_x_m", u.key("kinetic_energy_J")},
        {}};
    const std::size_t rows = std::min(r.load.size(), r.motion.size());
    for (std::size_t k = 0; k < rows; ++k) {
        const db::SoilMotionSample& m = r.motion[k];
        table.rows.push_back({r.load[k].time, r.load[k].force[0], r.load[k].force_filtered[0],
                              m.centre_of_mass[0], m.centre_of_mass[2], m.front_x,
                              m.kinetic_energy});
    }
    return table;
}

void write_soil_summary(std::ostream& out, QueryFormat format, const std::string& database,
                        const db::SoilRunRecord& record) {
    switch (format) {
        case QueryFormat::text:
            print_soil_summary(out, record, "stored in " + database);
            out << "run: started " << record.run.started_at << ", finished "
                << record.run.finished_at << ", rockfall " << record.run.tool_version << " ("
                << record.run.build << "); scenario hash " << record.run.scenario_hash << '\n';
            return;
        case QueryFormat::json: {
            nlohmann::json document = soil_json(record);
            document["database"] = database;
            document["query"] = "summary";
            out << document.dump(2) << '\n';
            return;
        }
        case QueryFormat::csv:
            print_csv(out, soil_summary_items(record));
            return;
    }
}

void write_soil_history(std::ostream& out, QueryFormat format, const std::string& database,
                        const db::SoilRunRecord& record) {
    const Table table = soil_history(record);
    switch (format) {
        case QueryFormat::text:
            out << "database: " << database << " (soil flow " << record.run.scenario_name << ")\n";
            print_text(out, table);
            return;
        case QueryFormat::json:
            out << nlohmann::ordered_json{{"database", database},
                                          {"query", "history"},
                                          {"rows", rows_json(table)}}
                       .dump(2)
                << '\n';
            return;
        case QueryFormat::csv:
            print_csv(out, table);
            return;
    }
}

void print_measured_comparison(std::ostream& out, const risk::HistoryComparison& c,
                               const risk::LoadHistory& measured, const db::SoilRunRecord& record) {
    const char* unit = measured.per_metre ? " kN/m" : " kN";
    const char* impulse_unit = measured.per_metre ? " kN s/m" : " kN s";
    auto kn = [](double newtons) { return fmt("%.2f", newtons / 1e3); };
    out << "compared with the measured wall load in " << measured.source << " (" << c.points
        << " points in t = " << fmt("%g", c.from) << " to " << fmt("%g", c.to)
        << " s; simulated: the sampled load, " << filter_text(record)
        << ", both linear between their points):\n"
        << "  peak: simulated " << kn(c.simulated_peak) << unit << " at "
        << fmt("%.2f", c.simulated_peak_time) << " s, measured " << kn(c.measured_peak) << unit
        << " at " << fmt("%.2f", c.measured_peak_time) << " s; simulated / measured "
        << fmt("%.3f", c.peak_ratio) << '\n'
        << "  impulse: simulated " << kn(c.simulated_impulse) << impulse_unit << ", measured "
        << kn(c.measured_impulse) << impulse_unit << "; simulated / measured "
        << fmt("%.3f", c.impulse_ratio) << '\n'
        << "  mean load up to the measured peak: simulated / measured "
        << fmt("%.3f", c.loading_ratio) << '\n'
        << "  mean load after the measured peak: simulated / measured "
        << fmt("%.3f", c.after_peak_ratio) << '\n'
        << "  RMS difference " << kn(c.rms_difference) << unit << " ("
        << fmt("%.1f", 100.0 * c.rms_difference / c.measured_peak) << " % of the measured peak)\n";
}

nlohmann::json measured_comparison_json(const risk::HistoryComparison& c,
                                        const risk::LoadHistory& measured) {
    const std::string u = measured.per_metre ? "_per_m" : "";
    return {{"measured_file", measured.source},
            {"points", c.points},
            {"from_s", c.from},
            {"to_s", c.to},
            {"simulated_peak_N" + u, c.simulated_peak},
            {"simulated_peak_time_s", c.simulated_peak_time},
            {"measured_peak_N" + u, c.measured_peak},
            {"measured_peak_time_s", c.measured_peak_time},
            {"peak_ratio", json_number(c.peak_ratio)},
            {"simulated_impulse_N_s" + u, c.simulated_impulse},
            {"measured_impulse_N_s" + u, c.measured_impulse},
            {"impulse_ratio", json_number(c.impulse_ratio)},
            {"loading_ratio", json_number(c.loading_ratio)},
            {"after_peak_ratio", json_number(c.after_peak_ratio)},
            {"rms_difference_N" + u, c.rms_difference}};
}

}  // namespace rockfall::report
